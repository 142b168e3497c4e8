"""Small harness for the case tests: named checks, a summary line per test
('N passed, N failed'), exit code 1 on any failure."""
import hashlib
import os
import shutil
import subprocess
import sys
import tempfile

project_dir = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))


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
        "resolution", "runParameters"))
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


def set_entry(case, dict_file, entry, value):
    """foamDictionary -entry <entry> -set <value> on a case dictionary."""
    code, out = run(["foamDictionary", dict_file, "-entry", entry, "-set",
                     str(value)], case)
    if code != 0:
        raise RuntimeError(out)


def snapshot(case):
    """Every file below a case with a hash of its content."""
    out = {}
    for root, _, files in os.walk(case):
        for f in files:
            p = os.path.join(root, f)
            out[os.path.relpath(p, case)] = hashlib.sha1(
                open(p, "rb").read()).hexdigest()
    return out


def table(path):
    """Rows of numbers of a whitespace-separated file, '#' lines skipped
    (a monitor's or the coupling's .dat)"""
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append([float(v) for v in line.split()])
    return rows


def scratch(prefix):
    return tempfile.mkdtemp(prefix=prefix + ".")
