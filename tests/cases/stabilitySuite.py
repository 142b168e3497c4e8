#!/usr/bin/python3
"""The stability suite's coarse form (tests/stability/stability.py): every
method on its hardest cases, each invariant at every written time one
check; the summary line counts the invariants met and missed.

And on the suite's baffle fracture run (ULPH + NOSB-PD, 4 mm, 0.4 s):
ParaView's reader (vtkOpenFOAMReader) loads its last time, the water and
the obstacle with their particle counts and the obstacle's damage and
plastic strain fields."""
import glob
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "stability"))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "lib"))
import stability  # noqa: E402
from caseTest import CaseTest  # noqa: E402
from foamCloud import read_positions, times  # noqa: E402
from readClouds import read_clouds  # noqa: E402


def reader_checks(work):
    t = CaseTest("stabilitySuite")
    runs = glob.glob(os.path.join(work, "obstacleFracture-*"))
    t.check("the baffle fracture's run is there", len(runs) == 1, str(runs))
    if len(runs) == 1:
        case = runs[0]
        last = times(case)[-1]
        clouds = read_clouds(case, last[0])
        for body in ("water", "obstacle"):
            n = len(read_positions(case, last[1], body))
            got = clouds.get(body, {"particles": -1})["particles"]
            t.check("obstacleFracture: the reader sees %s's %d particles at"
                    " %s s (%d)" % (body, n, last[1], got), got == n)
        seen = set(clouds.get("obstacle", {"arrays": {}})["arrays"])
        wanted = {"damage", "plasticStrain", "U"}
        t.check("obstacleFracture: the reader sees the obstacle's damage,"
                " plasticStrain, U", wanted <= seen, str(sorted(seen)))
    return t.passed, t.failed


if __name__ == "__main__":
    argv = sys.argv[1:]
    chosen = "-case" in argv or "-method" in argv
    sys.exit(stability.main(argv, "stabilitySuite",
                            None if chosen else reader_checks))
