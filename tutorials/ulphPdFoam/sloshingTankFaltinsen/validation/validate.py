#!/usr/bin/python3
"""Sloshing tank, Faltinsen et al. (2000) Fig. 7: free-surface elevation
0.05 m from the left wall against the experiment
(validation/faltinsen2000.dat: tank 1.73 m, water 0.6 m deep, sway
A0 = 0.032 m, T = 1.3 s, about 10 s).

The simulated elevation is swayTank's probe_elevation, as in the
sloshingTank tutorial: the
highest water particle within 1.5 spacings of the probe (which moves with
the tank) plus half a spacing, less the depth.

The measures, over the experimental series up to the end of the run:
- the extrema compared are the experiment's crests and troughs: within
  each run of samples of one sign (between zero crossings), the sample of
  largest |eta|, kept when |eta| >= 0.02 m (the smaller ones, near the
  beat's node, are within the digitising and particle resolution) and
  when the run ends before the simulation does;
- the simulated extremum matched to each is the largest (crest) or
  smallest (trough) simulated elevation within a quarter period of the
  experimental one's time, refined by a parabola through the samples
  around it (the experimental one is the digitised point: its neighbours
  are too far apart for a parabola). An extremum on the edge of its window (more than
  T/4 away) is reported as not found;
- the amplitude error (target < 15 %, BENCHMARKS.md) is the mean of
  | |eta_sim| - |eta_exp| | over the compared extrema, relative to the
  mean |eta_exp| of the same extrema; the signed ratio of the mean heights
  less one is printed too (positive: the run sways too much);
- the phase error of each extremum is (t_sim - t_exp)/T; the largest and
  the mean of |.| are printed (no target: the digitised peaks are a few
  hundredths of a second apart);
- the RMS difference from the experiment (linearly interpolated at the
  simulation's output times in the experimental range), relative to the
  experiment's largest |eta|.

The linear modal solution (etc/python/swayTank.py,
with h = 0.6 m, T = 1.3 s) is drawn on the plot for orientation only:
T/T1 = 0.78, so it beats with the first mode (T1 = 1.668 s).

Writes validation/result[-dx<spacing>].md and elevation[...].png.
With --check, exits 1 when the amplitude target is missed (or an extremum
is not found, or the run stopped before its endTime).

Usage: validate.py <case> [--check]
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT",
                         os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from foamMonitor import (arguments, body_cost, interp,  # noqa: E402
                         pyplot, read_rows, result_suffix, wall_time)
from fsiChecks import end_time, verdict  # noqa: E402
from swayTank import SwayTank  # noqa: E402

T = 1.3
XPROBE = 0.05
TANK = SwayTank(length=1.73, depth=0.6, amplitude=0.032, period=T)
AMPLITUDE_TARGET = 0.15
MIN_HEIGHT = 0.02


def linear_eta(t):
    return TANK.linear_eta(t, XPROBE)


def experiment():
    return [tuple(row[:2])
            for row in read_rows(os.path.join(here, "faltinsen2000.dat"))]


def refine(series, k):
    """Time and value of the extremum at sample k, refined by the parabola
    through samples k-1, k, k+1 (any spacing); the sample itself when they
    do not make one"""
    if k == 0 or k == len(series) - 1:
        return series[k]
    (t0, y0), (t1, y1), (t2, y2) = series[k - 1], series[k], series[k + 1]
    if not (t0 < t1 < t2):
        return series[k]
    # y = a (t - t1)^2 + b (t - t1) + y1
    d0, d2 = t0 - t1, t2 - t1
    s0, s2 = (y0 - y1) / d0, (y2 - y1) / d2
    a = (s2 - s0) / (d2 - d0)
    b = s0 - a * d0
    if a == 0:
        return series[k]
    tv = -b / (2 * a)
    if not (d0 <= tv <= d2):
        return series[k]
    return (t1 + tv, y1 + b * tv / 2)


def experimental_extrema(exp, tend):
    """(kind, t, eta) of each crest and trough of the experiment, see the
    docstring"""
    out, k = [], 0
    while k < len(exp):
        j = k
        sign = exp[k][1] >= 0
        while j + 1 < len(exp) and (exp[j + 1][1] >= 0) == sign:
            j += 1
        m = max(range(k, j + 1), key=lambda i: abs(exp[i][1]))
        if 0 < m < len(exp) - 1 and abs(exp[m][1]) >= MIN_HEIGHT \
                and exp[m][0] + T / 4 <= tend:
            out.append(("max" if sign else "min",) + exp[m])
        k = j + 1
    return out


def matched(sim, kind, te):
    """The simulated extremum of this kind within T/4 of te: (t, eta,
    found)"""
    idx = [i for i, s in enumerate(sim) if abs(s[0] - te) <= T / 4]
    if not idx:
        return (te, float("nan"), False)
    pick = max if kind == "max" else min
    m = pick(idx, key=lambda i: sim[i][1])
    t, e = refine(sim, m)
    return (t, e, m not in (idx[0], idx[-1]))


def plot(sim, exp, rows, path):
    plt = pyplot()
    if plt is None:
        return
    ts = [s[0] for s in sim]
    fig, ax = plt.subplots(figsize=(9, 3.8))
    tl = [k * 0.005 for k in range(int(max(ts) / 0.005) + 1)]
    ax.plot(tl, [1000 * linear_eta(t) for t in tl], ":", color="0.5", lw=1,
            label="linear modal solution")
    ax.plot([e[0] for e in exp], [1000 * e[1] for e in exp], "o-", ms=3,
            lw=0.8, color="k", label="experiment (Faltinsen et al. 2000)")
    ax.plot(ts, [1000 * s[1] for s in sim], "-", color="C0",
            label="ulphPdFoam")
    ax.plot([r[3] for r in rows if r[5]], [1000 * r[4] for r in rows if r[5]],
            "x", color="C3", label="compared extrema")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("elevation 0.05 m from the left wall [mm]")
    ax.set_xlim(0, max(ts))
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="lower left", ncol=2)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main(case, check):
    cost = body_cost(case, "water", walls="tank")
    t_end = end_time(case)
    dx = cost["dx"]
    sim = TANK.probe_elevation(case, dx, XPROBE)
    exp = experiment()
    tend = sim[-1][0]
    rows = []
    for kind, te, ee in experimental_extrema(exp, tend):
        ts, es, found = matched(sim, kind, te)
        rows.append((kind, te, ee, ts, es, found))
    good = [r for r in rows if r[5]]
    ok = bool(rows) and len(good) == len(rows)
    if good:
        mean_exp = sum(abs(r[2]) for r in good) / len(good)
        amp = sum(abs(abs(r[4]) - abs(r[2])) for r in good) / len(good) \
            / mean_exp
        ratio = sum(abs(r[4]) for r in good) / len(good) / mean_exp - 1
        phases = [(r[3] - r[1]) / T for r in good]
        phase_max = max(abs(p) for p in phases)
        phase_mean = sum(abs(p) for p in phases) / len(phases)
    else:
        amp = ratio = phase_max = phase_mean = float("nan")
    ok = ok and amp < AMPLITUDE_TARGET
    finished = tend >= t_end - 1e-6
    status = verdict(ok) if finished \
        else "%s so far, unfinished run" % ("met" if ok else "missed")
    ok = ok and finished
    t0, t1 = exp[0][0], min(exp[-1][0], tend)
    window = [s for s in sim if t0 <= s[0] <= t1]
    te, ee = [e[0] for e in exp], [e[1] for e in exp]
    rms = math.sqrt(sum((s[1] - interp(s[0], te, ee)) ** 2 for s in window)
                    / len(window)) / max(abs(e[1]) for e in exp
                                         if e[0] <= t1)
    suffix = result_suffix(dx, 0.01)
    paper = not suffix

    lines = [
        "# Sloshing tank (Faltinsen et al. 2000, Fig. 7): elevation 0.05 m"
        " from the left wall vs the experiment",
        "",
        "Command: `tutorials/ulphPdFoam/sloshingTankFaltinsen/Allrun%s`"
        % ("" if paper else " -dx %g" % dx),
        "",
        "| spacing | water particles | wall particles | simulated | steps |"
        " wall time (CPU time) | particle-steps/s | extrema compared |"
        " amplitude error (target < 15 %) | mean height sim/exp - 1 |"
        " phase error, largest / mean (% of T) | RMS difference / largest"
        " experimental elevation |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
        "| %g m | %d | %d | %g s | %d | %s (%.0f s) | %.3g | %d of %d |"
        " %.1f %%: %s | %+.1f %% | %.1f / %.1f | %.1f %% |"
        % (dx, cost["water"], cost["walls"], tend, cost["steps"],
           wall_time(cost), cost["cpu"], cost["rate"], len(good), len(rows), 100 * amp,
           status, 100 * ratio, 100 * phase_max,
           100 * phase_mean, 100 * rms),
        "",
    ]
    if not finished:
        lines += [
            "**Unfinished run**: stopped at t = %g s of %g s; the measures "
            "cover the experiment's extrema up to then only." %
            (tend, t_end), ""]
    lines += [
        "Set-up: Faltinsen et al. (2000), Fig. 7 (tank 1.73 x 1.15 m, depth "
        "0.6 m, A0 = 0.032 m, T = 1.3 s, X = A0 (cos(2 pi t/T) - 1) through "
        "tabulated6DoFMotion), with the numerical parameters of the "
        "ULPH-NOSBPD paper 4.3 (c0 = 40 m/s, alpha = 0.1, Gaussian h = 1.2 "
        "dx, horizon 3h, density filter every 20 steps), no-slip ghost walls,"
        " hydrostatic start. Experiment: validation/faltinsen2000.dat. "
        "Measures: see validate.py (amplitude error = mean | |eta_sim| - "
        "|eta_exp| | over the experiment's crests and troughs of at least "
        "2 cm, relative to their mean |eta_exp|; simulated extremum within "
        "T/4 of the experimental one).",
        "",
        "| extremum | experiment t [s] | eta [mm] | ulphPdFoam t [s] |"
        " eta [mm] | height difference | time difference / T |",
        "|---|---|---|---|---|---|---|",
    ]
    for kind, te, ee, ts, es, found in rows:
        if found:
            lines.append("| %s | %.3f | %.1f | %.3f | %.1f | %+.1f %% |"
                         " %+.1f %% |"
                         % (kind, te, 1000 * ee, ts, 1000 * es,
                            100 * (abs(es) - abs(ee)) / abs(ee),
                            100 * (ts - te) / T))
        else:
            lines.append("| %s | %.3f | %.1f | not within T/4 | | | |"
                         % (kind, te, 1000 * ee))
    lines += ["", "Plot: elevation%s.png." % suffix]
    open(os.path.join(here, "result%s.md" % suffix), "w").write(
        "\n".join(lines) + "\n")
    plot(sim, exp, rows, os.path.join(here, "elevation%s.png" % suffix))
    print("\n".join(lines))
    print("sloshing Faltinsen: amplitude error %.1f %% (target < 15 %%), "
          "mean height %+.1f %%, phase error %.1f %% T (largest), "
          "%.1f %% T (mean), RMS %.1f %%, %d of %d extrema: %s"
          % (100 * amp, 100 * ratio, 100 * phase_max, 100 * phase_mean,
             100 * rms, len(good), len(rows),
             "PASS" if ok else "FAIL" if finished else "FAIL (unfinished)"))
    return 0 if ok or not check else 1


if __name__ == "__main__":
    sys.exit(main(*arguments()))
