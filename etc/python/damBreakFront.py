"""The square-column dam break (L = H = 0.057 m, tank 4H) shared by the
validation scripts of the Riemann and ISPH dam-break tutorials: the surge
front of a run, its errors against the reference and the experiment at
the experiment's times, and the stability checks.

    from damBreakFront import front, front_errors, rms, series, stability
    ts, xs = front(case)                  # T = t sqrt(g/H), x_front/H
    rows = front_errors(ts, xs, folder)   # [(T, experiment, reference, run)]
    checks, total = stability(case, dx, 0.025)

folder holds interFoamFrontNoSurfaceTension.dat (the reference: the
converged Navier-Stokes front without surface tension,
benchmarks/damBreakVof) and martinMoyce1952.dat (the experiment, reported
beside it); the rows stop before the reference front reaches the far
wall (x/H = 4).
"""
import math
import os

from foamCloud import read_positions, times
from foamDict import dictionary_entry
from foamMonitor import interp, read_rows
from fsiChecks import energy_total, largest_rise

H, G, RHO0 = 0.057, 9.81, 1000.0
ENERGY_SCALE = RHO0 * G * H ** 3 / 2


def series(path):
    """(x, y) rows of a reference file (read_rows: '#' comments)"""
    return [(r[0], r[1]) for r in read_rows(path)]


def front(case):
    """The water's largest x over H at every written time T = t sqrt(g/H)"""
    ts, xs = [], []
    for t, name in times(case):
        x = read_positions(case, name, "water")
        ts.append(t * math.sqrt(G / H))
        xs.append(max(p[0] for p in x) / H)
    return ts, xs


def front_errors(ts, xs, folder):
    """[(T, experiment, reference, simulated)] at the experiment's times
    before the reference front reaches the far wall"""
    ref = series(os.path.join(folder, "interFoamFrontNoSurfaceTension.dat"))
    exp = series(os.path.join(folder, "martinMoyce1952.dat"))
    rT, rX = [a for a, _ in ref], [b for _, b in ref]
    rows = []
    for T, xe in exp:
        if T > ts[-1]:
            continue
        xr = interp(T, rT, rX)
        if xr >= 4 - 1e-3:
            continue
        rows.append((T, xe, xr, interp(T, ts, xs)))
    return rows


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values))


def stability(case, dx, guard):
    """[(what, met)]: ran to endTime, no particle lost, no particle deeper
    than 0.5 dx in the tank's walls, and the total energy never above its
    lowest earlier value by more than guard rho0 g H^3/2; and the energy
    series"""
    checks = []
    written = times(case)
    t1 = written[-1][0]
    end = float(dictionary_entry(case, "endTime", "system/controlDict"))
    checks.append(("ran to endTime %g s (last time %g s)" % (end, t1),
                   abs(t1 - end) < 1e-9))
    n0 = len(read_positions(case, written[0][1], "water"))
    lost, depth = None, 0.0
    for value, name in written:
        x = read_positions(case, name, "water")
        if len(x) != n0:
            lost = value
            break
        depth = max(depth, max(max(-p[0], p[0] - 4 * H, -p[1]) for p in x))
    checks.append(("the water keeps its %d particles at all %d written"
                   " times%s" % (n0, len(written), "" if lost is None
                                 else ": lost at %g s" % lost), lost is None))
    checks.append(("deepest wall penetration at any written time %.2f dx"
                   " < 0.5 dx" % (depth / dx), depth < 0.5 * dx))
    total = energy_total(case)
    rise = largest_rise(total)
    checks.append(("total energy never rises above its lowest earlier value"
                   " by more than %g %% of rho0 g H^3/2 = %.3f J/m (largest"
                   " rise %.3f %%)" % (100 * guard, ENERGY_SCALE,
                                       100 * rise / ENERGY_SCALE),
                   rise <= guard * ENERGY_SCALE))
    return checks, total
