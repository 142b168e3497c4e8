#!/usr/bin/python3
"""Obstacle fracture (ULPH-NOSBPD paper 4.4, Table 4): the soil baffle under
the dam-break flow. There is no published measurement; the checks are the
ones BENCHMARKS.md sets (runs to the end, stable, no particle lost) and that
the baffle fractures:
  - fsiChecks' stability checks: the run reached endTime, the water and
    the baffle keep their particles, every water particle below the walls'
    top is inside the tank (walls at x = 0 and 0.584 m and the floor
    penetrated by less than dx/2; the tank is open at the top, so a splash
    above it is counted, not failed), none inside the baffle, the total
    energy over the run and its restarts never rose above its start by
    more than 1e-3 of the column's potential energy rho g (2L)^2 L/2
    (61 J/m), the baffle's particle-scale velocity noise below
    0.1 sqrt(g 2L);
  - bonds broke (lagrangian/obstacle/brokenBonds) and the damage field of
    eq. 49 is written, with its largest value and the number of particles
    that lost more than half of their bonds.

Writes validation/result[-dx<spacing>].md and damage[-dx<spacing>].png (the
particles at the last time, the baffle coloured by damage).
With --check, exits 1 when a check fails.

Usage: validate.py <case> [--check]
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT",
                         os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from foamCloud import read_cloud, read_field, times  # noqa: E402
from foamMonitor import (arguments, case_spacing, pyplot,  # noqa: E402
                         result_suffix, run_cost, wall_time)
from fsiChecks import (check_rows, print_checks,  # noqa: E402
                       stability_checks)


DEFAULT_DX = 0.002
TANK = 0.584           # the tank's width and the height of its walls (open top)


def broken_pairs(case, name):
    """The broken bonds at a time as a set of (id, id), smaller id first
    (brokenBonds lists per particle the ids its broken bonds joined)."""
    path = os.path.join(case, name, "lagrangian", "obstacle", "brokenBonds")
    if not os.path.exists(path):
        return set()
    ids = read_field(case, name, "obstacle", "id")
    partners = read_field(case, name, "obstacle", "brokenBonds")
    return set((min(int(i), int(j)), max(int(i), int(j)))
               for i, js in zip(ids, partners) for j in js)


def largest_intact_stretch(cloud, broken, horizon):
    """Largest stretch (|y_j - y_i| - |xi|)/|xi| over the intact bonds
    (pairs closer than the horizon in X0), with the pair's X0 midpoint."""
    X0 = cloud["X0"]
    x = cloud["positions"]
    ids = cloud["id"]
    best = (-1.0, None)
    n = len(X0)
    for i in range(n):
        for j in range(i + 1, n):
            dx0 = X0[j][0] - X0[i][0]
            dy0 = X0[j][1] - X0[i][1]
            r0 = (dx0 * dx0 + dy0 * dy0) ** 0.5
            if r0 >= horizon * (1 - 1e-6):
                continue
            pair = (min(ids[i], ids[j]), max(ids[i], ids[j]))
            if pair in broken:
                continue
            r = ((x[j][0] - x[i][0]) ** 2 + (x[j][1] - x[i][1]) ** 2) ** 0.5
            s = (r - r0) / r0
            if s > best[0]:
                best = (s, ((X0[i][0] + X0[j][0]) / 2,
                            (X0[i][1] + X0[j][1]) / 2))
    return best


