#!/usr/bin/python3
"""Case test: the ISPH fluid in a swaying tank, the water named before its
moving walls.

The scene of tutorials/ulphPdFoam/sloshingTank (tank 1.73 x 1.15 m, water
0.5 m deep, eq. 60's sway through tabulated6DoFMotion) at dx = 0.02 m with
the projection ISPH fluid (isphSloshing/constant/particleProperties) for
1 s, in which the tank moves by up to 0.064 m = 3.2 dx. Checks:
- the run succeeds and no water particle is deeper than 0.5 dx in a wall
  at any written time (a contact line's particle may touch a face). The water body comes first in 'bodies': its neighbour
  relations with the tank are made before the tank sets up its motion,
  and a wall that reported itself fixed then got static neighbour lists
  (ghostWall::moving); the water leaked through the floor from
  t = 0.65 s, when the tank had moved 2.5 dx (blow-up at 0.81 s);
- the tank is where eq. 60 puts it at t = T/2 (1e-6 m).
"""
import os
import shutil
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.path.dirname(os.path.dirname(here))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import copy_case, run_parts, run_steps, set_entry  # noqa: E402
from foamCloud import read_positions, times  # noqa: E402
from swayChecks import check_tank  # noqa: E402
from swayTank import SwayTank  # noqa: E402

T = 1.875
DX = 0.02
TANK = SwayTank(length=1.73, depth=0.5, amplitude=0.032, period=T)


def motion_table(path):
    """Eq. 60 as tabulated6DoFMotion's table, as the tutorial's Allrun"""
    rows = [k * 0.005 - 0.01 for k in range(int(1.12 / 0.005) + 1)]
    with open(path, "w") as f:
        f.write("%d\n(\n" % len(rows))
        for t in rows:
            f.write("(%.4f ((%.10f 0 0) (0 0 0)))\n" % (t, TANK.tank_x(t)))
        f.write(")\n")


def sloshing(t, work):
    case = copy_case(os.path.join(project, "tutorials", "ulphPdFoam",
                                  "sloshingTank"),
                     os.path.join(work, "isphSloshing"))
    shutil.copy(os.path.join(here, "isphSloshing", "constant",
                             "particleProperties"),
                os.path.join(case, "constant", "particleProperties"))
    motion_table(os.path.join(case, "constant", "tankMotion.dat"))
    with open(os.path.join(case, "system", "resolution"), "w") as f:
        f.write("dx %g;\n" % DX)
    set_entry(case, "system/controlDict", "application", "isphTlsphFoam")
    set_entry(case, "system/controlDict", "endTime", 1.0)
    set_entry(case, "system/controlDict", "writeInterval", 0.05)
    set_entry(case, "system/controlDict", "maxCo", 0.1)
    ok, _ = run_steps(t, case, ("blockMesh", "seedParticles",
                                "isphTlsphFoam"))
    if not ok:
        return
    series = times(case)
    t.check_close("ran to 1 s", series[-1][0], 1.0, 1e-9)
    deepest = 0.0
    for time, name in series:
        X = TANK.tank_x(time)
        for p in read_positions(case, name, "water"):
            deepest = max(deepest, X - p[0], p[0] - TANK.L - X, -p[1])
    t.check("no water particle deeper than 0.5 dx in a wall at any written"
            " time (deepest %.2f dx)" % (deepest / DX), deepest < 0.5 * DX)
    check_tank(t, case, TANK)


if __name__ == "__main__":
    sys.exit(run_parts("isphSloshing", sloshing))
