#!/usr/bin/python3
"""Dam break of the projection ISPH fluid (isphTlsphFoam, model isph): the
surge front against the converged Navier-Stokes front without surface
tension, up to the impact on the far wall.

    validate.py <case> [--check]

Front: the largest x of the water particles at each written time,
T = t sqrt(g/H). Reference (pass/fail): the front of interFoam without
surface tension (benchmarks/damBreakVof, the finest run;
interFoamFrontNoSurfaceTension.dat) at the times of the Martin & Moyce
experiment up to T = 2.23 (0.17 s, before the front reaches the far wall;
the run goes on through the impact to 0.6 s): RMS of the differences below 0.05 H. The experiment
(martinMoyce1952.dat) is reported beside it (the team's dam-break
decision).

Stability (pass/fail): the run reached endTime; the water keeps its
particles; no particle deeper than dx/2 into a wall; the total energy
(kinetic + potential) never rises above its lowest earlier value by more
than 4 % of rho0 g H^3/2: a guard against a blow-up, not a goal (0.35 to
2.6 % from H/dx = 19 to 76: the run is chaotic in the small; the particle
shifting and the pressure floor do not conserve energy; the ULPH fluid
keeps 0.5 %).

Writes validation/result<suffix>.md and front<suffix>.png and keeps the
run's figures in validation/runs/. With --check, exits 1 when a check
fails.
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT") or os.path.abspath(
    os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from foamMonitor import (arguments, case_spacing, load_runs,  # noqa
                         pyplot, result_suffix, run_cost, save_run, wall_time)
from fsiChecks import largest_rise  # noqa: E402
from damBreakFront import (H, front, front_errors, rms,  # noqa
                           series, stability)

DX0 = 0.002
TARGET = 0.05


def plot(suffix, ts, xs, label):
    plt = pyplot()
    if plt is None:
        return
    ref = series(os.path.join(here, "interFoamFrontNoSurfaceTension.dat"))
    exp = series(os.path.join(here, "martinMoyce1952.dat"))
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot([a for a, _ in ref], [b for _, b in ref], "k-",
            label="interFoam, no surface tension (reference)")
    ax.plot([a for a, _ in exp], [b for _, b in exp], "ko",
            label="Martin & Moyce 1952 (reported)")
    ax.plot(ts, xs, "r-", label=label)
    ax.set_xlabel("T = t sqrt(g/H)")
    ax.set_ylabel("x_front / H")
    ax.set_xlim(0, 3)
    ax.set_ylim(1, 4.1)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "front%s.png" % suffix), dpi=110)
    plt.close(fig)


def main():
    case, check = arguments(__doc__)
    dx = case_spacing(case, DX0)
    suffix = result_suffix(dx, DX0)
    ts, xs = front(case)
    rows = front_errors(ts, xs, here)
    err = rms([r[3] - r[2] for r in rows])
    err_exp = rms([r[3] - r[1] for r in rows])
    checks, total = stability(case, dx, 0.04)
    cost = run_cost(case)
    front_ok = err < TARGET
    stable = all(ok for _, ok in checks)
    verdict = lambda ok: "met" if ok else "MISSED"  # noqa: E731

    lines = [
        "# Dam break, projection ISPH (isphTlsphFoam): front against the"
        " Navier-Stokes reference up to the impact", "",
        "Command: `tutorials/isphTlsphFoam/damBreak/Allrun%s`"
        % ("" if not suffix else " -dx %g" % dx), "",
        "Set-up: square column L = H = 0.057 m, tank 4H, ghost no-slip walls"
        " (4 layers), cubic spline h = 1.2 dx, constant density, the"
        " pressure Poisson equation by BiCGStab each step with the walls'"
        " own rows (the divergence-free source alone), free surface by div"
        " r, minPressure 0, the walls' contact condition, the sum form of"
        " the gradient near the surface, particle shifting (C = 0.1), maxCo"
        " 0.1, hydrostatic start, to 0.6 s (the front compared to T = 2.23,"
        " before the impact).",
        "",
        "| H/dx | water particles | steps | wall time | RMS front vs"
        " Navier-Stokes | target | RMS vs Martin & Moyce (reported) |",
        "|---|---|---|---|---|---|---|",
        "| %.1f | %d | %d | %s | %.4f H | < %.2f H: %s | %.4f H |"
        % (H / dx, cost["bodies"]["water"]["particles"], cost["steps"],
           wall_time(cost), err, TARGET, verdict(front_ok), err_exp),
        "", "Stability:", ""]
    lines += ["- %s: %s" % (what, verdict(ok)) for what, ok in checks]
    lines += ["",
              "| T | experiment x/H | interFoam x/H | isphTlsphFoam x/H |"
              " difference from interFoam |",
              "|---|---|---|---|---|"]
    lines += ["| %.3f | %.3f | %.3f | %.3f | %+.3f |"
              % (T, xe, xr, xm, xm - xr) for T, xe, xr, xm in rows]
    lines += ["", "Plot: front%s.png." % suffix]

    run = {"dx": dx, "rms": err, "rmsExp": err_exp,
           "particles": cost["bodies"]["water"]["particles"],
           "steps": cost["steps"], "wall": cost["wall"],
           "threads": cost["threads"], "stable": int(stable),
           "energyRise": largest_rise(total)}
    runs_dir = os.path.join(here, "runs")
    save_run(runs_dir, "dx%g" % dx, run)
    series_ = sorted(load_runs(runs_dir), key=lambda r: -r["dx"])
    if len(series_) > 1:
        lines += ["", "Convergence (runs kept in validation/runs):", "",
                  "| H/dx | RMS front vs Navier-Stokes | wall time |",
                  "|---|---|---|"]
        lines += ["| %.1f | %.4f H | %.0f s on %d threads |"
                  % (H / r["dx"], r["rms"], r["wall"], r["threads"])
                  for r in series_]
    with open(os.path.join(here, "result%s.md" % suffix), "w") as f:
        f.write("\n".join(lines) + "\n")
    plot(suffix, ts, xs, "isphTlsphFoam, H/dx = %.1f" % (H / dx))

    print("dam break (ISPH): RMS front vs Navier-Stokes %.4f H (target"
          " < %.2f H %s), vs Martin & Moyce %.4f H (reported); stability %s"
          % (err, TARGET, verdict(front_ok), err_exp, verdict(stable)))
    for what, ok in checks:
        print("  %s: %s" % (verdict(ok), what))
    if check and not (front_ok and stable):
        sys.exit(1)


if __name__ == "__main__":
    main()
