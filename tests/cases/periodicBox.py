#!/usr/bin/python3
"""Case test: periodic directions of a scene (constant/particleProperties
'periodic'), on the freeFall tutorial (a kinematic drop under gravity over
a fixed floor, 2D, particleFoam):

- the drop falls through the bottom of a y-periodic box [0, 0.2) twice in
  0.3 s; at every written time each particle is where the same run without
  the periodic entry (and an escape box that lets it fall) puts it, moved
  by a whole number of periods (1e-9 m), and within the box but for the
  last step's fall (positions are wrapped at the start of each step); the
  log names the periodic direction; the fixed floor does not move;
- bad input, each a FOAM FATAL IO ERROR naming particleProperties, the
  entry and what was expected: an unknown direction (z in 2D), max <= min,
  bounds that are not two numbers, a period shorter than two kernel
  supports, a fixed body outside the period.
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import copy_case, project_dir, run, run_parts  # noqa: E402

sys.path.insert(0, os.path.join(project_dir, "etc", "python"))
from foamCloud import read_positions, times  # noqa: E402

FREEFALL = os.path.join(project_dir, "tutorials/particleFoam/freeFall")
PP = "constant/particleProperties"
L = 0.2


def set_up(work, name, extra, end="0.3", kernel=False):
    case = copy_case(FREEFALL, os.path.join(work, name))
    path = os.path.join(case, PP)
    text = open(path).read()
    if kernel:
        text = text.replace(
            "model       kinematic;",
            "model       kinematic;\n        kernel { type wendlandC2;"
            " smoothingLengthRatio 1.3; }", 1)
    text = text.replace("vtp         no;", "vtp         no;\n" + extra)
    open(path, "w").write(text)
    cd = os.path.join(case, "system/controlDict")
    text = open(cd).read()
    text = text.replace("endTime         0.1;", "endTime         %s;" % end)
    text = text.replace("writeInterval   0.02;", "writeInterval   0.1;")
    open(cd, "w").write(text)
    for cmd in ("blockMesh", "seedParticles"):
        code, out = run([cmd], case)
        if code != 0:
            raise RuntimeError(cmd + " failed:\n" + out[-2000:])
    return case


def falls_through(t, work):
    box = "escapeBox { min (-1 -2 -1); max (1 1 1); }\n"
    free = set_up(work, "free", box)
    per = set_up(work, "periodic", "periodic { y (0 0.2); }\n")
    for case in (free, per):
        code, out = run(["particleFoam"], case)
        t.check("particleFoam runs (%s)" % os.path.basename(case), code == 0,
                out[-2000:])
        if case == per:
            t.check("the log names the periodic direction",
                    "periodic: y [0, 0.2)" in out, out[:3000])
    written = [name for _, name in times(per) if name != "0"]
    t.check_equal("written times", written,
                  [name for _, name in times(free) if name != "0"])
    dt, g = 0.001, 9.81
    for tm in written:
        a = read_positions(free, tm, "drop")
        b = read_positions(per, tm, "drop")
        worst = 0.0
        periods = set()
        inside = True
        # The last step's fall is not wrapped yet: |U| dt of the end time
        slack = g * float(tm) * dt + 1e-12
        for p, q in zip(a, b):
            k = round((p[1] - q[1]) / L)
            periods.add(k)
            worst = max(worst, abs(p[0] - q[0]),
                        abs(p[1] - q[1] - k * L))
            inside = inside and -slack <= q[1] < L
        t.check("time %s: the free fall moved by whole periods (%s), "
                "worst %.3g m" % (tm, sorted(periods), worst),
                worst < 1e-9)
        t.check("time %s: the drop is in the period" % tm, inside)
        if tm == written[-1]:
            t.check("the drop went through the bottom twice",
                    min(periods) <= -2, str(sorted(periods)))
    f0 = read_positions(per, "0", "floor")
    f1 = read_positions(per, written[-1], "floor")
    t.check("the fixed floor does not move", f0 == f1)


BAD = [
    ("unknown direction", "periodic { z (0 1); }\n", False,
     ["'z'", "expected one of"]),
    ("max <= min", "periodic { y (0.2 0.2); }\n", False,
     ["'y'", "expected max > min"]),
    ("bounds not two numbers", "periodic { x (0 0.05 0.1); }\n", False,
     ["'x'", "expected its bounds (min max)"]),
    ("not a dictionary", "periodic (0 1);\n", False,
     ["'periodic'", "expected a dictionary"]),
    ("period below two supports", "periodic { y (0 0.01); }\n", True,
     ["'y'", "expected more than two kernel supports", "drop"]),
    ("fixed body outside the period", "periodic { y (0.005 0.2); }\n", False,
     ["floor", "outside the period", "expected every particle"]),
]


def bad_input(t, work):
    for i, (what, extra, kernel, words) in enumerate(BAD):
        case = set_up(work, "bad%d" % i, extra, end="0.002", kernel=kernel)
        code, out = run(["particleFoam"], case)
        t.check("%s: fails" % what, code != 0, out[-1500:])
        ok = ("FOAM FATAL IO ERROR" in out and "particleProperties" in out
              and all(w in out for w in words)
              and "Segmentation" not in out)
        t.check("%s: FATAL IO ERROR naming the file, %s" % (what, words),
                ok, out[-1500:])


if __name__ == "__main__":
    sys.exit(run_parts("periodicBox", falls_through, bad_input))
