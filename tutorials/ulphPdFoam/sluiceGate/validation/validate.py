#!/usr/bin/python3
"""Sluice gate (Yilmaz et al. 2021; ULPH-NOSBPD paper 4.5): a dam break
opens a rubber sluice gate from below. No measured series is available to
us (the paper's Fig. 19 compares with the experiment as a plot only), so the
checks are the ones BENCHMARKS.md sets, 'stable' (fsiChecks):
  - the run reached endTime, no particle lost, every water particle in the
    tank, none inside the gate, the total energy not growing, the gate's
    particle-scale velocity noise below 0.1 sqrt(g H);
and two of the sequence the paper describes (Fig. 18-19): the gate is
pushed open downstream once the water arrives (point A's largest
horizontal displacement positive and larger than 2 spacings), and the
opening passes a maximum and then decreases as the reservoir drains (the
largest opening at least 0.1 s before the end, the last below 0.95 of it).

Point A is the centre of the gate's free lower end (monitor pointA).
Prints and writes validation/result[-dx<spacing>].md with point A's largest
opening and when, when the gate starts to open, particles, steps
and wall time, and pointA[-dx<spacing>].png (point A's displacement, and
the particles when the gate is most open).
With --check, exits 1 when a check is missed.

Usage: validate.py <case> [--check]
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT",
                         os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from foamCloud import read_positions, times  # noqa: E402
from fsiChecks import (check_rows, print_checks,  # noqa: E402
                       stability_checks)
from foamMonitor import (arguments, case_spacing, pyplot,  # noqa: E402
                         read_monitor, result_suffix, run_cost, wall_time)

DEFAULT_DX = 0.0035
TANK = (0.0, 1.5)       # walls at x = 0 and 1.5 m
COLUMN = (0.5, 0.2)     # water column width and height [m]


def main():
    case, check = arguments(__doc__)
    dx = case_spacing(case, DEFAULT_DX)

    # rho g H^2 W/2 of the column
    scale = 1000 * 9.81 * COLUMN[1] ** 2 * COLUMN[0] / 2
    checks = stability_checks(case, "gate", TANK, dx, scale,
                              velocity_scale=math.sqrt(9.81 * COLUMN[1]))

    a = read_monitor(case, "pointA")
    k = max(range(len(a["dx"])), key=lambda i: a["dx"][i])
    xMax, tMax = a["dx"][k], a["time"][k]
    checks.append(("the gate opens: point A's largest horizontal"
                   " displacement %.4f m > 2 dx" % xMax, xMax > 2 * dx))
    xEnd, tEnd = a["dx"][-1], a["time"][-1]
    checks.append(("the opening passes a maximum: largest at %.3f s, at"
                   " least 0.1 s before the end, and at %.3f s %.4f m <"
                   " 0.95 of it" % (tMax, tEnd, xEnd),
                   tMax < tEnd - 0.1 and xEnd < 0.95 * xMax))
    # The water's arrival: point A moves by 1 mm
    tArrive = next((t for t, x in zip(a["time"], a["dx"]) if x > 1e-3),
                   float("nan"))

    ok = all(c[1] for c in checks)
    print_checks(checks)
    print("point A: largest opening %.4f m (dy %.4f m) at %.3f s; the gate"
          " starts to open (1 mm) at %.3f s" % (xMax, a["dy"][k], tMax, tArrive))

    cost = run_cost(case)
    suffix = result_suffix(dx, DEFAULT_DX)
    with open(os.path.join(here, "result%s.md" % suffix), "w") as f:
        f.write("# Sluice gate: stability and the gate's opening\n\n")
        f.write("Command: `tutorials/ulphPdFoam/sluiceGate/Allrun%s`\n\n"
                % ("" if not suffix else " -dx %g" % dx))
        f.write("| spacing | particles | steps | wall time | particle-steps/s"
                " | the gate starts to open (1 mm) | point A: largest dx | at | dy then"
                " | dx at the end |\n|---|---|---|---|---|---|---|---|---|"
                "---|\n")
        f.write("| %g m | %d | %d | %s | %.3g | %.3f s | %.4f m | %.3f s"
                " | %.4f m | %.4f m (%g s) |\n"
                % (dx, cost["particles"], cost["steps"], wall_time(cost),
                   cost["rate"], tArrive, xMax, tMax, a["dy"][k], xEnd,
                   a["time"][-1]))
        f.write("\n| check (BENCHMARKS: stable; the paper's sequence) | |\n"
                "|---|---|\n")
        f.write("".join(row + "\n" for row in check_rows(checks)))
        f.write("\nSet-up: ULPH-NOSBPD paper 4.5, Table 5 (rubber gate 0.125"
                " x 0.007 m, rho 1250, E 4 MPa, nu 0.4; c0 60 m/s, alpha"
                " 0.05), water 0.5 x 0.2 m, the gate 0.3 m downstream of it."
                " Plot: pointA%s.png.\n" % suffix)

    plt = pyplot()
    if plt:
        fig, (ax0, ax1) = plt.subplots(2, 1, figsize=(8, 7))
        ax0.plot(a["time"], a["dx"], label="dx (horizontal)")
        ax0.plot(a["time"], a["dy"], label="dy (vertical)")
        ax0.axvline(tArrive, color="grey", ls=":", label="the gate starts to open")
        ax0.set_xlabel("t [s]")
        ax0.set_ylabel("point A displacement [m]")
        ax0.legend()
        ax0.grid(alpha=0.3)
        series = times(case)
        name = min(series, key=lambda s: abs(s[0] - tMax))
        for body, colour, size in (("water", "tab:blue", 1),
                                   ("gate", "tab:red", 3),
                                   ("tank", "grey", 1)):
            p = read_positions(case, name[1], body)
            ax1.scatter([q[0] for q in p], [q[1] for q in p], s=size,
                        c=colour)
        ax1.set_xlim(-0.02, TANK[1] + 0.02)
        ax1.set_ylim(-0.02, 0.42)
        ax1.set_aspect("equal")
        ax1.set_title("t = %s s (written time nearest the largest opening)"
                      % name[1])
        fig.tight_layout()
        fig.savefig(os.path.join(here, "pointA%s.png" % suffix), dpi=110)
    return 1 if check and not ok else 0


if __name__ == "__main__":
    sys.exit(main())
