#!/usr/bin/python3
"""Case test: the dam break on an elastic plate (Liao et al. 2015) with the
ISPH fluid and the TLSPH solid coupled by isphTlsph
(tutorials/isphTlsphFoam/liaoPlate), at its default resolution (the plate
4 particles thick at 1 mm, the water at 4 mm), through the first impact
and the plate's fold onto the floor to 0.32 s, with the checks of
riemannLiaoPlate.py: the validation's (no particle lost, the water in the
tank, the plate out of the floor, the coupling's forces equal and opposite
at every step), the impact between 0.2 and 0.3 s and the first peak of the
tip's x above 0.03 m. One of the validation's checks is missed to 0.32
s, as the tutorial's README documents (KNOWN): the total energy rises
before the impact (the time integration's error, first order in the
step; the water comes within 0.25 dx of the plate's particles only
later). The energy's rise is held below RISE_BOUND (0.446 J/m measured;
1.91 J/m with the density-invariant source, 10.9 J/m before the
structure's wall contact stopped speeding water up), and at
most MAX_UNCONVERGED coupling steps reach maxIterations (two, as the
plate folds onto the floor at 0.296 and 0.306 s, which end at their
least iterates, relative residuals 1.6e-4 and 2.4e-4 against the
tolerance's 1e-4; with the density-invariant source one, at 0.289 s,
9e-4).
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
KNOWN = ("total energy not growing",)
POTENTIAL = 1000 * 9.81 * 0.4 ** 2 * 0.2 / 2     # the column's [J/m]
RISE_BOUND = 1.0        # [J/m]: 0.446 measured
MAX_UNCONVERGED = 2


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
