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
tutorial's README documents (KNOWN): the impact on the flexible plate adds
energy (a rigid plate's loses it), water comes within 0.25 dx of the
plate's particles, and the plate's particle-scale noise exceeds 0.1
sqrt(g H) at 0.32 s. The energy's rise is held below a tenth of the
column's potential energy (15.7 J/m; 10.9 J/m measured), and every
coupling step converged (none at maxIterations).
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


def plate(t, work):
    case = plate_checks(t, TUTORIAL, work, KNOWN)
    if case is None:
        return
    with open(os.path.join(case, "validation", "result.md")) as f:
        m = re.search(r"largest rise ([0-9.e+-]+) J/m", f.read())
    t.check("result.md gives the energy's rise", m is not None)
    if m:
        rise = float(m.group(1))
        t.check("the energy's rise %.3g J/m below a tenth of the column's"
                " potential energy (%.1f J/m)" % (rise, 0.1 * POTENTIAL),
                rise < 0.1 * POTENTIAL)
    s = iteration_stats(t, case)
    if s:
        t.check("%.2f iterations per step on average; every step converged"
                " (%d at maxIterations)" % s, s[1] == 0)


if __name__ == "__main__":
    sys.exit(run_parts("isphLiaoPlate", plate))
