"""Dam break on an elastic plate (Liao, Hu and Sueyoshi 2015), shared by
the liaoPlate tutorials of every solver (the same scene).

    from liaoPlate import validate
    sys.exit(validate(here, "riemannSphFoam", 0.001, fluid_ratio=2))

No measured time series of the plate is public (BENCHMARKS.md): the case
is a violent one, checked for stability, and its tip history is compared
between the solvers. Reads the tip's displacement written by the
pointDisplacement monitor 'tip' (the experiment's marker, 0.0875 m above
the floor on the plate's centre line; a run and its restarts) and reports
the time of impact (tip x past 1 mm), the first peak of x and its time,
the largest x, and the mean and range of x over the last 0.2 s.

Writes validation/tip.dat (or tip-dx<spacing>.dat for a spacing other
than the tutorial's), the tip history every 2 ms, which the other
solvers' validations read to plot it beside theirs; validation/result.md
(result-dx<spacing>.md) with the figures, particles per body, steps,
solid sub-steps and wall time from the run cost (postProcessing/runCost);
and tip[-dx<spacing>].png: this run, this solver's other spacings and the
other solvers' tip.dat.

Applies fsiChecks' stability checks (run to the end, no particle lost,
water in the tank below its walls' top and not in the plate, energy not
growing, the plate's particle-scale velocity noise below 0.1 sqrt(g H)),
the coupling's momentum balance (the water's force on the plate and
the plate's on the water cancel to 1e-9 of it at every step), that the
plate's energy never rises above the work the water's force did on it
(by more than 1e-3 of the column's potential energy: the solid's own
integration makes none; postProcessing/coupling's work column), and that
the plate, which folds onto the floor, stays out of it: no plate particle
outside the notch reaches more than half its spacing into the floor (its
own extent half a spacing, so its centre no lower than 0).

With --check, exits 1 when a check is missed.

Usage of a tutorial's validate.py: validate.py <case> [--check]
"""
import math
import os

from foamMonitor import (arguments, case_spacing, pyplot, read_monitor,
                         result_suffix, run_cost)
from foamCloud import read_positions, times
from fsiChecks import (check_rows, momentum_exchange, print_checks,
                       solid_work_balance, stability_checks)
from solverComparison import (cost_rows, plot_comparison, resample,
                              write_history)

H = 0.4             # water column height [m]
W = 0.2             # water column width [m]
TANK = (0.0, 0.8)   # tank's side walls [m]
WALLS_TOP = 0.6     # the walls' top: the tank is open above [m]
NOTCH = (0.596, 0.6)  # the plate's foot, below the floor [m]
IMPACT = 0.001      # tip x that marks the impact [m]
SAMPLE = 0.002      # interval of tip.dat [s]
ENERGY_TOLERANCE = 1e-3  # of the column's potential energy (fsiChecks')


def figures(ts, xs):
    """Impact time, first peak (value, time), largest x (value, time) and
    the mean and range of x over the last 0.2 s"""
    impact = next((t for t, x in zip(ts, xs) if x > IMPACT), math.nan)
    first = (math.nan, math.nan)
    for k in range(1, len(xs) - 1):
        if (ts[k] > impact and xs[k] > IMPACT
                and xs[k - 1] < xs[k] >= xs[k + 1]):
            first = (xs[k], ts[k])
            break
    k = max(range(len(xs)), key=lambda i: xs[i])
    tail = [x for t, x in zip(ts, xs) if t >= ts[-1] - 0.2]
    return {"impact": impact, "first": first, "largest": (xs[k], ts[k]),
            "mean": sum(tail) / len(tail), "range": (min(tail), max(tail))}


def floor_overlap(case, dx):
    """The deepest overlap of a plate particle (its extent dx/2) with the
    floor outside the notch over the written times: max(dx/2 - y) [m]"""
    worst = -math.inf
    for _, name in times(case):
        for x, y in ((p[0], p[1]) for p in
                     read_positions(case, name, "plate")):
            if not NOTCH[0] <= x <= NOTCH[1]:
                worst = max(worst, 0.5 * dx - y)
    return worst


