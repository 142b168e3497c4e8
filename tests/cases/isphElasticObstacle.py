#!/usr/bin/python3
"""Case test: the dam break on an elastic obstacle (Walhorn et al. 2005)
with the ISPH fluid and the TLSPH solid coupled by isphTlsph
(tutorials/isphTlsphFoam/elasticObstacle), coarse: the obstacle at 4 mm
(3 particles thick), the water at 8 mm, to 0.3 s (past the first peak at
0.22 s):

- every stability check of the validation met (no particle lost, no water
  inside the obstacle or through the tank's walls, the total energy rising
  by less than 1e-3 of the column's potential energy, the obstacle's
  particle-scale noise); the first peak found (the displacement falls back
  after it) and above 2 cm (5.3 cm at 0.222 s measured; the published band
  4.10-4.91 cm is the default resolution's target, not this one's);
- the coupling: every step's forces on the obstacle and on the water
  cancel to 1e-9 of their size; every step converged (none at
  maxIterations; 2.9 iterations per step measured).
"""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import run_parts, run_tutorial  # noqa: E402
from isphElasticGate import (exchange_checks,  # noqa: E402
                             iteration_stats, validation_lines)

TUTORIAL = "tutorials/isphTlsphFoam/elasticObstacle"


def obstacle(t, work):
    case, code, out = run_tutorial(t, TUTORIAL, work, "coarse",
                                   ("-dx", "0.004", "-end", "0.3"))
    if code != 0:
        return
    met, missed = validation_lines(out)
    t.check("validation: stability checks met (%d)" % len(met),
            len(met) == 6 and not missed, "\n".join(missed) or out[-1500:])
    m = re.search(r"first peak ([0-9.]+) m at ([0-9.]+) s; published band"
                  r"[^\n]*: (met|MISSED)( \(the run ends)?", out)
    t.check("validation: the first peak printed", m is not None, out[-1500:])
    if m:
        t.check("first peak %s m at %s s, found (the displacement falls"
                " back after it) and above 2 cm" % m.group(1, 2),
                m.group(4) is None and float(m.group(1)) > 0.02)
    exchange_checks(t, case, "obstacle")
    s = iteration_stats(t, case)
    if s:
        t.check("%.2f iterations per step on average; every step converged"
                " (%d at maxIterations)" % s, s[1] == 0)


if __name__ == "__main__":
    sys.exit(run_parts("isphElasticObstacle", obstacle))
