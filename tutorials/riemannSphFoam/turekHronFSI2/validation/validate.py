#!/usr/bin/python3
"""Turek and Hron 2006, FSI2: the displacement of point A (the middle of
the flag's free end, monitor tipA) against the benchmark's reference.

Over the periods of y(t) in the run's last third (between up-crossings of
its mean): mean = (max + min)/2 and amplitude = (max - min)/2 of x and y
over the last period (Turek and Hron's definition), the amplitude of y
averaged over the periods with its largest deviation among them (the
particle method's period-to-period scatter, about 2 %), and the
frequency of y over them, against Turek and Hron's finest-level values
(Turek S, Hron J
(2006). Proposal for numerical benchmarking of fluid-structure
interaction between an elastic object and laminar incompressible flow.
In: Fluid-Structure Interaction, LNCSE 53, 371-385):

    x = -14.58 +- 12.44 mm [3.8 Hz], y = 1.23 +- 80.6 mm [2.0 Hz].

The paper gives the frequency to two digits. Beside it, the FEATFLOW
reference time series of FSI2 distributed with redbKIT
(Problems/FEM_FSI_Turek2D/FSI/ReferenceValues/ref_fsi2, t = 10-14.62 s,
a level below the paper's finest), evaluated here over its 8 full
periods: x = -14.85 +- 12.72 mm, y = 1.25 +- 81.66 mm, 1.9306 Hz.

Targets (BENCHMARKS): y amplitude (the average over the periods) within
5 %, frequency within 3 %, against the paper's values; the errors against
the FEATFLOW series are reported beside them. Also the particles in the channel and the mass through its ends
(postProcessing/openBoundaries), the wall time from the run cost.

Writes validation/result.md (result-dx<spacing>.md for another water
spacing than 0.01 m) and tipA[-dx<spacing>].png. With --check, exits 1
when a target is missed or fewer than three periods were found.

Usage: validate.py <case> [--check]
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT",
                         os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from foamMonitor import (arguments, case_spacing, pyplot,  # noqa: E402
                         read_monitor, result_suffix, run_cost, wall_time)

DEFAULT_DX = 0.01
# Turek and Hron 2006, FSI2: (mean, amplitude) [m] and frequency [Hz]
REF_X = (-14.58e-3, 12.44e-3, 3.8)
REF_Y = (1.23e-3, 80.6e-3, 2.0)
# FEATFLOW's series (redbKIT ref_fsi2), its 8 full periods
SERIES_X = (-14.85e-3, 12.72e-3)
SERIES_Y = (1.25e-3, 81.66e-3, 1.9306)
TOL_AMPLITUDE = 0.05
TOL_FREQUENCY = 0.03


def upcrossings(ts, vs, level, t_from):
    """Times where vs crosses level upwards after t_from (linear)"""
    out = []
    for k in range(1, len(ts)):
        if ts[k - 1] < t_from:
            continue
        if vs[k - 1] < level <= vs[k]:
            a = (level - vs[k - 1]) / (vs[k] - vs[k - 1])
            out.append(ts[k - 1] + a * (ts[k] - ts[k - 1]))
    return out


def period_stats(ts, vs, t0, t1):
    """(mean, amplitude) of vs over [t0, t1]"""
    window = [v for t, v in zip(ts, vs) if t0 <= t <= t1]
    hi, lo = max(window), min(window)
    return 0.5 * (hi + lo), 0.5 * (hi - lo)


def analyse(ts, dx, dy):
    """The periods of y in the run's last third: None when fewer than
    three were found"""
    t_from = 2 * ts[-1] / 3
    window = [v for t, v in zip(ts, dy) if t >= t_from]
    if not window:
        return None
    level = 0.5 * (max(window) + min(window))
    ups = upcrossings(ts, dy, level, t_from)
    if len(ups) < 4:
        return None
    periods = list(zip(ups[:-1], ups[1:]))
    amps = [period_stats(ts, dy, a, b)[1] for a, b in periods]
    mean_amp = sum(amps) / len(amps)
    t0, t1 = periods[-1]
    return {
        "window": (t0, t1),
        "x": period_stats(ts, dx, t0, t1),
        "y": period_stats(ts, dy, t0, t1),
        "periods": len(periods),
        "from": ups[0],
        "amplitude": mean_amp,
        "spread": max(abs(a - mean_amp) for a in amps),
        "frequency": len(periods) / (ups[-1] - ups[0]),
    }


def main():
    case, check = arguments(__doc__)
    sim = read_monitor(case, "tipA")
    ts, dx, dy = sim["time"], sim["dx"], sim["dy"]
    flux = read_monitor(case, "openBoundaries")
    cost = run_cost(case)
    spacing = case_spacing(case, DEFAULT_DX)
    res = analyse(ts, dx, dy)

    lines = []
    met = res is not None
    if res is None:
        lines.append("NO PERIODIC RESPONSE: fewer than three periods of"
                     " y(t) in the run's last half (run to %.2f s)" % ts[-1])
    else:
        err_a = res["amplitude"] / REF_Y[1] - 1
        err_f = res["frequency"] / REF_Y[2] - 1
        met = abs(err_a) <= TOL_AMPLITUDE and abs(err_f) <= TOL_FREQUENCY
        lines += [
            "point A, y: %.2f +- %.2f mm, %.3f Hz (Turek and Hron: %.2f +-"
            " %.1f mm, %.1f Hz)" % (1e3 * res["y"][0], 1e3 * res["y"][1],
                                     res["frequency"], 1e3 * REF_Y[0],
                                     1e3 * REF_Y[1], REF_Y[2]),
            "point A, x: %.2f +- %.2f mm (Turek and Hron: %.2f +- %.2f mm)"
            % (1e3 * res["x"][0], 1e3 * res["x"][1], 1e3 * REF_X[0],
               1e3 * REF_X[1]),
            "y amplitude error %+.1f %% (target 5 %%), frequency error"
            " %+.1f %% (target 3 %%): %s" % (
                100 * err_a, 100 * err_f, "met" if met else "MISSED"),
            "against FEATFLOW's series (%.2f mm, %.4f Hz): amplitude %+.1f %%,"
            " frequency %+.1f %%" % (
                1e3 * SERIES_Y[1], SERIES_Y[2],
                100 * (res["amplitude"] / SERIES_Y[1] - 1),
                100 * (res["frequency"] / SERIES_Y[2] - 1)),
            "y amplitude over %d periods from %.2f s: %.2f mm, each"
            " within %.2f mm of it" % (res["periods"], res["from"],
                                      1e3 * res["amplitude"],
                                      1e3 * res["spread"]),
        ]
    n_water = flux["water.particles"][-1]
    lines.append("water particles at the end %d; through the inlet %.1f"
                 " kg/m, the outlet %.1f kg/m" % (
                     n_water, flux["inlet.mass"][-1],
                     flux["outlet.mass"][-1]))
    for line in lines:
        print(line)

    suffix = result_suffix(spacing, DEFAULT_DX)
    with open(os.path.join(here, "result%s.md" % suffix), "w") as f:
        f.write("# turekHronFSI2 (riemannSphFoam): point A vs Turek and"
                " Hron 2006\n\n")
        f.write("Water spacing %g m (D/%d), flag %g m (%d particles"
                " thick), run to %.2f s.\n\n" % (
                    spacing, round(0.1 / spacing), spacing / 2,
                    round(0.04 / spacing), ts[-1]))
        f.write("| quantity | this run | Turek and Hron 2006 | FEATFLOW"
                " series (redbKIT ref_fsi2) |\n|---|---|---|---|\n")
        if res is not None:
            f.write("| y mean +- amplitude, last period [mm] | %.2f +- %.2f"
                    " | %.2f +- %.1f | %.2f +- %.2f |\n" % (
                        1e3 * res["y"][0], 1e3 * res["y"][1],
                        1e3 * REF_Y[0], 1e3 * REF_Y[1],
                        1e3 * SERIES_Y[0], 1e3 * SERIES_Y[1]))
            f.write("| y amplitude over %d periods from %.2f s [mm] | %.2f"
                    " (each within %.2f) | %.1f | %.2f |\n" % (
                        res["periods"], res["from"], 1e3 * res["amplitude"],
                        1e3 * res["spread"], 1e3 * REF_Y[1],
                        1e3 * SERIES_Y[1]))
            f.write("| y frequency [Hz] | %.3f | %.1f | %.4f |\n"
                    % (res["frequency"], REF_Y[2], SERIES_Y[2]))
            f.write("| x mean +- amplitude [mm] | %.2f +- %.2f | %.2f +-"
                    " %.2f | %.2f +- %.2f |\n" % (
                        1e3 * res["x"][0], 1e3 * res["x"][1],
                        1e3 * REF_X[0], 1e3 * REF_X[1],
                        1e3 * SERIES_X[0], 1e3 * SERIES_X[1]))
            f.write("| y amplitude error | | %+.1f %% (target 5 %%) | %+.1f"
                    " %% |\n" % (100 * (res["amplitude"] / REF_Y[1] - 1),
                                 100 * (res["amplitude"] / SERIES_Y[1] - 1)))
            f.write("| y frequency error | | %+.1f %% (target 3 %%) | %+.1f"
                    " %% |\n" % (100 * (res["frequency"] / REF_Y[2] - 1),
                                 100 * (res["frequency"] / SERIES_Y[2] - 1)))
            f.write("| last period | %.3f - %.3f s | | |\n" % res["window"])
        else:
            f.write("| periodic response | none found | | |\n")
        f.write("| water particles at the end | %d | | |\n" % n_water)
        f.write("| mass in / out [kg/m] | %.1f / %.1f | | |\n"
                % (flux["inlet.mass"][-1], -flux["outlet.mass"][-1]))
        f.write("| particles (all bodies) | %d | | |\n| fluid steps | %d |"
                " | |\n" % (cost["particles"], cost["steps"]))
        f.write("| wall time | %s%s | | |\n" % (
            wall_time(cost), "" if cost["runs"] == 1 else
            " in %d runs (restarts)" % cost["runs"]))
        f.write("\nTarget (y amplitude within 5 %%, frequency within 3 %%"
                " of the paper's): **%s**.\n" % ("met" if met else "missed"))

    plt = pyplot()
    if plt is not None:
        fig, axes = plt.subplots(2, 1, figsize=(10, 6), sharex=True)
        for ax, q, series, ref in ((axes[0], "x", dx, REF_X),
                                   (axes[1], "y", dy, REF_Y)):
            ax.plot(ts, [1e3 * v for v in series], "-",
                    label="riemannSphFoam, dx = %g m" % spacing)
            for level in (ref[0] - ref[1], ref[0] + ref[1]):
                ax.axhline(1e3 * level, color="k", ls="--", lw=0.8)
            ax.set_ylabel("point A, %s [mm]" % q)
            ax.grid(True)
        axes[1].plot([], [], "k--", lw=0.8,
                     label="Turek and Hron 2006: mean +- amplitude")
        axes[1].legend(loc="lower left")
        axes[1].set_xlabel("t [s]")
        fig.tight_layout()
        fig.savefig(os.path.join(here, "tipA%s.png" % suffix), dpi=100)
    return 1 if check and not met else 0


if __name__ == "__main__":
    sys.exit(main())
