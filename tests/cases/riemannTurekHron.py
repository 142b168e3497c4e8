#!/usr/bin/python3
"""Case test: the Turek-Hron FSI2 tutorial (tutorials/riemannSphFoam/
turekHronFSI2: Riemann water in a channel with an inflow buffer and an
outflow, a TLSPH flag behind a clamped cylinder, riemannTlsph coupling)
at its default resolution, to 0.5 s (the full run, 15 s, is the
tutorial's Allrun):

- Allrun succeeds, and validate.py writes validation/result.md (it finds
  no periodic response yet, which is no error without --check);
- the water's mass is accounted for at the end, to round-off: the seeded
  mass plus the mass in minus the mass out of postProcessing/
  openBoundaries; the mass in is rho U H times the ramped time's integral
  within one column of particles (inflow (1 - cos(pi t/2))/2 over the
  first 2 s);
- the fluid's force on the structure and the structure's on the fluid are
  equal and opposite at every step to 1e-9 of the largest force
  (postProcessing/coupling);
- no water particle within 0.25 of the water's spacing of a flag or
  cylinder particle, none beyond the outlet, point A still within 1 mm
  of its place (the flag has not started to swing).
The swing itself (15 s: amplitude and frequency against FEATFLOW's, in
the tutorial's validation/result.md; validate.py --check applies the
targets) is the tutorial's Allrun, about 6 minutes on 1 thread, not CI's;
the stability suite runs the flag coarse to 2 s.
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import run_parts, run_tutorial  # noqa: E402
from foamCloud import read_cloud, times  # noqa: E402
from foamMonitor import read_monitor, read_rows  # noqa: E402

TUTORIAL = "tutorials/riemannSphFoam/turekHronFSI2"
END, DX = 0.5, 0.01


def flag(t, work):
    case, code, out = run_tutorial(t, TUTORIAL, work, "short",
                                   ("-end", str(END)))
    if code != 0:
        return
    t.check("validate.py wrote validation/result.md", os.path.exists(
        os.path.join(case, "validation", "result.md")))

    series = times(case)
    t.check_close("ran to %g s" % END, series[-1][0], END, 1e-9)
    first = read_cloud(case, series[0][1], "water")
    last = read_cloud(case, series[-1][1], "water")
    flux = read_monitor(case, "openBoundaries")
    t.check_close("mass at the end = seeded + in + out",
                  sum(last["mass"]), sum(first["mass"])
                  + flux["inlet.mass"][-1] + flux["outlet.mass"][-1], 1e-12)
    # int_0^T (1 - cos(pi t/2))/2 dt for T <= 2; rho U H with U = 1
    ramp = 0.5 * (END - math.sin(math.pi * END / 2) * 2 / math.pi)
    expected = 1000 * 1.0 * 0.41 * ramp
    column = 1000 * DX * 0.41
    t.check("mass in %.2f kg/m vs rho U H int ramp = %.2f within a column"
            " (%.1f)" % (flux["inlet.mass"][-1], expected, column),
            abs(flux["inlet.mass"][-1] - expected) <= column)

    rows = read_rows(os.path.join(case, "postProcessing", "coupling", "0",
                                  "forces.dat"))
    largest = max(max(abs(v) for v in r[1:3]) for r in rows)
    worst = max(abs(r[1] + r[4]) + abs(r[2] + r[5]) for r in rows)
    t.check("force on the flag and on the water equal and opposite at"
            " every step (largest sum %.1e of the largest force %.3g N/m)"
            % (worst / largest, largest), worst <= 1e-9 * largest)

    solid = read_cloud(case, series[-1][1], "flag")["positions"]
    cell = {}
    for p in solid:
        cell.setdefault((int(p[0] // DX), int(p[1] // DX)), []).append(p)
    closest = math.inf
    for p in last["positions"]:
        i, j = int(p[0] // DX), int(p[1] // DX)
        for a in (i - 1, i, i + 1):
            for b in (j - 1, j, j + 1):
                for q in cell.get((a, b), ()):
                    closest = min(closest, math.hypot(p[0] - q[0],
                                                      p[1] - q[1]))
    t.check("no water particle within 0.25 dx of the structure (closest"
            " %.3f dx)" % (closest / DX), closest > 0.25 * DX)
    t.check("no water particle beyond the outlet",
            all(p[0] < 2.5 for p in last["positions"]))
    tip = read_monitor(case, "tipA")
    moved = max(math.hypot(a, b) for a, b in zip(tip["dx"], tip["dy"]))
    t.check("point A within 1 mm of its place to %g s (%.2e m)"
            % (END, moved), moved < 1e-3)


if __name__ == "__main__":
    sys.exit(run_parts("riemannTurekHron", flag))
