"""Small harness for the case tests: named checks, a summary line per test
('N passed, N failed'), exit code 1 on any failure; running a test's parts
in a scratch folder, tutorials and solvers in it. Importing it puts the
project's Python library (etc/python: clouds, monitors, run cost,
dictionaries, stability checks) on the path."""
import hashlib
import os
import shutil
import subprocess
import sys
import tempfile
import traceback

project_dir = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(project_dir, "etc", "python"))

# Add or set a case dictionary's entry (the project's dictionary library)
from foamDict import put_entry  # noqa: E402,F401


class CaseTest:
    def __init__(self, name):
        self.name = name
        self.passed = 0
        self.failed = 0

    def check(self, what, ok, detail=""):
        if ok:
            self.passed += 1
            print("[  PASS  ] %s: %s" % (self.name, what))
        else:
            self.failed += 1
            print("[  FAIL  ] %s: %s" % (self.name, what))
            if detail:
                print("           " + detail.replace("\n", "\n           "))
        sys.stdout.flush()

    def check_equal(self, what, value, expected):
        self.check(what, value == expected,
                   "got %r, expected %r" % (value, expected))

    def check_close(self, what, value, expected, rtol):
        ok = abs(value - expected) <= rtol * abs(expected)
        self.check(what + " (rtol %g)" % rtol, ok,
                   "got %.10g, expected %.10g" % (value, expected))

    def finish(self):
        print("%s: %d passed, %d failed" % (self.name, self.passed, self.failed))
        return 0 if self.failed == 0 else 1


def copy_case(src, dst, stored_results=True):
    """A clean copy of a tutorial: no mesh, no results, no logs, none of
    the files an Allrun writes into system/ for its options. Without
    stored_results, validation/ is copied without the tutorial's stored
    results (tables, plots, runs/), so that what the test's run writes
    there is all there is."""
    shutil.copytree(src, dst, ignore=shutil.ignore_patterns(
        "[0-9]*", "log.*", "*.foam", "polyMesh", "VTK", "postProcessing",
        "processor*", "resolution", "runParameters", "runTime",
        "integrator"))
    if not stored_results and os.path.isdir(os.path.join(src, "validation")):
        shutil.rmtree(os.path.join(dst, "validation"))
        shutil.copytree(os.path.join(src, "validation"),
                        os.path.join(dst, "validation"),
                        ignore=shutil.ignore_patterns("*.md", "*.png",
                                                      "runs"))
    return dst


def run(cmd, cwd):
    """Run a command in a case; returns (exit code, stdout + stderr)."""
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    return p.returncode, p.stdout + p.stderr


def run_steps(t, case, commands=("blockMesh", "seedParticles", "ulphPdFoam"),
              label=""):
    """Run each command in the case, each checked to succeed, up to the
    first that fails; returns (all succeeded, output of the last run)"""
    out = ""
    for cmd in commands:
        code, out = run([cmd], case)
        t.check(label + cmd + " succeeds", code == 0, out[-1500:])
        if code != 0:
            return False, out
    return True, out


def run_tutorial(t, tutorial, work, name, args=(), end=None, entries=(),
                 check=True):
    """A clean copy of the tutorial (project-relative path) without its
    stored results as <work>/<name>, to endTime end when given, with the
    entries [(dictionary, key, value)] set, run by its Allrun with args
    (checked to succeed unless check is False); returns (case, exit code,
    output)"""
    case = copy_case(os.path.join(project_dir, tutorial),
                     os.path.join(work, name), stored_results=False)
    if end is not None:
        set_entry(case, "system/controlDict", "endTime", end)
    for dictionary, key, value in entries:
        set_entry(case, dictionary, key, value)
    code, out = run(["./Allrun"] + list(args), case)
    if check:
        t.check("%s: Allrun %s%s succeeds"
                % (name, " ".join(args), "" if end is None else
                   " to %g s" % end), code == 0, out[-2000:])
    return case, code, out


def run_validated(t, tutorial, work, name, args=(), what="stable"):
    """run_tutorial, then its validation/validate.py --check (checked to
    succeed, 'what' naming what it checks), its lines printed; returns the
    case, or None when the run failed"""
    case, code, out = run_tutorial(t, tutorial, work, name, args)
    if code != 0:
        return None
    code, out = run(["/usr/bin/python3", "validation/validate.py", ".",
                     "--check"], case)
    t.check("validate.py --check: %s" % what, code == 0, out[-2000:])
    for line in out.splitlines():
        print("    " + line)
    return case


def set_entry(case, dict_file, entry, value):
    """foamDictionary -entry <entry> -set <value> on a case dictionary."""
    code, out = run(["foamDictionary", dict_file, "-entry", entry, "-set",
                     str(value)], case)
    if code != 0:
        raise RuntimeError(out)


def refused_entries(t, source, work, solver, cases,
                    dict_file="constant/particleProperties"):
    """Bad input: for each (name, entry, value, words) of cases, a copy of
    the case folder source as <work>/<name> with the entry put into
    dict_file (put_entry), meshed and seeded, then the solver: the run must
    stop and its output name every word."""
    for name, entry, value, words in cases:
        case = copy_case(source, os.path.join(work, name))
        put_entry(case, dict_file, entry, value)
        ok, _ = run_steps(t, case, ("blockMesh", "seedParticles"),
                          name + ": ")
        if not ok:
            continue
        code, out = run([solver], case)
        t.check(name + ": the run stops", code != 0, out[-400:])
        for w in words:
            t.check("%s: the error names '%s'" % (name, w), w in out,
                    out[-800:])


def snapshot(case):
    """Every file below a case with a hash of its content."""
    out = {}
    for root, _, files in os.walk(case):
        for f in files:
            p = os.path.join(root, f)
            out[os.path.relpath(p, case)] = hashlib.sha1(
                open(p, "rb").read()).hexdigest()
    return out


def scratch(prefix):
    return tempfile.mkdtemp(prefix=prefix + ".")


def run_parts(name, *parts):
    """A test of parts: each called as part(t, work) with the test's
    CaseTest and a scratch folder (removed at the end); a part that raises
    counts as a failure and the next part runs. Returns the exit code."""
    t = CaseTest(name)
    work = scratch(name)
    try:
        for part in parts:
            try:
                part(t, work)
            except Exception:
                t.check(part.__name__ + " ran", False,
                        traceback.format_exc()[-1500:])
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return t.finish()