def main():
    case, check = arguments(__doc__)
    dx = case_spacing(case, DEFAULT_DX)

    series = times(case)
    t1, last = series[-1]
    # rho g H^2 W/2 of the column (H = 2L = 0.292, W = L = 0.146)
    checks = stability_checks(case, "obstacle", (0, TANK), dx,
                              1000 * 9.81 * 0.292 ** 2 * 0.146 / 2,
                              velocity_scale=math.sqrt(9.81 * 0.292),
                              walls_top=TANK)
    clouds = {body: read_cloud(case, last, body)
              for body in ("water", "obstacle")}
    water = clouds["water"]["positions"]
    broken = broken_pairs(case, last)
    nBroken = len(broken)
    damage = clouds["obstacle"]["damage"]
    checks.append(("bonds broke (%d)" % nBroken, nBroken > 0))
    nHalf = sum(1 for d in damage if d > 0.5)
    # When the first bond broke, and how far the intact bonds are stretched
    # at the end (the baffle's horizon: 3 spacings)
    firstBroken = None
    for t, name in series:
        if broken_pairs(case, name):
            firstBroken = t
            break
    sMax, where = largest_intact_stretch(
        clouds["obstacle"], broken, 3 * dx)

    ok = all(c[1] for c in checks)
    print_checks(checks)
    plastic = max(clouds["obstacle"].get("plasticStrain", [0]))
    print("damage: largest %.3f, %d of %d particles above 0.5; largest"
          " equivalent plastic strain %.3f" % (max(damage), nHalf,
                                               len(damage), plastic))
    firstText = ("first written with broken bonds at %g s" % firstBroken
                 if firstBroken is not None else "no bond broke")
    stretchText = ("largest stretch of an intact bond at %g s: %.4f at"
                   " X0 (%.4f, %.4f) (critical 0.069)"
                   % (t1, sMax, where[0], where[1]))
    print("%s; %s" % (firstText, stretchText))

    cost = run_cost(case)
    suffix = result_suffix(dx, DEFAULT_DX)
    with open(os.path.join(here, "result%s.md" % suffix), "w") as f:
        f.write("# Obstacle fracture: stability and damage\n\n")
        f.write("Command: `tutorials/ulphPdFoam/obstacleFracture/Allrun%s`\n\n"
                % ("" if not suffix else " -dx %g" % dx))
        f.write("| spacing | particles | steps | wall time | particle-steps/s"
                " | broken bonds | largest damage | particles with damage"
                " > 0.5 | largest plastic strain |\n"
                "|---|---|---|---|---|---|---|---|---|\n")
        f.write("| %g m | %d | %d | %s | %.3g | %d | %.3f | %d of %d |"
                " %.3f |\n"
                % (dx, cost["particles"], cost["steps"], wall_time(cost),
                   cost["rate"], nBroken, max(damage), nHalf, len(damage),
                   plastic))
        if cost["runs"] > 1:
            f.write("\nThe case holds %d runs (a run and its restarts): the"
                    " wall time adds them up.\n" % cost["runs"])
        f.write("\nBonds: %s; %s.\n" % (firstText, stretchText))
        f.write("\n| check (BENCHMARKS: runs to the end, stable, no particle"
                " lost; fractures) | |\n|---|---|\n")
        f.write("".join(row + "\n" for row in check_rows(checks)))
        f.write("\nSet-up: ULPH-NOSBPD paper 4.4, Table 4 (Drucker-Prager"
                " baffle: rho 2500, E 30 MPa, nu 0.25, friction angle 13"
                " degrees, cohesion 5 kPa, dilation 0, critical stretch"
                " 0.069), the geometry and water of elasticObstacle."
                " Plot: damage%s.png (time %g s).\n" % (suffix, t1))

    plt = pyplot()
    if plt:
        fig, ax = plt.subplots(figsize=(8, 4.5))
        wx = [p[0] for p in water]
        wy = [p[1] for p in water]
        ax.scatter(wx, wy, s=1, c="tab:blue", label="water")
        ob = clouds["obstacle"]["positions"]
        sc = ax.scatter([p[0] for p in ob], [p[1] for p in ob], s=6,
                        c=damage, cmap="inferno", vmin=0, vmax=1)
        fig.colorbar(sc, ax=ax, label="damage (eq. 49)")
        ax.set_xlim(0, TANK)
        ax.set_ylim(-0.01, 0.3)
        ax.set_aspect("equal")
        ax.set_title("t = %g s" % t1)
        fig.tight_layout()
        fig.savefig(os.path.join(here, "damage%s.png" % suffix), dpi=110)
    return 1 if check and not ok else 0


if __name__ == "__main__":
    sys.exit(main())
