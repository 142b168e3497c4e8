#!/usr/bin/env python3
"""Collects the VOF dam-break fronts (front-n*.dat beside this script) into
result.md and front.png: each against the experiment of Martin and Moyce
(1952) (the damBreak tutorial's validation/martinMoyce1952.dat), and the
change between successive resolutions. The finest default front goes to
the tutorial as validation/interFoamFront.dat, the finest one with -sigma 0
alone (no surface tension, as the ULPH solver) as
interFoamFrontNoSurfaceTension.dat: the Navier-Stokes references its
validate.py reports the ULPH front against.
"""
import glob
import math
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "etc", "python"))
from foamMonitor import interp, pyplot  # noqa: E402
tutorial = os.path.join(here, "..", "..", "tutorials", "ulphPdFoam",
                        "damBreak", "validation")
# Front speed over the experiment's straight part, ending before the
# fastest front (interFoam without surface tension) reaches the far wall
# (T = 2.26)
T_SPEED = (1.44, 2.07)
WALL = 4.0 - 1e-3          # x/H of a front at the far wall
# The finest run of these variants goes to the tutorial's validation/
TUTORIAL_FRONTS = [
    ("", "interFoamFront.dat", "water's surface tension"),
    ("-sigma0", "interFoamFrontNoSurfaceTension.dat", "no surface tension"),
]


def table(path):
    rows, head = [], []
    for line in open(path):
        if line.startswith("#"):
            head.append(line[1:].strip())
        elif line.strip():
            rows.append(tuple(float(v) for v in line.split()[:2]))
    return head, rows


def at(rows, T):
    """x/H of a front's rows at T (linear; every time asked lies inside)"""
    return interp(T, [r[0] for r in rows], [r[1] for r in rows])


def rms(rows, ref):
    """RMS difference [H] at the experiment's times before the front
    reaches the far wall (as the tutorial's validate.py), and their number"""
    d = [x - X for x, X in ((at(rows, T), X) for T, X in ref) if x < WALL]
    return math.sqrt(sum(v*v for v in d)/len(d)), len(d)


def key(path):
    """(variant, n) of front-n<n>[-sigma<s>][-nu<nu>].dat: variant is the
    suffix after n ("" for the default fluid)"""
    m = re.match(r"front-n(\d+)(.*)\.dat$", os.path.basename(path))
    return (m.group(2), int(m.group(1)))


def variant(suffix):
    """sigma [N/m] and water's nu [m^2/s] of a variant suffix
    ([-sigma<s>][-nu<nu>], as Allrun names them)"""
    m = re.match(r"(?:-sigma(.+?))?(?:-nu(.+))?$", suffix)
    return (m.group(1) or "0.072", m.group(2) or "1e-6")


def main():
    _, ref = table(os.path.join(tutorial, "martinMoyce1952.dat"))
    files = sorted(glob.glob(os.path.join(here, "front-n*.dat")), key=key)
    runs = []
    for f in files:
        head, rows = table(f)
        suffix, n = key(f)
        runs.append((suffix, n, head[0], rows))

    out = ["# Dam break by interFoam (VOF): the Navier-Stokes front", "",
           "Command: `benchmarks/damBreakVof/Allrun -n <cells per H> "
           "[-np <processes>] [-sigma <N/m>] [-nu <m^2/s>]`, one line per "
           "run (front-n*.dat).",
           "Square column H = 0.057 m, tank 4H x 2H open at the top, water and "
           "air (nu 1e-6 and 1.5e-5 m^2/s), no-slip walls, laminar, "
           "surface tension 0.072 N/m, unless stated; maxCo 0.25. "
           "Front: foremost point of the alpha = 0.5 contour, every 2.5 ms.",
           "",
           "| cells per H | sigma [N/m] | water nu [m^2/s] | run | "
           "RMS vs experiment (points before the far wall) | "
           "speed T = %.2f-%.2f [sqrt(gH)] | " % T_SPEED
           + " | ".join("x/H at T = %.2f" % T for T, _ in ref[1::4]) + " |",
           "|---|---|---|---|---|---|" + "---|"*len(ref[1::4])]
    speeds = []
    for suffix, n, head, rows in runs:
        speed = (at(rows, T_SPEED[1]) - at(rows, T_SPEED[0])) \
            / (T_SPEED[1] - T_SPEED[0])
        cost = head.split(": ", 1)[1] if ": " in head else head
        out.append("| %d | %s | %s | %s | %.4f H (%d) | %.3f | " % (
            (n,) + variant(suffix) + (cost,) + rms(rows, ref) + (speed,))
            + " | ".join("%.3f" % at(rows, T) for T, _ in ref[1::4]) + " |")
        speeds.append(speed)
    exp_speed = (at(ref, T_SPEED[1]) - at(ref, T_SPEED[0])) \
        / (T_SPEED[1] - T_SPEED[0])
    out.append("| experiment | | | | | %.3f | " % exp_speed
               + " | ".join("%.3f" % X for _, X in ref[1::4]) + " |")

    # Change between successive resolutions (same sigma)
    out += ["", "Largest change of the front between successive resolutions "
            "at the experiment's times:", ""]
    for (s0, n0, _, r0), (s1, n1, _, r1) in zip(runs, runs[1:]):
        if s0 == s1:
            d = max(abs(at(r1, T) - at(r0, T)) for T, _ in ref)
            out.append("- n = %d to %d%s: %.3f H" % (
                n0, n1, " (sigma %s, nu %s)" % variant(s0) if s0 else "",
                d))

    for suffix, name, what in TUTORIAL_FRONTS:
        finest = [r for r in runs if r[0] == suffix]
        if not finest:
            continue
        _, n, head, rows = finest[-1]
        with open(os.path.join(tutorial, name), "w") as f:
            f.write("# Surge front of the square column by interFoam (VOF), "
                    "%s, n = %d cells per H\n" % (what, n))
            f.write("# Written by benchmarks/damBreakVof/Allrun (result.py): "
                    "%s\n" % head)
            f.write("# Foremost point of the alpha.water = 0.5 contour\n")
            f.write("# T = t sqrt(g/H)   x_front/H\n")
            for T, X in rows:
                f.write("%.5f %.5f\n" % (T, X))
        out += ["", "Reference for the tutorial (%s): n = %d written to "
                "tutorials/ulphPdFoam/damBreak/validation/%s." % (what, n,
                                                                 name)]

    plt = pyplot()
    if plt:
        fig, ax = plt.subplots(figsize=(6, 4.5))
        for suffix, n, _, rows in runs:
            ax.plot([r[0] for r in rows], [r[1] for r in rows],
                    "--" if suffix else "-",
                    label="interFoam n = %d%s" % (
                        n, ", sigma %s, nu %s" % variant(suffix)
                        if suffix else ""))
        ax.plot([r[0] for r in ref], [r[1] for r in ref], "ko",
                label="Martin & Moyce (1952)")
        ax.set_xlabel("T = t sqrt(g/H)")
        ax.set_ylabel("x/H")
        ax.set_xlim(0, 2.7)
        ax.set_ylim(1, 4.05)
        ax.legend()
        ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(here, "front.png"), dpi=100)
        out += ["", "Plot: front.png."]
    else:
        out += ["", "(matplotlib missing: no plot)"]

    text = "\n".join(out) + "\n"
    with open(os.path.join(here, "result.md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()
