#!/usr/bin/python3
"""Still water (isphTlsphFoam): a run against hydrostatics, the ISPH
issue's targets.

- bottom pressure: the bottom row's pressure averaged over the row and
  the written times of 1-2 s against rho g (y_s - dx/2), y_s the surface
  row's height at the start: the free-surface condition p = 0 sits on the
  surface particles (isph.H), half a spacing below the water's edge, so
  the column is dx/2 shorter than the seeded depth H; within 1 %. Its
  value against rho g H is reported beside it;
- spurious speeds: RMS below 1e-3 sqrt(g H) and largest below
  3e-3 sqrt(g H) at every written time;
- the surface row's pressure within 1 % of rho g H of hydrostatics (RMS
  over the row and the written times of 1-2 s);
- no particle lost or outside the tank.

Writes validation/result.md and speeds.png; with --check exits 1 when a
target is missed.

Usage: validate.py <case> [--check]
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT",
                         os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from foamCloud import read_cloud, speed_history, times  # noqa: E402
from foamMonitor import arguments, body_cost, pyplot, wall_time  # noqa
from fsiChecks import verdict  # noqa: E402

H, WIDTH, G, RHO = 0.1, 0.2, 9.81, 1000.0


def measure(case):
    cost = body_cost(case, "water", walls="tank")
    dx = cost["dx"]
    series = times(case)
    first = read_cloud(case, series[0][1], "water")
    top = max(x[1] for x in first["positions"])
    bottom, surface = [], []
    for time, folder in series:
        if time < 1 - 1e-9:
            continue
        c = read_cloud(case, folder, "water")
        bottom += [p for p, x in zip(c["p"], c["positions"]) if x[1] < dx]
        surface += [p - RHO * G * (top - x[1])
                    for p, x in zip(c["p"], c["positions"])
                    if x[1] > top - dx / 2]
    last = read_cloud(case, series[-1][1], "water")
    history = speed_history(case, "water")
    return {
        "cost": cost, "dx": dx, "end": series[-1][0],
        "bottom": sum(bottom) / len(bottom),
        "expected": RHO * G * (top - dx / 2),
        "noise": math.sqrt(sum(s * s for s in surface) / len(surface)),
        "kept": len(last["positions"]) == len(first["positions"]),
        "inside": all(0 <= x[0] <= WIDTH and x[1] >= 0
                      for x in last["positions"]),
        "history": history,
    }


def plot(history, path):
    plt = pyplot()
    if plt is None:
        return
    scale = math.sqrt(G * H)
    ts = [h[0] for h in history[1:]]
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.semilogy(ts, [h[1] / scale for h in history[1:]], "o-", label="RMS")
    ax.semilogy(ts, [h[2] / scale for h in history[1:]], "s-",
                label="largest")
    ax.axhline(1e-3, ls="--", color="C0", label="RMS target")
    ax.axhline(3e-3, ls=":", color="C1", label="largest target")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("spurious speed / sqrt(g H)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main(case, check):
    m = measure(case)
    scale = math.sqrt(G * H)
    rms = max(h[1] for h in m["history"]) / scale
    largest = max(h[2] for h in m["history"]) / scale
    err = m["bottom"] / m["expected"] - 1
    noise = m["noise"] / (RHO * G * H)
    checks = [
        ("ran to 2 s", abs(m["end"] - 2) < 1e-9),
        ("bottom pressure within 1 % of rho g (y_s - dx/2)", abs(err) < 0.01),
        ("RMS spurious speed < 1e-3 sqrt(g H)", rms < 1e-3),
        ("largest spurious speed < 3e-3 sqrt(g H)", largest < 3e-3),
        ("surface row within 1 % of rho g H of hydrostatics", noise < 0.01),
        ("no particle lost", m["kept"]),
        ("every particle inside the tank", m["inside"]),
    ]
    ok = all(c for _, c in checks)
    cost = m["cost"]
    lines = [
        "# Still water (isphTlsphFoam): against hydrostatics",
        "",
        "Command: `tutorials/isphTlsphFoam/stillWater/Allrun`",
        "",
        "| spacing | water particles | wall particles | steps | wall time |",
        "|---|---|---|---|---|",
        "| %g m | %d | %d | %d | %s |" % (m["dx"], cost["water"],
                                         cost["walls"], cost["steps"],
                                         wall_time(cost)),
        "",
        "| measure | value | target |",
        "|---|---|---|",
        "| bottom pressure (rows, 1-2 s) | %.1f Pa | rho g (y_s - dx/2) = "
        "%.1f Pa within 1 %%: %+.3f %% (%s) |"
        % (m["bottom"], m["expected"], 100 * err, verdict(abs(err) < 0.01)),
        "| bottom pressure / rho g H | %.4f | reported (the surface "
        "condition sits dx/2 below the edge) |" % (m["bottom"] / (RHO * G * H)),
        "| RMS spurious speed, largest over 2 s | %.2e sqrt(g H) | < 1e-3 "
        "(%s) |" % (rms, verdict(rms < 1e-3)),
        "| largest spurious speed over 2 s | %.2e sqrt(g H) | < 3e-3 (%s) |"
        % (largest, verdict(largest < 3e-3)),
        "| surface row vs hydrostatics (RMS) | %.2e rho g H | < 1e-2 (%s) |"
        % (noise, verdict(noise < 0.01)),
        "| particles kept, inside the tank | %s, %s | all |"
        % (m["kept"], m["inside"]),
        "",
        "Set-up: water 0.1 m deep in a 0.2 m wide tank, dx = 5 mm, cubic "
        "spline h = 1.2 dx, ghost walls of 4 layers (free slip), "
        "hydrostatic start, maxCo 0.1, CG to 1e-10. Plot: speeds.png.",
    ]
    open(os.path.join(here, "result.md"), "w").write("\n".join(lines) + "\n")
    plot(m["history"], os.path.join(here, "speeds.png"))
    print("\n".join(lines))
    for name, c in checks:
        print("  %s: %s" % (verdict(c), name))
    print("still water (ISPH): %s" % ("PASS" if ok else "FAIL"))
    return 0 if ok or not check else 1


if __name__ == "__main__":
    sys.exit(main(*arguments()))
