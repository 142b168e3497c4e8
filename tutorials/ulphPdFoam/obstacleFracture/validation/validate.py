#!/usr/bin/python3
"""Obstacle fracture (ULPH-NOSBPD paper 4.4, Table 4): the soil baffle under
the dam-break flow. There is no published measurement; the checks are the
ones BENCHMARKS.md sets (runs to the end, stable, no particle lost) and that
the baffle fractures:
  - the run reached endTime (the solver stops on a NaN or an escaped
    particle, naming both);
  - every body keeps its particles, and every water particle is inside the
    tank (0 <= x <= 0.584, y >= 0);
  - bonds broke (lagrangian/obstacle/brokenBonds) and the damage field of
    eq. 49 is written, with its largest value and the number of particles
    that lost more than half of their bonds;
  - the total energy (energy monitor) never rose above its start by more
    than 1e-3 of the column's potential energy rho g (2L)^2 L/2 (61 J/m).

Writes validation/result[-dx<spacing>].md and damage[-dx<spacing>].png (the
particles at the last time, the baffle coloured by damage).
With --check, exits 1 when a check fails.

Usage: validate.py <case> [--check]
"""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT",
                         os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from foamCloud import read_cloud, times  # noqa: E402
from foamMonitor import (case_spacing, pyplot, read_monitor,  # noqa: E402
                         run_cost)

DEFAULT_DX = 0.002
TANK = 0.584



def end_time(case):
    m = re.search(r"^endTime\s+([0-9.eE+-]+);",
                  open(os.path.join(case, "system", "controlDict")).read(),
                  re.M)
    return float(m.group(1))


def broken_bonds(case, name):
    path = os.path.join(case, name, "lagrangian", "obstacle", "brokenBonds")
    if not os.path.exists(path):
        return 0
    return len(re.findall(r"\(\s*\d+\s+\d+\s*\)", open(path).read()))


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
    inside = all(0 <= p[0] <= TANK and p[1] >= 0 for p in water)
    checks.append(("every water particle inside the tank", inside))
    nBroken = broken_bonds(case, last)
    damage = clouds["obstacle"]["damage"]
    checks.append(("bonds broke (%d)" % nBroken, nBroken > 0))
    nHalf = sum(1 for d in damage if d > 0.5)
    energy = read_monitor(case, "energy")
    rise = max(energy["total"]) - energy["total"][0]
    scale = 1000 * 9.81 * 0.292 ** 2 * 0.146 / 2
    checks.append(("total energy not growing (largest rise %.3g J/m <= %.3g)"
                   % (rise, 1e-3 * scale), rise <= 1e-3 * scale))

    ok = all(c[1] for c in checks)
    for what, good in checks:
        print("%s: %s" % ("met" if good else "MISSED", what))
    plastic = max(clouds["obstacle"].get("plasticStrain", [0]))
    print("damage: largest %.3f, %d of %d particles above 0.5; largest"
          " equivalent plastic strain %.3f" % (max(damage), nHalf,
                                               len(damage), plastic))

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
