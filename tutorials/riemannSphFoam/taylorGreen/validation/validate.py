#!/usr/bin/python3
"""Taylor-Green vortex of the Riemann WCSPH fluid (riemannSphFoam): the
kinetic energy's decay against the exact exp(-16 pi^2 t/Re).

    validate.py <case> [--check]

Decay rate: the least-squares slope of ln(E(t)/E(0)) over the written
energy monitor (0 < t <= 1), against the exact 16 pi^2/Re = 1.5791 (Re =
100); its relative error is the accuracy figure. The energy's largest
relative departure from the exact decay over the run shows a burst (the
lattice start's failure: README).

Checks (pass/fail) at dx = 1/50 with the default scheme (RKGC, normalised
Laplacian, relaxed particles): the run reached t = 1, decay-rate error
within 1 % and the energy within 2 % of the exact decay throughout
(measured: 0.43 % and 0.94 %). Other spacings and schemes are reported.

Writes validation/result.md (the runs kept in validation/runs as a table
per Laplacian: decay-rate error and observed order per correction) and
decay.png (E/E_exact of the kept runs of this run's Laplacian). With
--check, exits 1 when a check fails.
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT") or os.path.abspath(
    os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from foamDict import dictionary_entry  # noqa: E402
from foamMonitor import (arguments, case_spacing, load_runs,  # noqa: E402
                         monitor_rows, pyplot, run_cost, save_run)

RE = 100.0
RATE = 16 * math.pi ** 2 / RE
DX0 = 0.02
RATE_TOL, ENERGY_TOL = 0.01, 0.02
CORRECTIONS = ["none", "KGC", "RKGC"]


def decay(case):
    """(t, E) of the energy monitor and the fitted decay rate"""
    columns, rows = monitor_rows(case, "energy")
    k = columns.index("water:kinetic")
    t = [r[0] for r in rows]
    e = [r[k] for r in rows]
    pts = [(ti, math.log(ei / e[0])) for ti, ei in zip(t, e) if ti > 0]
    n = len(pts)
    mt = sum(p[0] for p in pts) / n
    my = sum(p[1] for p in pts) / n
    slope = (sum((p[0] - mt) * (p[1] - my) for p in pts)
             / sum((p[0] - mt) ** 2 for p in pts))
    return t, e, -slope


def departure(t, e):
    """Largest |E/E_exact - 1|"""
    return max(abs(ei / (e[0] * math.exp(-RATE * ti)) - 1)
               for ti, ei in zip(t, e))


def table(runs, laplacian):
    """Markdown rows: per spacing, each correction's rate error (observed
    order from the coarser spacing) and wall time"""
    sel = [r for r in runs if r["laplacian"] == laplacian]
    dxs = sorted({r["dx"] for r in sel}, reverse=True)
    if not dxs:
        return []
    lines = ["| 1/dx | particles | " + " | ".join(
        "%s: rate error (order), max departure, wall" % c
        for c in CORRECTIONS) + " |",
        "|---|---|" + "---|" * len(CORRECTIONS)]
    for k, dx in enumerate(dxs):
        cells = []
        n = ""
        for c in CORRECTIONS:
            r = [x for x in sel if x["dx"] == dx and x["correction"] == c]
            if not r:
                cells.append("-")
                continue
            r = r[0]
            n = r["particles"]
            order = ""
            if k:
                prev = [x for x in sel if x["dx"] == dxs[k - 1]
                        and x["correction"] == c]
                if prev and r["rateError"] != 0:
                    order = " (%.2f)" % (
                        math.log(abs(prev[0]["rateError"] / r["rateError"]))
                        / math.log(dxs[k - 1] / dx))
            cells.append("%+.2f %%%s, %.2f %%, %.0f s"
                         % (100 * r["rateError"], order,
                            100 * r["departure"], r["wall"]))
        lines.append("| %.0f | %s | %s |" % (1 / dx, n, " | ".join(cells)))
    return lines


def main():
    case, check = arguments(__doc__)
    dx = case_spacing(case, DX0)
    correction = dictionary_entry(case, "bodies/water/kernelCorrection")
    laplacian = dictionary_entry(case, "bodies/water/viscousLaplacian",
                                 default="morris")
    t, e, rate = decay(case)
    err = rate / RATE - 1
    dep = departure(t, e)
    cost = run_cost(case)
    reached = t[-1] > 1 - 1e-6
    default = (abs(dx - DX0) < 1e-9 and correction == "RKGC"
               and laplacian == "normalised")
    ok = reached and (not default
                      or (abs(err) < RATE_TOL and dep < ENERGY_TOL))

    run = {"dx": dx, "correction": correction, "laplacian": laplacian,
           "rate": rate, "rateError": err, "departure": dep,
           "particles": cost["bodies"]["water"]["particles"],
           "steps": cost["steps"], "wall": cost["wall"],
           "threads": cost["threads"]}
    runs_dir = os.path.join(here, "runs")
    save_run(runs_dir, "%s-%s-dx%g" % (laplacian, correction, dx), run)
    runs = load_runs(runs_dir)

    verdict = lambda good: "met" if good else "MISSED"  # noqa: E731
    lines = [
        "# Taylor-Green vortex, Riemann WCSPH (riemannSphFoam): decay rate"
        " per kernel correction", "",
        "Command: `tutorials/riemannSphFoam/taylorGreen/Allrun -series`"
        " (all runs below; `Allrun` alone: dx = 1/50, RKGC, normalised)", "",
        "Set-up: periodic unit box, U = 1, Re = 100, rho0 = 1, c0 = 10,"
        " Wendland C2 h = 1.3 dx, transport velocity (0.2), density"
        " summation, dual-criteria steps (advection maxCo 0.25), relaxed"
        " particles (seedParticles relaxation, 300 iterations), to t = 1."
        " Exact decay rate of the kinetic energy 16 pi^2/Re = %.4f." % RATE,
        "",
        "This run: 1/dx = %.0f, %s, %s Laplacian: decay rate %.4f, error"
        " %+.2f %%, largest departure of E from the exact decay %.2f %%,"
        " %d advection steps, %.1f s on %d threads."
        % (1 / dx, correction, laplacian, rate, 100 * err, 100 * dep,
           cost["steps"], cost["wall"], cost["threads"]), ""]
    if default:
        lines += ["Checks: reached t = 1: %s; decay-rate error below %.0f %%:"
                  " %s; energy within %.0f %% of the exact decay: %s." % (
                      verdict(reached), 100 * RATE_TOL,
                      verdict(abs(err) < RATE_TOL), 100 * ENERGY_TOL,
                      verdict(dep < ENERGY_TOL)), ""]
    for lap in ["normalised", "morris"]:
        rows = table(runs, lap)
        if rows:
            lines += ["Viscous Laplacian %s (runs kept in validation/runs;"
                      " order: observed from the coarser spacing):" % lap,
                      ""] + rows + [""]
    lines += ["Plot: decay.png (E/E_exact of the %s runs)." % laplacian]
    with open(os.path.join(here, "result.md"), "w") as f:
        f.write("\n".join(lines) + "\n")

    plt = pyplot()
    if plt:
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.plot(t, [ei / (e[0] * math.exp(-RATE * ti))
                    for ti, ei in zip(t, e)], "k-", lw=1.2,
                label="this run: 1/dx = %.0f, %s" % (1 / dx, correction))
        ax.axhline(1, color="0.6", lw=0.8)
        ax.set_xlabel("t")
        ax.set_ylabel("E / E_exact")
        ax.set_title("Taylor-Green, Re = 100, %s Laplacian" % laplacian)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(here, "decay.png"), dpi=110)
        plt.close(fig)

    print("Taylor-Green (Riemann, %s, %s, 1/dx = %.0f): decay rate %.4f"
          " (exact %.4f), error %+.2f %%, largest departure %.2f %%%s"
          % (correction, laplacian, 1 / dx, rate, RATE, 100 * err, 100 * dep,
             "" if not default else ": " + verdict(ok)))
    if check and not ok:
        sys.exit(1)


if __name__ == "__main__":
    main()
