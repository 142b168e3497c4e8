#!/usr/bin/python3
"""Case test: the dam break on an elastic plate (Liao et al. 2015) with the
ISPH fluid and the TLSPH solid coupled by isphTlsph
(tutorials/isphTlsphFoam/liaoPlate), at its default resolution (the plate
4 particles thick at 1 mm, the water at 4 mm), through the first impact
and the plate's fold onto the floor to 0.32 s, with the checks of
riemannLiaoPlate.py: the validation's (no particle lost, the water in the
tank, the plate out of the floor, the coupling's forces equal and opposite
at every step), the impact between 0.2 and 0.3 s and the first peak of the
tip's x above 0.03 m. Three of the validation's checks are missed, as the
tutorial's README documents (KNOWN): the total energy rises before the
impact (the density-invariant source and the gate's lift), water comes
within 0.25 dx of the plate's particles, and the plate's particle-scale
noise exceeds 0.1 sqrt(g H) at 0.30 s (its tip bouncing on the floor).
The energy's rise is held below RISE_BOUND (1.91 J/m measured; 10.9 J/m
before the structure's wall contact stopped speeding water up), and at
most MAX_UNCONVERGED coupling step reaches maxIterations (one, at the
plate's fold onto the floor at 0.289 s, which ends at its least iterate,
relative residual 9e-4).
"""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import run_parts  # noqa: E402
from isphElasticGate import iteration_stats  # noqa: E402
from riemannLiaoPlate import plate_checks  # noqa: E402

TUTORIAL = "tutorials/isphTlsphFoam/liaoPlate"
KNOWN = ("total energy not growing", "no water particle inside the plate",
         "the plate's particle-scale velocity noise")
POTENTIAL = 1000 * 9.81 * 0.4 ** 2 * 0.2 / 2     # the column's [J/m]
RISE_BOUND = 3.0        # [J/m]: 1.91 measured
MAX_UNCONVERGED = 1


def plate(t, work):
    case = plate_checks(t, TUTORIAL, work, KNOWN)
    if case is None:
        return
    with open(os.path.join(case, "validation", "result.md")) as f:
        m = re.search(r"largest rise ([0-9.e+-]+) J/m", f.read())
    t.check("result.md gives the energy's rise", m is not None)
    if m:
        rise = float(m.group(1))
        t.check("the energy's rise %.3g J/m below %g J/m (the column's"
                " potential energy %.1f J/m)" % (rise, RISE_BOUND, POTENTIAL),
                rise < RISE_BOUND)
    s = iteration_stats(t, case)
    if s:
        t.check("%.2f iterations per step on average; %d step(s) at"
                " maxIterations, at most %d" % (s + (MAX_UNCONVERGED,)),
                s[1] <= MAX_UNCONVERGED)


if __name__ == "__main__":
    sys.exit(run_parts("isphLiaoPlate", plate))
