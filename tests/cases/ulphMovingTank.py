#!/usr/bin/python3
"""Case test: a tank moved by one of OpenFOAM's solidBodyMotionFunctions.

The still-water tank (tests/cases/ulphStillWater) sways with
oscillatingLinearMotion, d(t) = A sin(w t), A = 0.01 m, w = 4 rad/s (well
below the first sloshing mode, w1 = sqrt(g k tanh(k h)) = 11.9 rad/s), for a
quarter period. Checks:
- the wall particles are where the motion puts them (1e-9 m) and carry its
  velocity A w cos(w t) (1e-6 A w);
- the water stays inside the moving tank;
- the water is carried along: far below resonance it moves nearly with the
  tank, so its centroid has moved by d(t) within 30 % of A (a wall that did
  not push would leave it at 0).
Then the tank rolls with oscillatingRotatingMotion, theta(t) = 2 deg
sin(w t) about its bottom centre: every wall particle keeps its distance to
the centre (1e-9 m) and turns by the same angle, |theta(t)| (1e-9 rad); the
water stays on the tank's side of its bottom.
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import copy_case, run_parts, run_steps, set_entry  # noqa: E402
from foamCloud import read_cloud, times  # noqa: E402

A, W = 0.01, 4.0
T_END = math.pi / (2 * W)


def moving_case(t, work, name, motion):
    """The still-water case with a moving tank, run for a quarter period;
    None when a step failed"""
    case = copy_case(os.path.join(here, "ulphStillWater"),
                     os.path.join(work, name))
    props = os.path.join(case, "constant/particleProperties")
    text = open(props).read()
    text = text.replace("slip        freeSlip;",
                        "slip        freeSlip;\n        motion\n" + motion)
    open(props, "w").write(text)
    set_entry(case, "system/controlDict", "endTime", "%.10f" % T_END)
    set_entry(case, "system/controlDict", "writeInterval", 0.1)
    return case if run_steps(t, case, label=name + ": ")[0] else None


def rolling(t, work):
    amp = 2.0
    case = moving_case(t, work, "rolling", """        {
            solidBodyMotionFunction oscillatingRotatingMotion;
            oscillatingRotatingMotionCoeffs
            {
                origin      (0.1 0 0);
                amplitude   (0 0 %g);
                omega       %g;
            }
        }""" % (amp, W))
    if not case:
        return
    t_end, last = times(case)[-1]
    theta = math.radians(amp * math.sin(W * t_end))
    wall0 = read_cloud(case, "0", "tank")
    wall1 = read_cloud(case, last, "tank")
    p0 = dict(zip(wall0["id"], wall0["positions"]))
    p1 = dict(zip(wall1["id"], wall1["positions"]))
    dr, dang, turns = 0.0, 0.0, []
    for i in p0:
        a, b = p0[i], p1[i]
        r0 = math.hypot(a[0] - 0.1, a[1])
        r1 = math.hypot(b[0] - 0.1, b[1])
        dr = max(dr, abs(r1 - r0))
        turn = math.atan2(b[1], b[0] - 0.1) - math.atan2(a[1], a[0] - 0.1)
        turn = (turn + math.pi) % (2 * math.pi) - math.pi
        dang = max(dang, abs(abs(turn) - theta))
        turns.append(turn)
    t.check("rolling: walls keep their distance to the centre (%.1e m)" % dr,
            dr < 1e-9)
    t.check("rolling: walls turned by theta(t) = %.5f rad (error %.1e)"
            % (theta, dang), dang < 1e-9)
    # The bottom passes through the centre, tilted as the walls turned:
    # no water particle below it
    tilt = sum(turns) / len(turns)
    w1 = read_cloud(case, last, "water")
    depth = max(math.tan(tilt) * (x[0] - 0.1) - x[1] for x in w1["positions"])
    t.check("rolling: no water below the tilted bottom (deepest %.1e m)"
            % depth, depth < 0)


def swaying(t, work):
    case = moving_case(t, work, "swaying", """        {
            solidBodyMotionFunction oscillatingLinearMotion;
            oscillatingLinearMotionCoeffs
            {
                amplitude   (%g 0 0);
                omega       %g;
            }
        }""" % (A, W))
    if not case:
        return

    t_end, last = times(case)[-1]
    t.check_close("ran to a quarter period", t_end, T_END, 1e-5)
    d = A * math.sin(W * t_end)
    v = A * W * math.cos(W * t_end)

    wall0 = read_cloud(case, "0", "tank")
    wall1 = read_cloud(case, last, "tank")
    p0 = dict(zip(wall0["id"], wall0["positions"]))
    p1 = dict(zip(wall1["id"], wall1["positions"]))
    err = max(max(abs(p1[i][0] - p0[i][0] - d), abs(p1[i][1] - p0[i][1]))
              for i in p0)
    t.check("walls where the motion puts them (error %.1e m)" % err,
            err < 1e-9)
    uerr = max(max(abs(u[0] - v), abs(u[1])) for u in wall1["U"])
    t.check("wall velocity A w cos(w t) (error %.1e m/s)" % uerr,
            uerr < 1e-6 * A * W)

    w0 = read_cloud(case, "0", "water")
    w1 = read_cloud(case, last, "water")
    inside = all(d <= x[0] <= 0.2 + d and x[1] >= 0
                 for x in w1["positions"])
    t.check("water inside the moving tank", inside)
    cx0 = sum(x[0] for x in w0["positions"]) / len(w0["positions"])
    cx1 = sum(x[0] for x in w1["positions"]) / len(w1["positions"])
    t.check("water carried with the tank: centroid moved %.4f m, tank"
            " %.4f m" % (cx1 - cx0, d), abs(cx1 - cx0 - d) < 0.3 * A)


if __name__ == "__main__":
    sys.exit(run_parts("ulphMovingTank", swaying, rolling))
