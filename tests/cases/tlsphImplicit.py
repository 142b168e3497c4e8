#!/usr/bin/python3
"""Case test: the implicit integrator of the solids (integrator implicit:
generalised-alpha, Newton with the coloured finite-difference tangent)
against the explicit RK4 results it must converge to.

- The oscillating plate (tutorials/isphTlsphFoam/oscillatingPlate, T/dx =
  10, finite kinematics, to 0.7 s): RK4 at the acoustic step and the
  implicit integrator at a fixed 2.5 ms (about 100 steps per period) give
  periods within 0.5 % and first amplitudes within 0.2 % of each other.
- The clamped beam (tutorials/isphTlsphFoam/clampedBeam, n = 5, small
  kinematics, damped to rest): static tip deflections within 0.2 % of each
  other, the implicit run at 10 us (300 steps) with one tangent and one
  factorisation for the whole run (a linear law at a fixed step).
- Bad input: rhoInfinity outside [0, 1] and an unknown scheme stop the run
  naming the keyword; a solid alone with adjustTimeStep and no maxDeltaT
  (nothing limits the implicit step) stops naming maxDeltaT; a Newton
  that cannot converge (maxIter 1, tolerance 1e-14) stops as a blow-up
  naming the residual after halving the step.
"""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import run, run_parts, run_tutorial, set_entry  # noqa: E402
from foamMonitor import load_runs  # noqa: E402

PLATE = "tutorials/isphTlsphFoam/oscillatingPlate"
BEAM = "tutorials/isphTlsphFoam/clampedBeam"


def only_run(case):
    runs = load_runs(os.path.join(case, "validation", "runs"))
    return runs[0] if len(runs) == 1 else None


def explicit_and_implicit(t, tutorial, work, name, args, dt):
    """The tutorial run by Allrun args with RK4 and with -implicit dt:
    (the RK4 run's figures, the implicit run's, the implicit case)"""
    ex, _, _ = run_tutorial(t, tutorial, work, name + "RK4", args)
    im, _, _ = run_tutorial(t, tutorial, work, name + "Implicit",
                            args + ("-implicit", dt))
    a, b = only_run(ex), only_run(im)
    t.check("both %s runs kept" % name, a is not None and b is not None)
    return a, b, im


def plate(t, work):
    a, b, im = explicit_and_implicit(t, PLATE, work, "plate",
                                     ("-dx", "0.002"), "0.0025")
    if a is None or b is None:
        return
    dp = b["period"] / a["period"] - 1
    da = b["amplitude"] / a["amplitude"] - 1
    t.check("plate: implicit period %.3f vs RK4 %.3f (t c0/L), %+.3f %% "
            "within 0.5 %%" % (b["period"], a["period"], 100 * dp),
            abs(dp) < 0.005)
    t.check("plate: implicit amplitude %.5f vs RK4 %.5f (A/L), %+.3f %% "
            "within 0.2 %%" % (b["amplitude"], a["amplitude"], 100 * da),
            abs(da) < 0.002)
    t.check("plate: implicit %d steps, RK4 %d" % (b["steps"], a["steps"]),
            b["steps"] * 50 < a["steps"])

    # Bad input on the implicit copy
    def refused(what, params, words, time_params=None):
        with open(os.path.join(im, "system", "runParameters"), "a") as f:
            f.write(params)
        if time_params is not None:
            with open(os.path.join(im, "system", "timeParameters"),
                      "w") as f:
                f.write(time_params)
        code, log = run(["isphTlsphFoam"], im)
        t.check(what, code != 0 and all(w in log for w in words),
                log[-1500:])

    base = open(os.path.join(im, "system", "runParameters")).read()
    set_entry(im, "constant/particleProperties",
              "bodies/plate/implicit", "{ rhoInfinity 2; }")
    refused("rhoInfinity 2 refused, naming the keyword", "",
            ["rhoInfinity 2", "0 <= rhoInfinity <= 1"])
    set_entry(im, "constant/particleProperties",
              "bodies/plate/implicit", "{ scheme euler; }")
    refused("an unknown implicit scheme refused, naming both schemes", "",
            ["scheme euler", "generalisedAlpha", "newmark"])
    set_entry(im, "constant/particleProperties",
              "bodies/plate/implicit", "{ }")
    refused("adjustTimeStep without maxDeltaT refused for an implicit "
            "solid alone, naming maxDeltaT", "",
            ["maxDeltaT", "no body limits the step"],
            "adjustTimeStep yes;\n")
    with open(os.path.join(im, "system", "runParameters"), "w") as f:
        f.write(base)
    set_entry(im, "constant/particleProperties",
              "bodies/plate/implicit", "{ maxIter 1; tolerance 1e-14; }")
    refused("Newton that cannot converge stops as a blow-up naming the "
            "residual", "", ["Blow-up", "Newton did not converge",
                             "16 parts", "residual"],
            "adjustTimeStep no;\ndeltaT 0.0025;\n")


def beam(t, work):
    a, b, im = explicit_and_implicit(t, BEAM, work, "beam", ("-n", "5"),
                                     "1e-5")
    if a is None or b is None:
        return
    dd = b["deflection"] / a["deflection"] - 1
    t.check("beam: implicit deflection %.4f mm vs RK4 %.4f mm, %+.3f %% "
            "within 0.2 %%" % (1e3 * b["deflection"], 1e3 * a["deflection"],
                               100 * dd), abs(dd) < 0.002)
    log = open(os.path.join(im, "log.isphTlsphFoam")).read()
    m = re.findall(r"beam: Newton (\d+) iterations.*tangents (\d+) .*"
                   r"factorisations (\d+)", log)
    t.check("beam: one tangent and one factorisation for the run (linear "
            "law, fixed step): %s" % (("tangents %s, factorisations %s"
                                       % m[-1][1:]) if m else "no log line"),
            bool(m) and m[-1][1] == "1" and m[-1][2] == "1")


if __name__ == "__main__":
    sys.exit(run_parts("tlsphImplicit", plate, beam))
