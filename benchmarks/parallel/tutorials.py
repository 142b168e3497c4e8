#!/usr/bin/python3
"""Every tutorial, a few steps serially and on 2 processes, the OpenFOAM
way; the table goes to tutorials.md beside this script.

Usage:
    benchmarks/parallel/tutorials.py [-steps N] [-np P] [tutorial ...]

Each tutorial is prepared by its own Allrun at its default resolution:
the solver the Allrun calls is a stand-in that only succeeds, so the
Allrun does its mesh, seeding and generated files (motion tables) and
stops at its validation. Then, from the seeded time:
- the solver runs N steps (default 20: stopAt nextWrite, written every
  N steps) serially; a projection fluid's pressureSolver is set to
  BoomerAMG (in both runs), the one that solves over the processors,
  with tolerance PRESSURE_TOL, and coupling iterations get tolerance
  COUPLING_TOL: iterations stopped at the tutorials' own tolerances
  give iterates that differ at those tolerances (the ISPH elastic gate
  at 1e-4: U differs by 8e-3 after 10 steps; at these, by 3e-11);
- decomposePar (scotch, P subdomains; default 2), mpirun -np P
  <solver> -parallel (one thread each), reconstructPar;
- every body's particles at the end, matched by id, are compared: the
  count, every value finite, and the largest difference of the positions
  relative to their largest magnitude and of the velocities relative to
  their scale, the largest of their magnitudes and of g t (a fluid at
  rest has velocities of round-off size, the balance of its pressure
  and its weight). What differs is the order of the sums over
  neighbours, and where iterations stop at a tolerance (ISPH's
  multigrid, whose coarsening follows the partition; coupling
  iterations; an implicit solid's Newton iterations) the iterates.
A tutorial passes when both runs succeed, the particles are the same,
every value is finite and both differences are within TOL (TOL_ITERATED
where iterations stop at a tolerance). The wall times are reported
beside (2 cores: the serial run on one thread).
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

here = os.path.dirname(os.path.abspath(__file__))
project = os.path.dirname(os.path.dirname(here))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from foamCloud import read_cloud  # noqa: E402

SOLVERS = ("riemannSphFoam", "ulphPdFoam", "isphTlsphFoam", "particleFoam")
TOL = 1e-9
TOL_ITERATED = 1e-7
PRESSURE_TOL = 1e-12
COUPLING_TOL = 1e-10
G = 9.81
ENV = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
           OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_mpi_yield_when_idle="1", MESHLESS_PROJECT=project)
ENV.pop("PWD", None)
HEADER = "FoamFile { version 2.0; format ascii; class dictionary;" \
    " object %s; }\n"


def sh(cmd, cwd, env=ENV):
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True,
                       env=env)
    return p.returncode, p.stdout + p.stderr


def foam_set(case, key, value, file="system/controlDict"):
    return sh(["foamDictionary", file, "-entry", key, "-set", str(value)],
              case)


def foam_get(case, key, file="system/controlDict"):
    code, out = sh(["foamDictionary", file, "-entry", key, "-value"], case)
    return out.strip().splitlines()[-1] if code == 0 and out.strip() \
        else None


def solver_of(tutorial):
    with open(os.path.join(tutorial, "Allrun")) as f:
        text = f.read()
    for s in SOLVERS:
        if re.search(r"\b%s\b" % s, text):
            return s
    return None


def prepared(tutorial, case):
    """The tutorial's Allrun with the solvers stood in for: mesh, seeding
    and the files it generates"""
    shutil.copytree(tutorial, case, ignore=shutil.ignore_patterns(
        "[0-9]*", "log.*", "processor*", "postProcessing", "VTK"))
    # Exported shell functions of the solvers' names: they come before
    # any program of that name (a stand-in program first on the PATH does
    # not stay there: the Allrun's etc/bashrc puts the project's first)
    env = dict(ENV)
    for s in SOLVERS:
        env["BASH_FUNC_%s%%%%" % s] = "() {  return 0\n}"
    sh(["./Allrun"], case, env)
    return os.path.isdir(os.path.join(case, "0", "lagrangian"))


def clouds(case, t):
    d = os.path.join(case, t, "lagrangian")
    return sorted(os.listdir(d)) if os.path.isdir(d) else []


def compare(serial, parallel, t):
    """(same particles, all finite, {field: (largest difference, largest
    magnitude)} of the positions and velocities over the bodies)"""
    same, finite = True, True
    worst = {"positions": (0.0, 0.0), "U": (0.0, 0.0)}
    for body in clouds(serial, t):
        a = read_cloud(serial, t, body)
        b = read_cloud(parallel, t, body)
        ia = {i: k for k, i in enumerate(a["id"])}
        ib = {i: k for k, i in enumerate(b.get("id", []))}
        if set(ia) != set(ib):
            same = False
            continue
        for f in worst:
            if f not in a or f not in b:
                continue
            diff, scale = worst[f]
            for i, ka in ia.items():
                for x, y in zip(a[f][ka], b[f][ib[i]]):
                    finite = finite and abs(x) < 1e300 and abs(y) < 1e300 \
                        and x == x and y == y
                    diff = max(diff, abs(x - y))
                    scale = max(scale, abs(x))
            worst[f] = (diff, scale)
    return same, finite, worst


def run_one(tutorial, work, steps, np_):
    name = os.path.relpath(tutorial, os.path.join(project, "tutorials"))
    solver = solver_of(tutorial)
    row = {"tutorial": name, "solver": solver or "-"}
    if solver is None:
        row["result"] = "no solver (not a solver tutorial)"
        return row
    case = os.path.join(work, name.replace("/", "_"))
    if not prepared(tutorial, case):
        row["result"] = "FAILED: its Allrun did not seed the case"
        return row
    # N first steps, written at the end; the seeded time only
    for d in os.listdir(case):
        if re.match(r"^[0-9.e+-]+$", d) and d != "0":
            shutil.rmtree(os.path.join(case, d))
    for d in ("postProcessing", "runTime"):
        p = os.path.join(case, "system", d) if d == "runTime" \
            else os.path.join(case, d)
        if os.path.isdir(p):
            shutil.rmtree(p)
        elif os.path.isfile(p):
            os.remove(p)
    # N steps exactly: the first write after N steps stops the run
    foam_set(case, "stopAt", "nextWrite")
    foam_set(case, "writeControl", "timeStep")
    foam_set(case, "writeInterval", steps)
    foam_set(case, "startFrom", "startTime")
    foam_set(case, "startTime", 0)
    foam_set(case, "writeFormat", "binary")
    # A projection fluid's pressure system spans the processors: hypre's
    # BoomerAMG (the other solvers solve on one processor and are refused
    # in parallel), serially too for the same iterates
    props = "constant/particleProperties"
    code, out = sh(["foamDictionary", props, "-entry", "bodies", "-keywords"],
                   case)
    notes = []
    for body in out.split() if code == 0 else []:
        if foam_get(case, "bodies/%s/model" % body, props) == "isph":
            key = "bodies/%s/pressureSolver/solver" % body
            if foam_get(case, key, props) != "BoomerAMG":
                foam_set(case, key, "BoomerAMG", props)
                notes.append("%s: BoomerAMG" % body)
            # Iterates that differ at the tolerance are not the point
            foam_set(case, "bodies/%s/pressureSolver/tolerance" % body,
                     PRESSURE_TOL, props)
            foam_set(case, "bodies/%s/pressureSolver/maxIter" % body,
                     2000, props)
            notes.append("%s: pressure tolerance %g" % (body, PRESSURE_TOL))
    if foam_get(case, "coupling/iterations/tolerance", props) is not None:
        foam_set(case, "coupling/iterations/tolerance", COUPLING_TOL, props)
        foam_set(case, "coupling/iterations/maxIterations", 100, props)
        notes.append("coupling iterations tolerance %g" % COUPLING_TOL)
    row["changed"] = ", ".join(notes)
    parallel = case + ".parallel"
    shutil.copytree(case, parallel)

    start = time.time()
    code, out = sh([solver], case)
    row["serial s"] = "%.1f" % (time.time() - start)
    if code != 0:
        row["result"] = "FAILED serially: " + out.strip()[-200:]
        return row
    last = sorted((d for d in os.listdir(case)
                   if re.match(r"^[0-9.e+-]+$", d) and d != "0"),
                  key=float)
    if not last:
        row["result"] = "FAILED: the serial run wrote nothing"
        return row
    t = last[-1]

    with open(os.path.join(parallel, "system", "decomposeParDict"),
              "w") as f:
        f.write(HEADER % "decomposeParDict"
                + "numberOfSubdomains %d;\nmethod scotch;\n" % np_)
    code, out = sh(["decomposePar", "-force"], parallel)
    if code != 0:
        row["result"] = "FAILED: decomposePar: " + out.strip()[-200:]
        return row
    start = time.time()
    code, out = sh(["mpirun", "--oversubscribe", "-np", str(np_), solver,
                    "-parallel"], parallel)
    row["parallel s"] = "%.1f" % (time.time() - start)
    with open(os.path.join(parallel, "log." + solver), "w") as f:
        f.write(out)
    if code != 0:
        row["result"] = "FAILED in parallel: " + out.strip()[-300:]
        return row
    code, out = sh(["reconstructPar", "-time", t], parallel)
    if code != 0:
        row["result"] = "FAILED: reconstructPar: " + out.strip()[-200:]
        return row
    same, finite, worst = compare(case, parallel, t)
    row["time"] = t
    d, x = worst["positions"]
    dx = d/x if x > 0 else d
    d, u = worst["U"]
    du = d/max(u, G*float(t))
    row["positions"] = "%.1e" % dx
    row["U"] = "%.1e" % du
    row["largest U"] = "%.2g" % u
    with open(os.path.join(case, props)) as f:
        iterated = solver == "isphTlsphFoam" or re.search(
            r"\b(iterations|implicit)\b", f.read()) is not None
    tol = TOL_ITERATED if iterated else TOL
    row["tolerance"] = "%g" % tol
    ok = same and finite and max(dx, du) <= tol
    row["result"] = "pass" if ok else "FAILED: " + (
        "other particles" if not same else "non-finite" if not finite
        else "differences above the tolerance")
    return row


def main(argv):
    steps, np_, names = 20, 2, []
    i = 0
    while i < len(argv):
        if argv[i] == "-steps":
            steps = int(argv[i + 1])
            i += 2
        elif argv[i] == "-np":
            np_ = int(argv[i + 1])
            i += 2
        else:
            names.append(argv[i])
            i += 1
    root = os.path.join(project, "tutorials")
    tutorials = [os.path.join(root, n) for n in names] if names else sorted(
        os.path.join(root, s, t) for s in os.listdir(root)
        for t in os.listdir(os.path.join(root, s))
        if os.path.isfile(os.path.join(root, s, t, "Allrun")))
    work = tempfile.mkdtemp(prefix="parallelTutorials.")
    rows = []
    try:
        for tut in tutorials:
            row = run_one(tut, work, steps, np_)
            rows.append(row)
            print("%-36s %s" % (row["tutorial"], row["result"]), flush=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)

    cols = ("tutorial", "solver", "changed", "time", "serial s",
            "parallel s", "positions", "U", "largest U", "tolerance",
            "result")
    lines = [
        "# Every tutorial in parallel",
        "",
        "`benchmarks/parallel/tutorials.py -steps %d -np %d`: each tutorial"
        " at its default resolution, %d steps serially (one thread) and on"
        " %d processes (scotch), the particles at the end compared by id"
        " (positions: the largest difference over the particles,"
        " relative to the largest magnitude; U: relative to the largest"
        " of the largest |U| (m/s) and g t, since a fluid at rest has"
        " velocities of round-off size). A tutorial passes within"
        " %g, or %g where iterations stop at a tolerance (ISPH's"
        " multigrid, coupling iterations, an implicit solid)."
        % (steps, np_, steps, np_, TOL, TOL_ITERATED),
        "",
        "| " + " | ".join(cols) + " |",
        "|" + "---|" * len(cols),
    ]
    for r in rows:
        lines.append("| " + " | ".join(
            " ".join(str(r.get(c, "")).split()).replace("|", "/")
            for c in cols) + " |")
    passed = sum(1 for r in rows if r["result"] == "pass")
    skipped = sum(1 for r in rows if r["result"].startswith("no solver"))
    lines += ["", "%d of %d solver tutorials pass." % (passed,
                                                    len(rows) - skipped)]
    if not names:
        with open(os.path.join(here, "tutorials.md"), "w") as f:
            f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0 if passed == len(rows) - skipped else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
