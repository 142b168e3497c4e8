"""Elastic gate (Antoci et al. 2007): free-end displacement vs experiment,
shared by the elasticGate tutorials of every solver (the same scene).

    from elasticGate import validate
    sys.exit(validate(here, "ulphPdFoam", 0.00125))

Reads the free end's displacement written by the pointDisplacement monitor
'freeEnd' (postProcessing/freeEnd/<start>/freeEnd.dat of a run and its
restarts), interpolates it linearly
to the experiment's times (validation/antoci2007_freeEnd.dat) and prints the
RMS error of x(t) and y(t) over the experiment's points inside the run.
For scale, the RMS of the published numerical curves against the same
points (computed from the digitised curves of Ng et al. 2020 listed in
README.md): x 8.3 mm (Khayyer 2018 ISPH-SPH) to 10.8 mm (Ng 2020 SPH-VCPM),
y 4.6 mm to 5.7 mm; the target (BENCHMARKS) is an RMS of x below those.

Writes validation/result.md (or result-dx<spacing>.md for a spacing other
than the tutorial's 1.25 mm) with the errors, peaks, particles, steps,
solid sub-steps and wall time from the run cost
(postProcessing/runCost), and freeEnd[-dx<spacing>].png.

Also applies fsiChecks' stability checks (run to the end, no particle
lost, water in the tank and not in the gate, energy not growing, the gate's
particle-scale velocity noise below 0.1 sqrt(g H)).

With --check, exits 1 when the run stopped before 0.36 s, its x RMS is
not below the best published curve's, or a stability check is missed.

Usage of a tutorial's validate.py: validate.py <case> [--check]
"""
import math
import os

from foamMonitor import (arguments, case_spacing, interp, pyplot,
                         read_monitor, read_rows, result_suffix, run_cost,
                         wall_time)
from fsiChecks import check_rows, print_checks, stability_checks

PUBLISHED_X = 0.0083    # best published RMS of x [m] (Khayyer 2018)


def rms_errors(case, here):
    """{"x": (RMS, points), "y": (RMS, points)}: the free end's x(t) and
    y(t) of the case (monitor freeEnd) interpolated linearly to the
    experiment's times inside the run (here: the folder of
    antoci2007_freeEnd.dat); RMS nan without a point"""
    sim = read_monitor(case, "freeEnd")
    ts = sim["time"]
    ref = read_rows(os.path.join(here, "antoci2007_freeEnd.dat"))
    errors = {}
    for q, series in (("x", sim["dx"]), ("y", sim["dy"])):
        pts = [(t, v) for k, t, v in ref if k == q and 0 < t <= ts[-1]]
        sq = [(interp(t, ts, series) - v) ** 2 for t, v in pts]
        errors[q] = (math.sqrt(sum(sq) / len(sq)) if sq else float("nan"),
                     len(sq))
    return errors


def material_suffix(case):
    """'-<name>' when the case's gate has another material than the
    tutorial's own (constant/material, whose first line is '// material
    <name>', written by Allrun -material), else ''"""
    path = os.path.join(case, "constant", "material")
    if not os.path.isfile(path):
        return ""
    with open(path) as f:
        words = f.readline().split()
    return "-" + words[2] if words[:2] == ["//", "material"] else "-material"


