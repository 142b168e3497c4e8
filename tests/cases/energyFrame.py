#!/usr/bin/python3
"""The energy monitor seen from a moving tank (energy { frame tank; }):
two clouds the tank does not touch, one at rest and one falling freely
(particleFoam, kinematic bodies), and a ghost-wall tank rolled by 30
degrees at 10 rad/s. Seen from the tank their kinetic energies change
(the frame turns under them) and the frame's motion does work; the total
less that work must change exactly as the inertial total does (the
kinematic integrator's own drift, first order in the step), and a
restart must continue the frame's work."""
import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))), "lib"))
from caseTest import (copy_case, project_dir, run, run_parts,  # noqa: E402
                      run_steps, set_entry)

BODIES = """bodies
{
    resting { model kinematic; density 1000; }
    falling
    {
        model kinematic; density 1000;
        effects { gravity { value (0 -9.81 0); } }
    }
    tank
    {
        model ghostWall; density 1000; slip noSlip;
        motion
        {
            solidBodyMotionFunction oscillatingRotatingMotion;
            oscillatingRotatingMotionCoeffs
            {
                origin (0.05 0.1 0); amplitude (0 0 30); omega 10;
            }
        }
    }
}
monitors
{
    inertial { type energy; bodies (resting falling); }
    tankFrame { type energy; bodies (resting falling); frame tank; }
}
"""

SEEDS = """bodies
{
    resting
    {
        spacing 0.002; density 1000;
        region { type box; min (0.03 0.14 -1); max (0.07 0.18 1); }
    }
    falling
    {
        spacing 0.002; density 1000;
        region { type box; min (0.03 0.1 -1); max (0.07 0.12 1); }
    }
    tank
    {
        spacing 0.002; density 1000; normal (0 -1 0);
        region { type box; min (0 0 -1); max (0.1 0.008 1); }
    }
}
"""


def replace_bodies(path, text):
    with open(path) as f:
        s = f.read()
    with open(path, "w") as f:
        f.write(s[:s.index("bodies")] + text)


def rows(case, name, start="0"):
    path = os.path.join(case, "postProcessing", name, start, name + ".dat")
    with open(path) as f:
        return [[float(v) for v in line.split()] for line in f
                if not line.startswith("#")]


def make(work, name):
    case = copy_case(os.path.join(project_dir, "tutorials", "particleFoam",
                                  "freeFall"), os.path.join(work, name))
    for f in ("Allrun", "Allclean"):
        os.remove(os.path.join(case, f))
    shutil.rmtree(os.path.join(case, "validation"))
    replace_bodies(os.path.join(case, "constant", "particleProperties"),
                   BODIES)
    replace_bodies(os.path.join(case, "system", "seedParticlesDict"), SEEDS)
    for key, value in (("endTime", 0.1), ("deltaT", 5e-5),
                       ("maxDeltaT", 5e-5), ("writeInterval", 0.05)):
        set_entry(case, "system/controlDict", key, value)
    return case


def balance(t, work):
    case = make(work, "frame")
    ok, _ = run_steps(t, case, ("blockMesh", "seedParticles", "particleFoam"))
    if not ok:
        return
    frame, inertial = rows(case, "tankFrame"), rows(case, "inertial")
    t.check_equal("both monitors sample every step", len(frame),
                  len(inertial))
    scale = max(r[1] for r in frame)
    t.check("seen from the tank the resting cloud moves (largest kinetic"
            " energy %.3g J/m > 0.01)" % scale, scale > 0.01)
    work_done = max(abs(r[-2]) for r in frame)
    t.check("the frame's motion does work (largest |work| %.3g J/m > 0.1 x"
            " %.3g)" % (work_done, scale), work_done > 0.1 * scale)
    drift = max(abs((a[-1] - frame[0][-1]) - (b[-1] - inertial[0][-1]))
                for a, b in zip(frame, inertial))
    t.check("the total less the frame's work changes as the inertial"
            " total (largest difference %.2e J/m < 1e-4 x %.3g)"
            % (drift, scale), drift < 1e-4 * scale)

    # A restart from 0.05 s continues the frame's work
    last = frame[-1]
    shutil.rmtree(os.path.join(case, "0.1"))
    set_entry(case, "system/controlDict", "startFrom", "latestTime")
    code, out = run(["particleFoam"], case)
    t.check("the restart from 0.05 s runs", code == 0, out[-1500:])
    if code != 0:
        return
    again = rows(case, "tankFrame", "0.05")[-1]
    t.check("the restarted run ends with the uninterrupted run's work and"
            " total (%.12g, %.12g vs %.12g, %.12g)"
            % (again[-2], again[-1], last[-2], last[-1]),
            abs(again[-2] - last[-2]) < 1e-12 * scale
            and abs(again[-1] - last[-1]) < 1e-12 * scale)


def bad_frame(t, work):
    case = make(work, "badFrame")
    path = os.path.join(case, "constant", "particleProperties")
    with open(path) as f:
        s = f.read()
    with open(path, "w") as f:
        f.write(s.replace("frame tank;", "frame resting;"))
    ok, _ = run_steps(t, case, ("blockMesh", "seedParticles"))
    if not ok:
        return
    code, out = run(["particleFoam"], case)
    t.check("a frame that is not a moving wall stops the run", code != 0)
    t.check("the error names the keyword and what was expected",
            "frame resting" in out and "moving wall" in out, out[-800:])


if __name__ == "__main__":
    sys.exit(run_parts("energyFrame", balance, bad_frame))
