#!/usr/bin/python3
"""Case test: still water in a tank with the projection ISPH fluid
(isphTlsphFoam, model isph): the tutorial tutorials/isphTlsphFoam/stillWater, and its
validate.py --check.

Water 0.1 m deep in a 0.2 m wide 2D tank (dx = 5 mm, fixed ghost walls of
4 layers, free slip, cubic spline h = 1.2 dx, hydrostatic start, maxCo
0.1, CG) for 2 s. Checks against hydrostatics (the issue's targets):
- the bottom row's pressure, averaged over the row and the written times
  of 1-2 s, is rho g (y_s - dx/2) within 1 %, y_s the height of the
  surface row (H - dx/2 at the start): the free-surface condition p = 0
  sits on the surface particles (isph.H), half a spacing below the
  water's edge, so the pressure is that of a column dx/2 shorter;
- the RMS spurious speed below 1e-3 sqrt(g H) and the largest below
  3e-3 sqrt(g H) at every written time;
- the pressure of the surface row within 1 % of rho g H of hydrostatics
  (RMS over the row and the written times);
- no particle lost or outside the tank;
- the log names the model and reports each step's pressure solve
  (iterations, residual); the run cost has the model's parts;
- the solvers agree: 0.05 s with CG, BiCGStab and BoomerAMG give the same
  pressures within 1e-6 of rho g H;
- the consistent Laplacian (laplacian consistent, BiCGStab) keeps it still
  and hydrostatic too, and so do the walls as unknowns (wallPressure
  implicit or solved, BiCGStab); an unknown laplacian is an error naming
  it, and so is laplacian consistent with CG (a solver for symmetric
  matrices);
- a solve that cannot converge (maxIter 1) stops the run with a diagnosis
  naming the solver and its residual; an unknown solver is an error
  naming 'solver'.
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.path.dirname(os.path.dirname(here))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import copy_case, run, run_parts, run_steps  # noqa: E402
from foamCloud import read_cloud, times  # noqa: E402
from foamMonitor import run_cost  # noqa: E402

TUTORIAL = os.path.join(project, "tutorials", "isphTlsphFoam", "stillWater")
sys.path.insert(0, os.path.join(TUTORIAL, "validation"))
import validate as still  # noqa: E402  (the tutorial's measures)

H, G, RHO = 0.1, 9.81, 1000.0
PP = "constant/particleProperties"
CD = "system/controlDict"


def set_entry(case, dictionary, key, value):
    for action in ("-add", "-set"):
        code, out = run(["foamDictionary", dictionary, "-entry", key, action,
                         str(value)], case)
        if code != 0:
            raise RuntimeError(out)


def make_case(work, name, entries=(), end=None):
    case = copy_case(TUTORIAL, os.path.join(work, name))
    for key, value in entries:
        set_entry(case, PP, key, value)
    if end is not None:
        set_entry(case, CD, "endTime", end)
        set_entry(case, CD, "writeInterval", end)
    return case


def still_water(t, work):
    case = make_case(work, "cg")
    ok, out = run_steps(t, case, ("blockMesh", "seedParticles",
                                  "isphTlsphFoam"), "still water: ")
    if not ok:
        return
    t.check("log shows 'model isph'", "model isph" in out)
    t.check("log reports the pressure solves",
            "water: pressure CG," in out and "iterations, residual" in out)

    m = still.measure(case)
    t.check_close("ran to 2 s", m["end"], 2.0, 1e-9)
    t.check_close("bottom pressure over 1-2 s vs rho g (y_s - dx/2)",
                  m["bottom"], m["expected"], 0.01)
    t.check("surface row: pressure off hydrostatics by %.4f rho g H RMS"
            " (< 0.01)" % (m["noise"] / (RHO * G * H)),
            m["noise"] < 0.01 * RHO * G * H)
    t.check("no particle lost", m["kept"])
    t.check("every particle inside the tank", m["inside"])
    scale = math.sqrt(G * H)
    rms = max(r for _, r, _ in m["history"])
    largest = max(x for _, _, x in m["history"])
    t.check("RMS spurious speed, largest over 2 s, %.2e < 1e-3 sqrt(gH)"
            % (rms / scale), rms < 1e-3 * scale, str(m["history"]))
    t.check("largest spurious speed over 2 s %.2e < 3e-3 sqrt(gH)"
            % (largest / scale), largest < 3e-3 * scale, str(m["history"]))

    code, out = run(["/usr/bin/python3", "validation/validate.py", ".",
                     "--check"], case)
    t.check("the tutorial's validate.py --check passes and writes result.md",
            code == 0 and "PASS" in out and os.path.isfile(
                os.path.join(case, "validation", "result.md")), out[-800:])

    parts = run_cost(case)["parts"]
    for part in ("water.isph", "water.poissonAssembly",
                 "water.pressureSolve", "water.projection"):
        t.check("run cost has the part %s" % part,
                parts.get(part, {}).get("calls", 0) > 0, str(sorted(parts)))


def solvers(t, work):
    pressures = {}
    for solver in ("CG", "BiCGStab", "BoomerAMG"):
        case = make_case(work, solver, [
            ("bodies/water/pressureSolver/solver", solver)], end=0.05)
        ok, out = run_steps(t, case, ("blockMesh", "seedParticles",
                                      "isphTlsphFoam"), solver + ": ")
        if not ok:
            continue
        t.check(solver + ": log reports its solves",
                "water: pressure %s," % solver in out)
        c = read_cloud(case, times(case)[-1][1], "water")
        pressures[solver] = c["p"]
    if len(pressures) == 3:
        for solver in ("BiCGStab", "BoomerAMG"):
            diff = max(abs(a - b) for a, b in
                       zip(pressures["CG"], pressures[solver]))
            t.check("%s and CG agree: largest difference %.2e rho g H"
                    " (< 1e-6)" % (solver, diff / (RHO * G * H)),
                    diff < 1e-6 * RHO * G * H)


def consistent(t, work):
    """The consistent Laplacian (laplacian consistent; BiCGStab): still
    water stays still and hydrostatic too."""
    case = make_case(work, "consistent", [
        ("bodies/water/laplacian", "consistent"),
        ("bodies/water/pressureSolver/solver", "BiCGStab")])
    ok, out = run_steps(t, case, ("blockMesh", "seedParticles",
                                  "isphTlsphFoam"), "consistent: ")
    if not ok:
        return
    m = still.measure(case)
    t.check_close("consistent: ran to 2 s", m["end"], 2.0, 1e-9)
    t.check_close("consistent: bottom pressure over 1-2 s vs rho g"
                  " (y_s - dx/2)", m["bottom"], m["expected"], 0.01)
    scale = math.sqrt(G * H)
    largest = max(x for _, _, x in m["history"])
    t.check("consistent: largest spurious speed over 2 s %.2e < 3e-3"
            " sqrt(gH)" % (largest / scale), largest < 3e-3 * scale)


def options(t, work):
    """The dam break's options (isph.H) keep still water still and
    hydrostatic: the walls as unknowns (wallPressure implicit or solved,
    BiCGStab),
    the one-sided density-invariance term with the walls' contact
    condition; wallPressure implicit with CG is an error naming both."""
    variants = (
        ("wallImplicit", [("bodies/water/wallPressure", "implicit"),
                          ("bodies/water/pressureSolver/solver",
                           "BiCGStab")]),
        ("wallSolved", [("bodies/water/wallPressure", "solved"),
                        ("bodies/water/pressureSolver/solver",
                         "BiCGStab")]),
        ("densityInvariant", [
            ("bodies/water/densityInvariantRelaxation", 0.05),
            ("bodies/water/densityInvariantCompressionOnly", "yes"),
            ("bodies/water/wallContact", 1)]))
    scale = math.sqrt(G * H)
    for name, entries in variants:
        case = make_case(work, name, entries)
        ok, _ = run_steps(t, case, ("blockMesh", "seedParticles",
                                    "isphTlsphFoam"), name + ": ")
        if not ok:
            continue
        m = still.measure(case)
        t.check_close(name + ": ran to 2 s", m["end"], 2.0, 1e-9)
        t.check_close(name + ": bottom pressure over 1-2 s vs rho g"
                      " (y_s - dx/2)", m["bottom"], m["expected"], 0.01)
        largest = max(x for _, _, x in m["history"])
        t.check(name + ": largest spurious speed over 2 s %.2e < 3e-3"
                " sqrt(gH)" % (largest / scale), largest < 3e-3 * scale)
    case = make_case(work, "wallImplicitCG",
                     [("bodies/water/wallPressure", "implicit")], end=0.01)
    ok, _ = run_steps(t, case, ("blockMesh", "seedParticles"),
                      "wallImplicitCG: ")
    if ok:
        code, out = run(["isphTlsphFoam"], case)
        t.check("wallImplicitCG: the run stops", code != 0, out[-600:])
        for w in ("wallPressure implicit", "CG", "BiCGStab"):
            t.check("wallImplicitCG: the error names '%s'" % w, w in out,
                    out[-1200:])


def bad_input(t, work):
    case = make_case(work, "noConvergence",
                     [("bodies/water/pressureSolver/maxIter", 1)], end=0.01)
    ok, _ = run_steps(t, case, ("blockMesh", "seedParticles"),
                      "noConvergence: ")
    if ok:
        code, out = run(["isphTlsphFoam"], case)
        t.check("noConvergence: the run stops", code != 0, out[-600:])
        for w in ("did not converge", "CG", "residual", "pressureSolver"):
            t.check("noConvergence: the diagnosis names '%s'" % w, w in out,
                    out[-1200:])
    case = make_case(work, "unknownSolver",
                     [("bodies/water/pressureSolver/solver", "Jacobi")],
                     end=0.01)
    ok, _ = run_steps(t, case, ("blockMesh", "seedParticles"),
                      "unknownSolver: ")
    if ok:
        code, out = run(["isphTlsphFoam"], case)
        t.check("unknownSolver: the run stops", code != 0, out[-600:])
        for w in ("solver", "Jacobi", "CG"):
            t.check("unknownSolver: the error names '%s'" % w, w in out,
                    out[-1200:])
    case = make_case(work, "unknownLaplacian",
                     [("bodies/water/laplacian", "exact")], end=0.01)
    ok, _ = run_steps(t, case, ("blockMesh", "seedParticles"),
                      "unknownLaplacian: ")
    if ok:
        code, out = run(["isphTlsphFoam"], case)
        t.check("unknownLaplacian: the run stops", code != 0, out[-600:])
        for w in ("laplacian", "exact", "consistent", "particleProperties"):
            t.check("unknownLaplacian: the error names '%s'" % w, w in out,
                    out[-1200:])
    case = make_case(work, "consistentCG",
                     [("bodies/water/laplacian", "consistent")], end=0.01)
    ok, _ = run_steps(t, case, ("blockMesh", "seedParticles"),
                      "consistentCG: ")
    if ok:
        code, out = run(["isphTlsphFoam"], case)
        t.check("consistentCG: the run stops", code != 0, out[-600:])
        for w in ("laplacian consistent", "CG", "BiCGStab",
                  "particleProperties"):
            t.check("consistentCG: the error names '%s'" % w, w in out,
                    out[-1200:])


if __name__ == "__main__":
    sys.exit(run_parts("isphStillWater", still_water, consistent, solvers,
                       options, bad_input))
