#!/usr/bin/python3
"""Case test: the rolling tank with an elastic baffle (Idelsohn et al.
2008) with the ISPH fluid and the TLSPH solid coupled by isphTlsph
(tutorials/isphTlsphFoam/rollingTankBaffle), at its default resolution
(the baffle 4 particles thick at 1 mm, the oil at 2 mm), through the first
half period of the roll to 0.5 s: the checks of riemannRollingTank.py
(validate.py --check: no particle lost, the oil inside the rolled tank and
out of the baffle, the baffle's particle-scale noise, the coupling's
forces equal and opposite at every step; the baffle's foot on the roll;
the tip bent to -x in the tank's frame), every coupling step
converged (none at maxIterations), and a step's pressure re-solves start
from the last solve's pressure (isphElasticGate.resolve_check).
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import run_parts  # noqa: E402
from isphElasticGate import iteration_stats, resolve_check  # noqa: E402
from riemannRollingTank import tank_checks  # noqa: E402

TUTORIAL = "tutorials/isphTlsphFoam/rollingTankBaffle"


def tank(t, work):
    case = tank_checks(t, TUTORIAL, work)
    if case is None:
        return
    s = iteration_stats(t, case)
    if s:
        t.check("%.2f iterations per step on average; every step converged"
                " (%d at maxIterations)" % s, s[1] == 0)
    resolve_check(t, case)


if __name__ == "__main__":
    sys.exit(run_parts("isphRollingTank", tank))
