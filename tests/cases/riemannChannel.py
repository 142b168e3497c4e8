#!/usr/bin/python3
"""Case test: open boundaries (openBoundary: inflow and outflow) of the
Riemann WCSPH fluid (riemannSphFoam).

A plug flow through a 2D free-slip channel 0.1 m high (dx = 5 mm,
Wendland C2 h = 1.3 dx, c0 = 10 m/s, WKGC): in through an inflow buffer
x in [-0.02, 0) whose velocity 0.5 m/s is ramped in over 0.5 s
(halfCosineRamp), out through the plane x = 0.4 with a pressure buffer
(p = 0) over [0.38, 0.4); 1.5 s, so that the channel's water is replaced
about twice. Checks:
- at 1.5 s, the water of x in (0.05, 0.35) moves at the inflow speed:
  mean u within 0.5 % (0.04 % measured), its spread and the RMS of v
  below 1 % of it, the mean pressure below 1 % of rho U^2;
- mass is accounted for at every written time, to round-off: the
  cloud's mass is the seeded mass plus the mass in minus the mass out of
  postProcessing/openBoundaries, and the particle count likewise; ids
  stay unique; no particle lies beyond the outlet; the inflow buffer
  (field inletBuffer) holds its 80 particles and no fluid particle lies
  upstream of the inlet;
- the mass in is rho U H times the ramped time, 62.5 kg/m, within one
  column of particles (0.5 kg/m);
- the log names both open boundaries;
- the same with the velocity ramped in the expression, of the time t,
  instead of by a ramp: the same plug flow at 1.5 s;
- bad input, each an error naming the keyword: an open boundary of a
  body that is not a fluid, an inflow without buffer, an outflow pressure
  without buffer, an unknown type (the error lists inflow and outflow).
Exact restarts with open boundaries are checked in restartExact.py.
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import (copy_case, put_entry, refused_entries,  # noqa: E402
                      run_parts, run_steps)
from foamCloud import read_cloud, times  # noqa: E402
from foamMonitor import monitor_rows  # noqa: E402

U0, H, RHO, OUTLET = 0.5, 0.1, 1000.0, 0.4
PP = "constant/particleProperties"


def set_pp(case, key, value):
    put_entry(case, PP, key, value)


def plug_flow(t, work, name="plug", entries=(), mass_in=True):
    case = copy_case(os.path.join(here, "riemannChannel"),
                     os.path.join(work, name))
    for key, value in entries:
        set_pp(case, key, value)
    ok, out = run_steps(t, case, ("blockMesh", "seedParticles",
                                  "riemannSphFoam"), name + ": ")
    if not ok:
        return
    for name in ("inlet: inflow of water", "outlet: outflow of water"):
        t.check("log names the open boundary " + name, name in out)

    rows = {round(r[0], 9): r
            for r in monitor_rows(case, "openBoundaries")[1]}
    series = times(case)
    c0 = read_cloud(case, series[0][1], "water")
    n0, m0 = len(c0["mass"]), sum(c0["mass"])
    for time, folder in series:
        c = read_cloud(case, folder, "water")
        row = rows.get(round(time, 9))
        if row is None:
            t.check("openBoundaries has a row at %g s" % time, False)
            continue
        # columns: time, water.particles, inlet particles, mass, outlet ...
        n, m = len(c["mass"]), sum(c["mass"])
        t.check_equal("%g s: particles = seeded + in + out" % time, n,
                      n0 + int(row[2]) + int(row[4]))
        t.check_equal("%g s: monitor's particle count" % time, n,
                      int(row[1]))
        t.check_close("%g s: mass = seeded + in + out" % time, m,
                      m0 + row[3] + row[5], 1e-12)
        t.check_equal("%g s: ids unique" % time, len(set(c["id"])), n)
        t.check("%g s: no particle beyond the outlet" % time,
                all(x[0] < OUTLET for x in c["positions"]))
        if time > 0:
            flags = c.get("inletBuffer", [])
            t.check_equal("%g s: the inflow buffer holds its 4 columns of"
                          " 20 particles" % time,
                          sum(1 for f in flags if f > 0.5), 80)
            t.check("%g s: no fluid particle upstream of the inlet" % time,
                    all(f > 0.5 or x[0] >= 0 for f, x in
                        zip(flags, c["positions"])))

    end = series[-1]
    t.check_close("ran to 1.5 s", end[0], 1.5, 1e-9)
    c = read_cloud(case, end[1], "water")
    inner = [k for k, x in enumerate(c["positions"])
             if 0.05 < x[0] < 0.35]
    u = [c["U"][k][0] for k in inner]
    v = [c["U"][k][1] for k in inner]
    p = [c["p"][k] for k in inner]
    mean = sum(u) / len(u)
    spread = (sum((a - mean) ** 2 for a in u) / len(u)) ** 0.5
    rms_v = (sum(a * a for a in v) / len(v)) ** 0.5
    t.check_close("1.5 s: mean u of the channel's water vs inflow", mean,
                  U0, 5e-3)
    t.check("1.5 s: spread of u %.2e < 1e-2 U" % (spread / U0),
            spread < 1e-2 * U0)
    t.check("1.5 s: RMS of v %.2e < 1e-2 U" % (rms_v / U0),
            rms_v < 1e-2 * U0)
    p_mean = sum(p) / len(p)
    t.check("1.5 s: mean pressure %.2e < 1e-2 rho U^2" % (
        abs(p_mean) / (RHO * U0 ** 2)), abs(p_mean) < 1e-2 * RHO * U0 ** 2)
    if not mass_in:
        return
    row = rows[round(end[0], 9)]
    expected = RHO * U0 * H * (1.5 - 0.25)
    t.check("mass in %.3f kg/m vs rho U H (t - 0.25 s) = %.3f within a"
            " column (0.5)" % (row[3], expected),
            abs(row[3] - expected) <= 0.5)


def time_expression(t, work):
    """The ramp written in the velocity's expression of t instead"""
    plug_flow(t, work, "timeExpression", (
        ("openBoundaries/inlet/ramp", "constant 1"),
        ("openBoundaries/inlet/velocity/expression",
         '"vector(0.5*min(t/0.5, 1), 0, 0)"'),
    ), mass_in=False)


def bad_input(t, work):
    refused_entries(t, os.path.join(here, "riemannChannel"), work,
                    "riemannSphFoam", (
        ("notFluid", "openBoundaries/inlet/body", "channel",
         ("particleProperties", "inlet", "channel", "not a fluid")),
        ("noBuffer", "openBoundaries/inlet/bufferLength", 0,
         ("particleProperties", "bufferLength",
          "expected a buffer length > 0")),
        ("pressureNoBuffer", "openBoundaries/outlet/bufferLength", 0,
         ("particleProperties", "pressure", "bufferLength")),
        ("unknownType", "openBoundaries/outlet/type", "exit",
         ("particleProperties", "exit", "inflow", "outflow")),
    ))


if __name__ == "__main__":
    sys.exit(run_parts("riemannChannel", plug_flow, time_expression,
                       bad_input))
