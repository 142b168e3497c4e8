#!/usr/bin/python3
"""Case test: the ULPH-PD fluid-structure tutorials at coarse spacings:
the dam break on an elastic obstacle (ULPH-NOSBPD paper 4.4, tutorial
elasticObstacle; 4 mm, the obstacle 3 particles thick, to 0.3 s, past the
first peak of the obstacle's deflection) and the elastic gate (paper 4.6,
tutorial elasticGate; 2.5 mm to 0.15 s, past the 0.111 s where its jet used
to blow up).

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
  of the water's initial potential energy, the solid's particle-scale
  velocity noise below 0.1 sqrt(g H) (etc/python/fsiChecks.py).
sluiceGate (paper 4.5; 3.5 mm, the gate 2 particles thick, to 0.3 s):
the momentum exchange and stability checks above, the run cost has the
time of the walls' repulsion of thin layers, and the gate opens (its free
end moves downstream by more than 2 spacings).
Coupled restart: elasticGate to 0.06 s in one go and stopped at 0.03 s
and restarted end at the same particles (RESTART_TOLERANCE) in as many
steps (the run cost of the two runs).
ParaView's reader loads the last time of sluiceGate. The fracturing
variant (obstacleFracture, 4 mm) runs in the stability suite
(tests/cases/stabilitySuite.py: its invariants, and the reader with the
damage and plastic strain fields).
"""
import math
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import (copy_case, project_dir, run, run_parts,  # noqa: E402
                      run_steps, run_tutorial, set_entry)
from fsiChecks import momentum_exchange, stability_checks  # noqa: E402
from foamCloud import read_positions, times  # noqa: E402
from foamMonitor import run_cost  # noqa: E402
from readClouds import read_clouds  # noqa: E402

# The sluice gate's run: past the water's arrival (about 0.2 s) and the
# opening of the gate
SLUICE_END = 0.3

# Restarted coupled run against the uninterrupted one: positions [m]
# (ascii writes of 12 digits)
RESTART_TOLERANCE = 1e-9

# First peak of point A at 4 mm: value [m] and time [s] bands
FIRST_PEAK = ((0.030, 0.060), (0.19, 0.28))


def prepare(t, name, work, dx, end):
    return run_tutorial(t, "tutorials/ulphPdFoam/" + name, work, name,
                        ("-dx", "%g" % dx), end)


def stability(t, case, solid, tank, dx, energy_scale, depth):
    """Momentum exchange, and fsiChecks' stability checks (run to the end,
    particle counts, water in the tank and not in the solid, energy, the
    solid's velocity noise below 0.1 sqrt(g depth))"""
    name = os.path.basename(case)
    worst = momentum_exchange(case, floor=1e-6)
    t.check("%s: fluid-on-solid + solid-on-fluid = 0 (worst %.1e of the"
            " force)" % (name, worst), worst < 1e-9)

    for what, good in stability_checks(case, solid, tank, dx, energy_scale,
                                       velocity_scale=math.sqrt(9.81 * depth)):
        t.check("%s: %s" % (name, what), good)


def reader_sees(t, case, solid, arrays):
    """ParaView's reader (vtkOpenFOAMReader) loads the last time's clouds:
    the water and the solid with their particle counts, and the solid's
    fields 'arrays'"""
    name = os.path.basename(case)
    last = times(case)[-1]
    clouds = read_clouds(case, last[0])
    for body in ("water", solid):
        n = len(read_positions(case, last[1], body))
        got = clouds.get(body, {"particles": -1})["particles"]
        t.check("%s: the reader sees %s's %d particles at %s s (%d)"
                % (name, body, n, last[1], got), got == n)
    seen = set(clouds.get(solid, {"arrays": {}})["arrays"])
    t.check("%s: the reader sees the %s's %s" % (name, solid,
                                                 ", ".join(arrays)),
            set(arrays) <= seen, str(sorted(seen)))


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
    stability(t, case, "obstacle", (0, 0.584), 0.004,
              1000 * 9.81 * 0.292 ** 2 * 0.146 / 2, 0.292)


def elastic_gate(t, work):
    case, code, out = prepare(t, "elasticGate", work, 0.0025, 0.15)
    if code != 0:
        return
    # rho g H^2 W/2 of the water (H = 0.14, W = 0.1)
    stability(t, case, "gate", (0, 0.5), 0.0025,
              1000 * 9.81 * 0.14 ** 2 * 0.1 / 2, 0.14)


def sluice_gate(t, work):
    case, code, out = prepare(t, "sluiceGate", work, 0.0035, SLUICE_END)
    if code != 0:
        return
    # rho g H^2 W/2 of the column (H = 0.2, W = 0.5)
    stability(t, case, "gate", (0, 1.5), 0.0035,
              1000 * 9.81 * 0.2 ** 2 * 0.5 / 2, 0.2)
    reader_sees(t, case, "gate", ("U", "p"))
    parts = run_cost(case)["parts"]
    t.check("sluiceGate: the run cost has the walls' repulsion of thin"
            " layers (water.wallRepulsion)", "water.wallRepulsion" in parts,
            str(sorted(parts)))
    m = re.search(r"^(met|MISSED): the gate opens.*$", out, re.M)
    t.check("sluiceGate: " + (m.group(0) if m else "validation printed"
                              " whether the gate opens"),
            m is not None and m.group(1) == "met", out[-1500:])


def coupled_restart(t, work):
    """elasticGate at 2.5 mm: a run to 0.06 s in one go, and one stopped at
    0.03 s and restarted from its last write (startFrom latestTime) end at
    the same particles: the solid's last external force (the fluid's) and
    its stress are written and read back"""
    src = os.path.join(project_dir, "tutorials", "ulphPdFoam", "elasticGate")
    cases = []
    for name, end in (("gateOneGo", 0.06), ("gateRestarted", 0.03)):
        case = copy_case(src, os.path.join(work, name))
        with open(os.path.join(case, "system", "resolution"), "w") as f:
            f.write("dx 0.0025;\n")
        set_entry(case, "system/controlDict", "writeInterval", 0.03)
        set_entry(case, "system/controlDict", "endTime", end)
        if not run_steps(t, case, label="coupled restart: %s: " % name)[0]:
            return
        cases.append(case)
    one, two = cases
    set_entry(two, "system/controlDict", "startFrom", "latestTime")
    set_entry(two, "system/controlDict", "endTime", 0.06)
    code, out = run(["ulphPdFoam"], two)
    t.check("coupled restart: the restart succeeds", code == 0, out[-2000:])
    if code != 0:
        return
    diff = 0.0
    for body in ("water", "gate"):
        a = read_positions(one, "0.06", body)
        b = read_positions(two, "0.06", body)
        diff = max([diff] + [max(abs(p - q) for p, q in zip(u, v))
                             for u, v in zip(a, b)])
    t.check("coupled restart ends where the uninterrupted run does (max"
            " difference %.1e m)" % diff, diff < RESTART_TOLERANCE)
    split, whole = run_cost(two), run_cost(one)
    t.check("coupled restart takes the same number of steps (%d in %d runs,"
            " %d in one)" % (split["steps"], split["runs"], whole["steps"]),
            split["runs"] == 2 and split["steps"] == whole["steps"])


if __name__ == "__main__":
    sys.exit(run_parts("ulphPdFsi", elastic_obstacle,
                       elastic_gate, sluice_gate, coupled_restart))
