"""The stability checks of a run that has no measurement to compare with
(BENCHMARKS: 'runs to the end, stable, no particle lost'), shared by the
validation scripts of the FSI tutorials, the dam break and the case tests,
and how they are reported.

    from fsiChecks import stability_checks, print_checks, check_rows
    checks = stability_checks(case, "gate", (0, 1.5), dx, scale)
    print_checks(checks)                # 'met: ...' / 'MISSED: ...'
    lines += check_rows(checks)         # '| ... | met |'
"""
import math

from foamCloud import read_cloud, read_field, read_positions, times
from foamDict import dictionary_entry
from foamMonitor import monitor_rows, monitor_runs


def end_time(case):
    """endTime of system/controlDict"""
    return float(dictionary_entry(case, "endTime", "system/controlDict"))


def verdict(good):
    """How a check is reported: 'met' or 'MISSED'"""
    return "met" if good else "MISSED"


def print_checks(checks):
    """Each check of [(what, met)] as a line 'met: what' or 'MISSED: what'"""
    for what, good in checks:
        print("%s: %s" % (verdict(good), what))


def check_rows(checks):
    """Each check of [(what, met)] as a row '| what | met |' of a
    markdown table"""
    return ["| %s | %s |" % (what, verdict(good)) for what, good in checks]


def momentum_exchange(case, floor=None):
    """Largest |F_fs + F_sf|/|F_fs| over the coupling's steps
    (postProcessing/coupling/<start>/forces.dat, a run and its restarts):
    the fluid's force on the (first) solid and the solid's force on the
    fluid, summed from the fluid's side, in the plane. With floor, only the
    steps whose force on the solid is larger than floor [N/m]"""
    worst = 0.0
    for r in monitor_rows(case, "coupling", "forces.dat")[1]:
        size = math.hypot(r[1], r[2])
        if floor is None or size > floor:
            worst = max(worst, math.hypot(r[1] + r[4], r[2] + r[5])
                        / max(size, 1e-30))
    return worst


def solid_work_balance(case, solid):
    """Largest rise of a solid's energy (kinetic + strain + potential, the
    energy monitor) beyond the work the fluid's force did on it (forces.dat's
    <solid>:work), from each run's start (a restart's work starts at zero):
    above zero the solid's own integration, not the coupling, made energy.
    Returns (rise [J/m in 2D], largest |work|), or None without both."""
    try:
        energy = monitor_runs(case, "energy")
        forces = monitor_runs(case, "coupling", "forces.dat")
    except RuntimeError:
        return None
    worst, scale = -float("inf"), 0.0
    for (ec, er), (fc, fr) in zip(energy, forces):
        key = solid + ":work"
        if key not in fc or solid + ":kinetic" not in ec:
            return None
        kw = fc.index(key)
        ke = [ec.index(solid + ":" + c)
              for c in ("kinetic", "strain", "potential")]
        work = {round(r[0], 12): r[kw] for r in fr}
        start = None
        for r in er:
            w = work.get(round(r[0], 12))
            if w is None:
                continue
            e = sum(r[k] for k in ke)
            if start is None:
                start = e - w
            worst = max(worst, e - w - start)
            scale = max(scale, abs(w))
    if worst == -float("inf"):
        return None
    return worst, scale


def energy_total(case):
    """The energy monitor's total over a run and its restarts. A restart's
    monitor measures potential energy from the restart's own positions (it
    starts at zero), so its totals are shifted to continue the earlier
    run's at the restart's first time: joined unshifted (read_monitor), a
    restart would raise the total by the potential energy released before
    it, a false growth."""
    rows = []
    for columns, values in monitor_runs(case, "energy"):
        k = columns.index("total")
        own = [(v[0], v[k]) for v in values]
        if not own:
            continue
        offset = 0.0
        if rows:
            before = [e for t, e in rows if t <= own[0][0] + 1e-12]
            offset = (before[-1] if before else rows[0][1]) - own[0][1]
        while rows and rows[-1][0] >= own[0][0]:
            rows.pop()
        rows.extend((t, e + offset) for t, e in own)
    return [e for t, e in rows]


