#!/usr/bin/python3
"""Case test: the ULPH-PD fluid-structure tutorials at coarse spacings:
the dam break on an elastic obstacle and its fracturing variant (ULPH-NOSBPD
paper 4.4, tutorials elasticObstacle and obstacleFracture; 4 mm, the
obstacle 3 particles thick, to 0.3 s, past the first peak of the obstacle's
deflection) and the elastic gate (paper 4.6, tutorial elasticGate; 2.5 mm
to 0.15 s, past the 0.111 s where its jet used to blow up).

elasticObstacle:
- Allrun and its validation succeed; the first peak of point A's
  displacement lies within a band for this spacing, FIRST_PEAK (the paper's
  2 mm is checked against the published band by the tutorial itself);
elasticObstacle and elasticGate:
- momentum exchange: per step the fluid's force on the solid and the
  solid's force on the fluid cancel to 1e-9 of their size;
- stability: no particle lost, no water particle inside the solid (every
  water particle further than a quarter spacing from every solid particle,
  at every written time), the total energy not growing by more than 1e-3
  of the water's initial potential energy.
obstacleFracture: its validation's stability checks hold (runs to the end,
no particle lost, water inside the tank, energy not growing); whether bonds
broke is printed only (at this spacing none do).
"""
import math
import os
import re
import shutil
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import (CaseTest, copy_case, project_dir, run,  # noqa: E402
                      scratch, set_entry, table)
sys.path.insert(0, os.path.join(project_dir, "etc", "python"))
from foamCloud import read_positions, times  # noqa: E402
from foamMonitor import read_monitor  # noqa: E402

# First peak of point A at 4 mm: value [m] and time [s] bands
FIRST_PEAK = ((0.030, 0.060), (0.19, 0.28))


def prepare(t, name, work, dx, end):
    src = os.path.join(project_dir, "tutorials", "ulphPdFoam", name)
    case = copy_case(src, os.path.join(work, name))
    shutil.rmtree(os.path.join(case, "validation"))
    shutil.copytree(os.path.join(src, "validation"),
                    os.path.join(case, "validation"),
                    ignore=shutil.ignore_patterns("*.md", "*.png"))
    set_entry(case, "system/controlDict", "endTime", end)
    code, out = run(["./Allrun", "-dx", str(dx)], case)
    t.check("%s: Allrun -dx %g to %g s succeeds" % (name, dx, end),
            code == 0, out[-2000:])
    return case, code, out


def nearest_squared(points, others, radius):
    """Smallest squared distance from any of points to any of others,
    through a bucket grid of the others (cell size radius)"""
    grid = {}
    for q in others:
        grid.setdefault((int(q[0] // radius), int(q[1] // radius)),
                        []).append(q)
    best = math.inf
    for p in points:
        i, j = int(p[0] // radius), int(p[1] // radius)
        for di in (-1, 0, 1):
            for dj in (-1, 0, 1):
                for q in grid.get((i + di, j + dj), ()):
                    best = min(best, (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2)
    return best


def stability(t, case, solid, dx, energy_scale):
    """Momentum exchange, particle counts, no water in the solid, energy"""
    name = os.path.basename(case)
    forces = table(os.path.join(case, "postProcessing", "coupling", "0",
                                "forces.dat"))
    worst = max(math.hypot(r[1] + r[4], r[2] + r[5])
                / max(math.hypot(r[1], r[2]), 1e-30) for r in forces
                if math.hypot(r[1], r[2]) > 1e-6)
    t.check("%s: fluid-on-solid + solid-on-fluid = 0 (worst %.1e of the"
            " force)" % (name, worst), worst < 1e-9)

    series = times(case)
    n0 = {b: len(read_positions(case, series[0][1], b))
          for b in ("water", solid)}
    closest = math.inf
    for _, tn in series:
        water = read_positions(case, tn, "water")
        body = read_positions(case, tn, solid)
        if len(water) != n0["water"] or len(body) != n0[solid]:
            t.check("%s: no particle lost at time %s" % (name, tn), False)
            return
        closest = min(closest, nearest_squared(water, body, dx))
    t.check("%s: no particle lost (%d written times)" % (name, len(series)),
            True)
    t.check("%s: no water particle inside the %s (closest %.2f dx >"
            " 0.25 dx)" % (name, solid, math.sqrt(closest) / dx),
            math.sqrt(closest) > 0.25 * dx)

    energy = read_monitor(case, "energy")
    rise = max(energy["total"]) - energy["total"][0]
    t.check("%s: total energy not growing (rise %.2e J/m <= %.2e)"
            % (name, rise, 1e-3 * energy_scale), rise <= 1e-3 * energy_scale)


def elastic_obstacle(t, work):
    case, code, out = prepare(t, "elasticObstacle", work, 0.004, 0.3)
    if code != 0:
        return
    m = re.search(r"first peak ([0-9.e-]+) m at ([0-9.]+) s", out)
    t.check("validation printed the first peak", m is not None, out[-1500:])
    if m:
        x, tp = float(m.group(1)), float(m.group(2))
        (x0, x1), (t0, t1) = FIRST_PEAK
        t.check("first peak %.4f m at %.3f s within %g-%g m, %g-%g s"
                % (x, tp, x0, x1, t0, t1), x0 <= x <= x1 and t0 <= tp <= t1)
    # rho g H^2 W/2 of the column (H = 2L = 0.292, W = L = 0.146)
    stability(t, case, "obstacle", 0.004, 1000 * 9.81 * 0.292 ** 2 * 0.146 / 2)


def elastic_gate(t, work):
    case, code, out = prepare(t, "elasticGate", work, 0.0025, 0.15)
    if code != 0:
        return
    # rho g H^2 W/2 of the water (H = 0.14, W = 0.1)
    stability(t, case, "gate", 0.0025, 1000 * 9.81 * 0.14 ** 2 * 0.1 / 2)


def obstacle_fracture(t, work):
    case, code, out = prepare(t, "obstacleFracture", work, 0.004, 0.3)
    if code != 0:
        return
    # Stability checks of its validation; whether bonds break at this
    # spacing is printed, not required (none did at 4 mm to 0.4 s)
    lines = [line for line in out.splitlines()
             if line.startswith("met: ") or line.startswith("MISSED: ")]
    t.check("obstacleFracture: validation ran", len(lines) >= 6, out[-1500:])
    for line in lines:
        what = line.split(": ", 1)[1]
        if what.startswith("bonds broke"):
            print("           obstacleFracture: " + what)
            continue
        t.check("obstacleFracture: " + what, line.startswith("met: "))


def main():
    t = CaseTest("ulphPdFsi")
    work = scratch("ulphPdFsi")
    try:
        elastic_obstacle(t, work)
        obstacle_fracture(t, work)
        elastic_gate(t, work)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return t.finish()


if __name__ == "__main__":
    sys.exit(main())
