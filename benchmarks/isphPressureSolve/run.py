#!/usr/bin/python3
"""Driver of benchmarks/isphPressureSolve/Allrun (see its header)."""
import os
import re
import shutil
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "etc", "python"))
from foamMonitor import run_cost  # noqa: E402

SOLVERS = ["CG", "BiCGStab", "BoomerAMG"]
SIZES = [("1e4", 0.0014142), ("1e5", 0.00044721), ("4e5", 0.00022361)]


def sh(cmd, cwd, env=None):
    r = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, universal_newlines=True)
    if r.returncode != 0:
        sys.exit("%s failed in %s:\n%s" % (" ".join(cmd), cwd, r.stdout[-2000:]))
    return r.stdout


def seeded(work, dx):
    case = os.path.join(work, "seed-%g" % dx)
    shutil.copytree(os.path.join(here, "case"), case)
    with open(os.path.join(case, "system", "resolution"), "w") as f:
        f.write("dx %.8g;\n" % dx)
    sh(["blockMesh"], case)
    sh(["seedParticles"], case)
    return case


def measure(seed, work, solver, threads, repeat):
    best = None
    for k in range(repeat):
        case = os.path.join(work, "%s-%d-%d" % (solver, threads, k))
        shutil.copytree(seed, case)
        sh(["foamDictionary", "constant/particleProperties", "-entry",
            "bodies/water/pressureSolver/solver", "-set", solver], case)
        env = dict(os.environ, OMP_NUM_THREADS=str(threads))
        log = sh(["isphTlsphFoam"], case, env)
        m = re.search(r"water: pressure \S+, (\d+) iterations, residual "
                      r"(\S+) -> (\S+)", log)
        cost = run_cost(case)
        parts = cost["parts"]
        run = {"solve": parts["water.pressureSolve"]["seconds"],
               "assembly": parts["water.poissonAssembly"]["seconds"],
               "iterations": int(m.group(1)), "residual": float(m.group(3)),
               "particles": cost["bodies"]["water"]["particles"]}
        shutil.rmtree(case)
        if best is None or run["solve"] < best["solve"]:
            best = run
    return best


def main():
    quick = "-quick" in sys.argv
    repeat = 2
    if "-repeat" in sys.argv:
        repeat = int(sys.argv[sys.argv.index("-repeat") + 1])
    if quick:
        repeat = 1
    sizes = SIZES[:1] if quick else SIZES
    work = tempfile.mkdtemp(prefix="isphPressureSolve.")
    rows = []
    try:
        for name, dx in sizes:
            seed = seeded(work, dx)
            for solver in SOLVERS:
                for threads in (1, 2):
                    r = measure(seed, work, solver, threads, repeat)
                    r.update(size=name, solver=solver, threads=threads)
                    rows.append(r)
                    print("%s %-9s %d thread(s): %d particles, solve %.4f s,"
                          " %d iterations, residual %.2e, assembly %.4f s"
                          % (name, solver, threads, r["particles"], r["solve"],
                             r["iterations"], r["residual"], r["assembly"]),
                          flush=True)
            shutil.rmtree(seed)
    finally:
        shutil.rmtree(work, ignore_errors=True)

    lines = ["# ISPH pressure Poisson solve: time per solve per linear solver",
             "", "Command: `benchmarks/isphPressureSolve/Allrun%s`"
             % (" -quick" if quick else ""), "",
             "Still water from rest (p = 0), one solve to the hydrostatic"
             " pressure at relative residual 1e-8; time of the solve with"
             " its set-up (run cost water.pressureSolve), fastest of %d"
             " run(s)." % repeat, "",
             "| particles | solver | threads | solve [s] | us per particle |"
             " iterations | final residual | assembly [s] |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %d | %s | %d | %.4f | %.3f | %d | %.1e | %.4f |"
                     % (r["particles"], r["solver"], r["threads"], r["solve"],
                        1e6 * r["solve"] / r["particles"], r["iterations"],
                        r["residual"], r["assembly"]))
    ok = True
    verdicts = []
    for name, limit in (("1e4", 0.05), ("1e5", 0.3)):
        two = [r for r in rows if r["size"] == name and r["threads"] == 2]
        if not two:
            continue
        best = min(two, key=lambda r: r["solve"])
        good = best["solve"] <= limit
        ok = ok and good
        verdicts.append("- %s particles, 2 threads: best %s %.4f s, target"
                        " <= %g s: %s" % (name, best["solver"], best["solve"],
                                          limit, "met" if good else "MISSED"))
    amg = [r for r in rows if r["solver"] == "BoomerAMG" and r["threads"] == 2]
    if len(amg) == len(SIZES):
        per = [r["solve"] / r["particles"] for r in amg]
        good = max(per) <= 2 * min(per)
        ok = ok and good
        verdicts.append("- BoomerAMG cost per particle, 1e4 to 4e5, 2 threads:"
                        " %s us, largest / smallest %.2f, target <= 2: %s"
                        % (", ".join("%.3f" % (1e6 * p) for p in per),
                           max(per) / min(per), "met" if good else "MISSED"))
    lines += ["", "Targets:", ""] + verdicts
    text = "\n".join(lines) + "\n"
    print(text)
    if not quick:
        with open(os.path.join(here, "result.md"), "w") as f:
            f.write(text)
    sys.exit(0 if ok else 2)


if __name__ == "__main__":
    main()