def validate(here, solver, default_dx, fluid_ratio=1, doc=None):
    """Validate the case named on the command line: 'here' is the
    tutorial's validation folder, 'solver' names the curve, default_dx is
    the plate's spacing of the tutorial's default run and fluid_ratio the
    water's spacing over the plate's. Returns the exit code (1 with
    --check when a check is missed)."""
    case, check = arguments(doc or __doc__)
    sim = read_monitor(case, "tip")    # a run and its restarts
    ts, xs, ys = sim["time"], sim["dx"], sim["dy"]
    dx = case_spacing(case, default_dx)
    suffix = result_suffix(dx, default_dx)
    fig = figures(ts, xs)
    cost = run_cost(case)

    own = os.path.join(here, "tip%s.dat" % suffix)
    write_history(own, ["liaoPlate tip (0.598, 0.0875) m, %s, plate spacing"
                        " %g m, water %g m" % (solver, dx, fluid_ratio * dx),
                        "t [s]  x [m]  y [m]"],
                  resample(SAMPLE, ts, xs, ys))

    lines = [
        "impact (tip x > %g m) at %.3f s" % (IMPACT, fig["impact"]),
        "first peak of tip x %.4f m at %.3f s" % fig["first"],
        "largest tip x %.4f m at %.3f s" % fig["largest"],
        "tip x over the last 0.2 s: mean %.4f m, %.4f .. %.4f m"
        % ((fig["mean"],) + fig["range"]),
    ]
    for line in lines:
        print(line)

    # potential energy of the column: rho g H^2 W / 2 [J/m]
    potential = 1000 * 9.81 * H ** 2 * W / 2
    checks = stability_checks(case, "plate", TANK, fluid_ratio * dx,
                              potential,
                              velocity_scale=math.sqrt(9.81 * H),
                              walls_top=WALLS_TOP, solid_dx=dx)
    overlap = floor_overlap(case, dx)
    checks.append(("the plate out of the floor (deepest overlap %.2f dx"
                   " <= 0.5 dx)" % (overlap / dx), overlap <= 0.5 * dx))
    work = solid_work_balance(case, "plate")
    if work is not None:
        checks.append(("the plate's energy never above the water's work on"
                       " it (largest excess %.3g J/m <= %.3g)"
                       % (work[0], ENERGY_TOLERANCE * potential),
                       work[0] <= ENERGY_TOLERANCE * potential))
    balance = momentum_exchange(case, floor=1e-6)
    checks.append(("the water's force on the plate and the plate's on the"
                   " water cancel (largest |F_fs + F_sf|/|F_fs| %.1e"
                   " <= 1e-9)" % balance, balance <= 1e-9))
    print_checks(checks)

    with open(os.path.join(here, "result%s.md" % suffix), "w") as f:
        f.write("# liaoPlate (%s): dam break on an elastic plate\n\n"
                % solver)
        f.write("Plate spacing %g m (%d particles through its 0.004 m),"
                " water %g m, run to %.3f s. No measured history is public:"
                " the figures are for comparing solvers and resolutions,"
                " the checks are the targets.\n\n"
                % (dx, round(0.004 / dx), fluid_ratio * dx, ts[-1]))
        f.write("| quantity | value |\n|---|---|\n")
        f.write("| impact (tip x > %g m) | %.3f s |\n"
                % (IMPACT, fig["impact"]))
        f.write("| first peak of tip x | %.4f m at %.3f s |\n" % fig["first"])
        f.write("| largest tip x | %.4f m at %.3f s |\n" % fig["largest"])
        f.write("| tip x over the last 0.2 s | mean %.4f m, %.4f .. %.4f m"
                " |\n" % ((fig["mean"],) + fig["range"]))
        for what, value in cost_rows(cost, "water"):
            f.write("| %s | %s |\n" % (what, value))
        f.write("\n| check | |\n|---|---|\n")
        f.write("".join(row + "\n" for row in check_rows(checks)))

    plt = pyplot()
    if plt is not None:
        figure, ax = plt.subplots(figsize=(8, 4.5))
        ax.plot(ts, xs, "-", lw=1.8, label="%s, dx = %g m (this run)"
                % (solver, dx))
        plot_comparison(ax, here, "liaoPlate", solver, own, 1)
        ax.set_xlabel("t [s]")
        ax.set_ylabel("tip x displacement [m]")
        ax.set_title("Liao et al. 2015 plate, marker at 0.0875 m")
        ax.grid(True)
        ax.legend(fontsize=8)
        figure.tight_layout()
        figure.savefig(os.path.join(here, "tip%s.png" % suffix), dpi=100)

    met = all(good for _, good in checks)
    return 1 if check and not met else 0