def largest_rise(values):
    """The largest rise of a series above its lowest earlier value (0 when
    it never rises): how much energy a run gained at most"""
    low, rise = math.inf, 0.0
    for e in values:
        low = min(low, e)
        rise = max(rise, e - low)
    return rise


def closest_distance(points, others, radius):
    """Smallest distance from any of points to any of others, searched
    through a bucket grid of the others (cell size radius); inf when none
    is closer than radius"""
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
    return math.sqrt(best)


def velocity_noise(case, body, dx):
    """Largest particle-scale velocity noise of a body over the written
    times: the deviation of a particle's velocity from the mean velocity of
    its neighbours within 1.6 dx (its nearest lattice neighbours). A
    smoothly deforming body has a deviation of order (velocity gradient) x
    dx; an odd-even (zero-energy) mode one of its own amplitude."""
    r = 1.6 * dx
    worst = 0.0
    for _, name in times(case):
        cloud = read_cloud(case, name, body)
        if "U" not in cloud:
            continue
        x, U = cloud["positions"], cloud["U"]
        grid = {}
        for i, p in enumerate(x):
            grid.setdefault((int(p[0] // r), int(p[1] // r)), []).append(i)
        for i, p in enumerate(x):
            ci, cj = int(p[0] // r), int(p[1] // r)
            near = [j for di in (-1, 0, 1) for dj in (-1, 0, 1)
                    for j in grid.get((ci + di, cj + dj), ())
                    if j != i and (x[j][0] - p[0]) ** 2
                    + (x[j][1] - p[1]) ** 2 < r * r]
            if not near:
                continue
            mean = [sum(U[j][d] for j in near) / len(near) for d in (0, 1)]
            worst = max(worst, math.hypot(U[i][0] - mean[0],
                                          U[i][1] - mean[1]))
    return worst


def written_times_checks(case, series, fluid, solid, dx, visit=None):
    """[(what, met)] over the written times of series (times(case)): the
    fluid and the solid keep their particles; no fluid particle closer
    than dx/4 to a solid particle (inside the solid: a tutorial's own,
    stricter check; the stability suite, tests/stability, bounds the
    depth behind the solid's face by 0.5 dx, the criterion every method
    is held to there). visit(value, name,
    fluid_positions), when given, is called at each time read (a scene's
    own checks on the same pass)"""
    n0 = {b: len(read_positions(case, series[0][1], b))
          for b in (fluid, solid)}
    lost, closest = None, math.inf
    for value, name in series:
        fl = read_positions(case, name, fluid)
        so = read_positions(case, name, solid)
        if len(fl) != n0[fluid] or len(so) != n0[solid]:
            lost = value
            break
        closest = min(closest, closest_distance(fl, so, dx))
        if visit is not None:
            visit(value, name, fl)
    return [("%s and %s keep their %d and %d particles (%d written times)%s"
             % (fluid, solid, n0[fluid], n0[solid], len(series),
                "" if lost is None else ": lost at %g s" % lost),
             lost is None),
            ("no %s particle inside the %s (closest %.2f dx > 0.25 dx)"
             % (fluid, solid, closest / dx), closest > 0.25 * dx)]


def stability_checks(case, solid, tank, dx, energy_scale, fluid="water",
                     velocity_scale=None, walls_top=None, solid_dx=None):
    """[(what, met)] for a run of the fluid 'fluid' on the solid 'solid':
    - the run reached endTime (the solver stops on a NaN or an escaped
      particle, naming both);
    - the fluid and the solid keep their particles at every written time;
    - every fluid particle is inside the tank at the last time: walls at
      x = tank[0], x = tank[1] and y = 0 penetrated by less than dx/2 (the
      dam break's criterion: the first ghost layer lies at dx/2). With
      walls_top, the height where the side walls of an open tank end, only
      the particles below it: a splash may fly over the walls and land
      beyond them, which no wall leaked; those above are counted, and so
      are those below it beside the tank that were above it at a written
      time (they flew over the walls);
    - no fluid particle closer than dx/4 to a solid particle at any written
      time (a fluid particle inside the solid);
    - the total energy (energy monitor, over a run and its restarts:
      energy_total) never rises above its start by more than 1e-3 of
      energy_scale (the fluid's initial potential energy, J/m in 2D);
    - with velocity_scale (e.g. sqrt(g H) of the fluid): the solid's
      particle-scale velocity noise (velocity_noise) below 0.1 of it at
      every written time (smooth deformation at impact: up to 0.045 of it
      in sluiceGate). The per-particle forces of a coupling excite the
      solid's odd-even modes; undamped they grow (2 m/s in the rubber gate
      of elasticGate by 0.3 s) and throw fluid particles out.
    dx is the fluid's spacing, solid_dx the solid's (default dx) when the
    two differ (multi-resolution)."""
    series = times(case)
    t1 = series[-1][0]
    checks = [("ran to endTime %g s (last time %g s)" % (end_time(case), t1),
               abs(t1 - end_time(case)) < 1e-9)]

    top = math.inf if walls_top is None else walls_top
    # Particles that flew over the walls: above their top at a written
    # time (on the pass of written_times_checks), beside the tank below it
    # at the last
    flew = set()

    def over_the_top(value, name, positions):
        above = [k for k, p in enumerate(positions) if p[1] >= top]
        if above:
            ids = read_field(case, name, fluid, "id")
            flew.update(int(ids[k]) for k in above)

    checks += written_times_checks(case, series, fluid, solid, dx,
                                   visit=over_the_top)
    fl = read_positions(case, series[-1][1], fluid)
    ids = [int(i) for i in read_field(case, series[-1][1], fluid, "id")]
    above = [p for p in fl if p[1] >= top]
    landed = [p for i, p in zip(ids, fl) if p[1] < top
              and i in flew and not tank[0] <= p[0] <= tank[1]]
    depth = max((max(tank[0] - p[0], p[0] - tank[1], -p[1])
                 for i, p in zip(ids, fl)
                 if p[1] < top and not (i in flew
                                        and not tank[0] <= p[0] <= tank[1])),
                default=0.0)
    if walls_top is None:
        what = ("every %s particle inside the tank (deepest wall penetration"
                " %.2f dx < 0.5 dx)" % (fluid, depth / dx))
    else:
        what = ("every %s particle below the walls' top (%g m) inside the"
                " tank (deepest wall penetration %.2f dx < 0.5 dx); %d above"
                " it (splash), %d of those beyond the side walls; %d flew"
                " over the walls and fell beside the tank"
                % (fluid, walls_top, depth / dx, len(above),
                   sum(1 for p in above if not tank[0] <= p[0] <= tank[1]),
                   len(landed)))
    checks.append((what, depth < 0.5 * dx))

    total = energy_total(case)
    rise = max(total) - total[0]
    checks.append(("total energy not growing (largest rise %.3g J/m <= %.3g)"
                   % (rise, 1e-3 * energy_scale), rise <= 1e-3 * energy_scale))
    if velocity_scale is not None:
        noise = velocity_noise(case, solid, solid_dx or dx)
        checks.append(("the %s's particle-scale velocity noise %.3g m/s <"
                       " 0.1 x %.3g m/s" % (solid, noise, velocity_scale),
                       noise < 0.1 * velocity_scale))
    return checks


def plate_force_checks(t, case, out, coupling, min_steps, expected,
                       rtol=0.03):
    """The checks of a column of water resting on a coupled plate (t a
    CaseTest): the log names the coupling ('coupling <coupling>: fluid
    water, solids (plate)'), forces.dat has more than min_steps rows, the
    mean vertical force on the plate from 0.1 s to the end is expected
    within rtol, and per step the fluid's force on the plate and the
    plate's on the fluid cancel to 1e-9. Returns forces.dat's rows"""
    t.check("log names the coupling",
            "coupling %s: fluid water, solids (plate)" % coupling in out)
    forces = monitor_rows(case, "coupling", "forces.dat")[1]
    t.check("forces written every step", len(forces) > min_steps)
    late = [r for r in forces if r[0] >= 0.1]
    mean = sum(r[2] for r in late) / len(late)
    t.check_close("mean vertical force on the plate (0.1 s to the end) "
                  "%.2f N/m vs -rho g H W = %.2f N/m" % (mean, expected),
                  mean, expected, rtol)
    worst = momentum_exchange(case)
    t.check("fluid-on-solid + solid-on-fluid = 0 (worst %.1e of the"
            " force)" % worst, worst < 1e-9)
    return forces
