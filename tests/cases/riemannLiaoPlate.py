#!/usr/bin/python3
"""Case test: the dam break on an elastic plate (Liao et al. 2015) with the
Riemann fluid and the TLSPH solid (tutorials/riemannSphFoam/liaoPlate), at
its default resolution (the plate 4 particles thick at 1 mm, the water at
2 mm), through the first impact to 0.32 s:

- validate.py --check: the stability checks (no particle lost, water in
  the tank and not in the plate, energy not growing: the gate, a free-slip
  wall lifted at up to 145 m/s^2, does no work on the water, the plate's
  particle-scale noise, the coupling's forces equal and opposite);
- the water reaches the plate between 0.2 and 0.3 s (0.262 s measured) and
  bends it: the first peak of the tip's x above 0.03 m (0.073 m measured at
  0.287 s; no measured history exists to hold it to).
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(here)),
                                "etc", "python"))
from caseTest import run_parts, run_validated  # noqa: E402
from foamMonitor import read_monitor  # noqa: E402
from liaoPlate import figures  # noqa: E402

TUTORIAL = "tutorials/riemannSphFoam/liaoPlate"


def plate(t, work):
    case = run_validated(t, TUTORIAL, work, "default", ("-end", "0.32"))
    if case is None:
        return
    tip = read_monitor(case, "tip")
    fig = figures(tip["time"], tip["dx"])
    t.check("impact between 0.2 and 0.3 s (%.3f s)" % fig["impact"],
            0.2 < fig["impact"] < 0.3)
    t.check("first peak of the tip's x above 0.03 m (%.4f m at %.3f s)"
            % fig["first"], fig["first"][0] > 0.03)


if __name__ == "__main__":
    sys.exit(run_parts("riemannLiaoPlate", plate))