def validate(here, solver, default_dx, fluid_ratio=1, doc=None):
    """Validate the case named on the command line: 'here' is the
    tutorial's validation folder (the experiment's file, the results),
    'solver' names the curve, default_dx is the gate's spacing of the
    tutorial's default run and fluid_ratio the water's spacing over the
    gate's. Returns the exit code (1 with --check when the target or a
    stability check is missed)."""
    case, check = arguments(doc or __doc__)
    sim = read_monitor(case, "freeEnd")    # a run and its restarts
    ts, dx_sim, dy_sim = sim["time"], sim["dx"], sim["dy"]
    ref = read_rows(os.path.join(here, "antoci2007_freeEnd.dat"))
    errors = rms_errors(case, here)

    cost = run_cost(case)
    # the most solid sub-steps per fluid step the coupling took
    sub = cost["subSteps"]["coupling"]["most"]
    dx = case_spacing(case, default_dx)
    peak_x = max(dx_sim)
    peak_y = max(dy_sim)
    t_peak = ts[dx_sim.index(peak_x)]
    lines = [
        "RMS of free-end x(t) vs Antoci 2007: %.4f m over %d points"
        % errors["x"],
        "RMS of free-end y(t) vs Antoci 2007: %.4f m over %d points"
        % errors["y"],
        "peak x %.4f m at %.3f s (experiment 0.0464 m at 0.16 s),"
        " peak y %.4f m (experiment 0.0171 m)" % (peak_x, t_peak, peak_y),
    ]
    complete = ts[-1] >= 0.36
    if complete:
        lines.append("x RMS %s the best published numerical curve's (%.4f m)"
                     % ("below" if errors["x"][0] < PUBLISHED_X else "above",
                        PUBLISHED_X))
    if not complete:
        lines.insert(0, "INCOMPLETE: the run stopped at %.3f s, before the"
                     " experiment's last point (0.36 s); errors over the"
                     " points up to there only" % ts[-1])
    for line in lines:
        print(line)
    # rho g H^2 W/2 of the water (H = 0.14, W = 0.1)
    checks = stability_checks(case, "gate", (0, 0.5), fluid_ratio * dx,
                              1000 * 9.81 * 0.14 ** 2 * 0.1 / 2,
                              velocity_scale=math.sqrt(9.81 * 0.14),
                              solid_dx=dx)
    print_checks(checks)

    suffix = result_suffix(dx, default_dx) + material_suffix(case)
    with open(os.path.join(here, "result%s.md" % suffix), "w") as f:
        f.write("# elasticGate (%s): free-end displacement vs Antoci et"
                " al. 2007\n\n" % solver)
        f.write("Spacing %g m (gate %d particles thick)%s, run to %.3f s.\n\n"
                % (dx, round(0.005 / dx), "" if fluid_ratio == 1 else
                   ", water %g m" % (fluid_ratio * dx), ts[-1]))
        if material_suffix(case):
            with open(os.path.join(case, "constant", "material")) as m:
                f.write("Gate material (Allrun -material): %s\n\n"
                        % " ".join(m.read().split()))
        if not complete:
            f.write("**INCOMPLETE**: %s.\n\n" % lines[0].split(": ", 1)[1])
        f.write("| quantity | value |\n|---|---|\n")
        f.write("| RMS error x(t) | %.4f m (%d points) |\n" % errors["x"])
        f.write("| RMS error y(t) | %.4f m (%d points) |\n" % errors["y"])
        f.write("| peak x | %.4f m at %.3f s (experiment 0.0464 m at 0.16 s)"
                " |\n" % (peak_x, t_peak))
        f.write("| peak y | %.4f m (experiment 0.0171 m) |\n" % peak_y)
        f.write("| best published RMS x (Khayyer 2018) | %.4f m |\n"
                % PUBLISHED_X)
        f.write("| particles | %d |\n| fluid steps | %d |\n"
                % (cost["particles"], cost["steps"]))
        f.write("| solid sub-steps per fluid step (max) | %d |\n" % sub)
        f.write("| wall time | %s%s |\n"
                % (wall_time(cost), "" if cost["runs"] == 1 else
                   " in %d runs (restarts)" % cost["runs"]))
        f.write("\n| check (fsiChecks: stable) | |\n|---|---|\n")
        f.write("".join(row + "\n" for row in check_rows(checks)))

    plt = pyplot()
    if plt is None:
        return 0
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, q, series in ((axes[0], "x", dx_sim), (axes[1], "y", dy_sim)):
        rt = [t for k, t, v in ref if k == q]
        rv = [v for k, t, v in ref if k == q]
        ax.plot(ts, series, "-", label="%s, dx = %g m" % (solver, dx))
        ax.plot(rt, rv, "o", label="Antoci et al. 2007 (experiment)")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("free-end %s displacement [m]" % q)
        ax.grid(True)
        ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(here, "freeEnd%s.png" % suffix), dpi=100)
    met = (complete and errors["x"][0] < PUBLISHED_X
           and all(good for _, good in checks))
    return 1 if check and not met else 0
