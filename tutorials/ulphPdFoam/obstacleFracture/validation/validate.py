#!/usr/bin/python3
"""Obstacle fracture (ULPH-NOSBPD paper 4.4, Table 4): the soil baffle under
the dam-break flow. There is no published measurement; the checks are the
ones BENCHMARKS.md sets (runs to the end, stable, no particle lost) and that
the baffle fractures:
  - the run reached endTime (the solver stops on a NaN or an escaped
    particle, naming both);
  - every body keeps its particles, and every water particle below the
    walls' top is inside the tank (0 <= x <= 0.584, y >= 0, walls
    penetrated by less than dx/2 as in fsiChecks); the tank is
    open at the top, so a splash above it is counted, not failed;
  - bonds broke (lagrangian/obstacle/brokenBonds) and the damage field of
    eq. 49 is written, with its largest value and the number of particles
    that lost more than half of their bonds;
  - the total energy (energy monitor) never rose above its start by more
    than 1e-3 of the column's potential energy rho g (2L)^2 L/2 (61 J/m);
  - the baffle's particle-scale velocity noise (fsiChecks.velocity_noise)
    stays below 0.1 sqrt(g 2L).

Writes validation/result[-dx<spacing>].md and damage[-dx<spacing>].png (the
particles at the last time, the baffle coloured by damage).
With --check, exits 1 when a check fails.

Usage: validate.py <case> [--check]
"""
import math
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT",
                         os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from foamCloud import read_cloud, times  # noqa: E402
from foamMonitor import case_spacing, pyplot, run_cost  # noqa: E402
from fsiChecks import end_time, velocity_noise  # noqa: E402


DEFAULT_DX = 0.002
TANK = 0.584


def broken_bonds(case, name):
    path = os.path.join(case, name, "lagrangian", "obstacle", "brokenBonds")
    if not os.path.exists(path):
        return 0
    return len(re.findall(r"\(\s*\d+\s+\d+\s*\)", open(path).read()))


def energy_total(case):
    """The energy monitor's total over a run and its restarts. A restart's
    monitor measures potential energy from the restart's own positions, so
    its totals are shifted to continue the earlier run's at the restart's
    first time."""
    base = os.path.join(case, "postProcessing", "energy")
    rows = []
    for start in sorted(os.listdir(base), key=float):
        own = []
        for line in open(os.path.join(base, start, "energy.dat")):
            if line.strip() and not line.startswith("#"):
                values = [float(v) for v in line.split()]
                own.append((values[0], values[-1]))
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


def broken_pairs(case, name):
    """The broken bonds at a time as a set of (id, id), smaller id first."""
    path = os.path.join(case, name, "lagrangian", "obstacle", "brokenBonds")
    if not os.path.exists(path):
        return set()
    return set((int(a), int(b)) for a, b in
               re.findall(r"\(\s*(\d+)\s+(\d+)\s*\)", open(path).read()))


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
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if not args:
        print(__doc__)
        return 2
    case = args[0]
    check = "--check" in sys.argv
    dx = case_spacing(case, DEFAULT_DX)

    series = times(case)
    t0, first = series[0]
    t1, last = series[-1]
    checks = []
    checks.append(("ran to endTime %g s (last time %g s)"
                   % (end_time(case), t1),
                   abs(t1 - end_time(case)) < 1e-9))
    clouds = {}
    for body in ("water", "obstacle", "tank"):
        n0 = len(read_cloud(case, first, body)["positions"])
        clouds[body] = read_cloud(case, last, body)
        n1 = len(clouds[body]["positions"])
        checks.append(("%s keeps its %d particles" % (body, n0), n0 == n1))
    water = clouds["water"]["positions"]
    # The tank is open at the top (its walls end at TANK): a splash may fly
    # above the walls and land beyond them, which no wall leaked
    below = [p for p in water if p[1] < TANK]
    above = [p for p in water if p[1] >= TANK]
    # inside: walls penetrated by less than dx/2, the criterion of the dam
    # break and fsiChecks (the first ghost layer lies at dx/2)
    depth = max([0.0] + [max(-p[0], p[0] - TANK, -p[1]) for p in below])
    inside = depth < 0.5 * dx
    checks.append(("every water particle below the walls' top (%g m) inside"
                   " the tank (deepest wall penetration %.2f dx < 0.5 dx);"
                   " %d above it (splash), %d of those beyond the"
                   " side walls" % (TANK, depth / dx, len(above),
                                    sum(1 for p in above
                                        if not 0 <= p[0] <= TANK)),
                   inside))
    nBroken = broken_bonds(case, last)
    damage = clouds["obstacle"]["damage"]
    checks.append(("bonds broke (%d)" % nBroken, nBroken > 0))
    nHalf = sum(1 for d in damage if d > 0.5)
    # When the first bond broke, and how far the intact bonds are stretched
    # at the end (the baffle's horizon: 3 spacings)
    firstBroken = None
    for t, name in series:
        if broken_bonds(case, name):
            firstBroken = t
            break
    sMax, where = largest_intact_stretch(
        clouds["obstacle"], broken_pairs(case, last), 3 * dx)
    total = energy_total(case)
    rise = max(total) - total[0]
    scale = 1000 * 9.81 * 0.292 ** 2 * 0.146 / 2
    checks.append(("total energy not growing (largest rise %.3g J/m <= %.3g)"
                   % (rise, 1e-3 * scale), rise <= 1e-3 * scale))
    noise = velocity_noise(case, "obstacle", dx)
    vScale = math.sqrt(9.81 * 0.292)
    checks.append(("the obstacle's particle-scale velocity noise %.3g m/s <"
                   " 0.1 x %.3g m/s (fsiChecks)" % (noise, vScale),
                   noise < 0.1 * vScale))

    ok = all(c[1] for c in checks)
    for what, good in checks:
        print("%s: %s" % ("met" if good else "MISSED", what))
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

    cost = run_cost(os.path.join(case, "log.ulphPdFoam"))
    suffix = "" if abs(dx - DEFAULT_DX) < 1e-12 else "-dx%g" % dx
    with open(os.path.join(here, "result%s.md" % suffix), "w") as f:
        f.write("# Obstacle fracture: stability and damage\n\n")
        f.write("Command: `tutorials/ulphPdFoam/obstacleFracture/Allrun%s`\n\n"
                % ("" if not suffix else " -dx %g" % dx))
        f.write("| spacing | particles | steps | wall time | particle-steps/s"
                " | broken bonds | largest damage | particles with damage"
                " > 0.5 | largest plastic strain |\n"
                "|---|---|---|---|---|---|---|---|---|\n")
        f.write("| %g m | %d | %d | %.0f s | %.3g | %d | %.3f | %d of %d |"
                " %.3f |\n"
                % (dx, cost["particles"], cost["steps"], cost["wall"],
                   cost["rate"], nBroken, max(damage), nHalf, len(damage),
                   plastic))
        if cost["runs"] > 1:
            f.write("\nThe log holds %d runs (a run and its restarts): the"
                    " wall time adds them up.\n" % cost["runs"])
        f.write("\nBonds: %s; %s.\n" % (firstText, stretchText))
        f.write("\n| check (BENCHMARKS: runs to the end, stable, no particle"
                " lost; fractures) | |\n|---|---|\n")
        for what, good in checks:
            f.write("| %s | %s |\n" % (what, "met" if good else "MISSED"))
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
