#!/usr/bin/python3
"""The stability suite's coarse form (tests/stability/stability.py): every
method on its hardest cases, each invariant at every written time one
check; the summary line counts the invariants met and missed.

And on the suite's baffle fracture run (ULPH + NOSB-PD, 4 mm, 0.4 s):
ParaView's reader (vtkOpenFOAMReader) loads its last time, the water and
the obstacle with their particle counts and the obstacle's damage and
plastic strain fields.

And -continue: the ULPH dam break's coarse run made again in a second
folder, its Allrun stopped (SIGTERM to its process group) once 0.2 s is
written, the suite run again with -continue: it continues the run from
its latest time (not a new Allrun), the run reaches 0.6 s in two runs
(their runCost files), and its particles at 0.6 s are those of the
uninterrupted run (the same ids, 1e-9 m: the restart is exact); a third
-continue leaves the finished run as it is.

And the depth in a wall (stability.wall_depth) on a wall with an open
end, as the dam break's tank without a lid: a particle beside the end,
past the wall's top, is in no wall; one inside it is as deep as it is."""
import glob
import math
import os
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "stability"))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "lib"))
import stability  # noqa: E402
from caseTest import CaseTest  # noqa: E402
from foamCloud import read_cloud, read_positions, times  # noqa: E402
from foamMonitor import run_cost  # noqa: E402
from readClouds import read_clouds  # noqa: E402

#: The run -continue is tried on, and where its Allrun is stopped [s]
CONTINUED = ("damBreak", "ULPH")
STOP_AT = 0.2


def open_end_wall(dx):
    """A wall as seedParticles lays it (4 layers, normals into the wall,
    wallDistance to its face) along the face x = 0 for y < H = 10 dx, and
    the layers that wrap round its open end: normals and distances from
    the end's edge (0, H)"""
    H = 10 * dx
    points, normals, distances = [], [], []
    for k in range(4):
        xs = (k + 0.5) * dx
        for j in range(14):
            ys = (j + 0.5) * dx
            if ys < H:
                n, dist = (1.0, 0.0), xs
            else:
                dist = math.hypot(xs, ys - H)
                n = (xs / dist, (ys - H) / dist)
            points.append((xs, ys, 0.0))
            normals.append((n[0], n[1], 0.0))
            distances.append(dist)
    return {"positions": points, "normal": normals,
            "wallDistance": distances}


def depth_checks(t):
    """stability.wall_depth on a wall with an open end: a particle beside
    the end, past the wall's top, is in no wall (it was 0.8 dx deep for
    the Riemann dam break's full form, which has no lid); nor is a splash
    beside the tank that flew over it (4.6 dx deep for the ISPH Liao
    plate's full form)"""
    dx = 0.001
    wall = open_end_wall(dx)
    # (what, position [dx], expected depth [dx], flown over the walls): a
    # splash that has flown over the walls and landed beside the tank is
    # behind the face without having gone through the wall; inside the
    # wall's cells it still counts
    cases = [("beside the open end, 0.9 dx above the top", (-0.3, 10.9),
              None, False),
             ("0.7 dx inside the wall", (0.7, 5.0), 0.7, False),
             ("0.3 dx in front of the face", (-0.3, 5.0), -0.3, False),
             ("gone through the wall, 0.3 dx past its last layer",
              (4.3, 5.2), 4.3, False),
             ("0.4 dx inside the wrapped end", (0.4, 10.3), "inside", False),
             ("above the wrapped end", (0.5, 14.8), None, False),
             ("beside the tank after flying over it, 0.3 dx past the last"
              " layer", (4.3, 5.2), None, True),
             ("0.7 dx inside the wall after flying over it", (0.7, 5.0),
              0.7, True)]
    for what, (a, b), expected, flown in cases:
        got = stability.wall_depth([(a * dx, b * dx, 0.0)], wall, dx,
                                   4 * dx, [flown]) / dx
        if expected is None:
            t.check("wall depth of a particle %s: %.2f dx <= 0" % (what, got),
                    got <= 0)
        elif expected == "inside":
            # The wrapped end's faces are the plane through the edge
            # across each normal: 0.50 dx here
            t.check("wall depth of a particle %s: %.2f dx > 0" % (what, got),
                    got > 0)
        else:
            t.check("wall depth of a particle %s: %.3f dx (%.1f)"
                    % (what, got, expected), abs(got - expected) < 1e-9)


def reader_checks(work, threads):
    t = CaseTest("stabilitySuite")
    runs = glob.glob(os.path.join(work, "obstacleFracture-*"))
    t.check("the baffle fracture's run is there", len(runs) == 1, str(runs))
    if len(runs) == 1:
        case = runs[0]
        last = times(case)[-1]
        clouds = read_clouds(case, last[0])
        for body in ("water", "obstacle"):
            n = len(read_positions(case, last[1], body))
            got = clouds.get(body, {"particles": -1})["particles"]
            t.check("obstacleFracture: the reader sees %s's %d particles at"
                    " %s s (%d)" % (body, n, last[1], got), got == n)
        seen = set(clouds.get("obstacle", {"arrays": {}})["arrays"])
        wanted = {"damage", "plasticStrain", "U"}
        t.check("obstacleFracture: the reader sees the obstacle's damage,"
                " plasticStrain, U", wanted <= seen, str(sorted(seen)))
    continue_checks(t, work, threads)
    depth_checks(t)
    return t.passed, t.failed


def suite(work, threads, resume=True):
    """The suite's command on one case and method, in work (-continue
    when resume)"""
    return [sys.executable, stability.__file__, "-case", CONTINUED[0],
            "-method", CONTINUED[1], "-work", work, "-threads",
            str(threads)] + (["-continue"] if resume else [])


def continue_checks(t, work, threads):
    """A run stopped and continued by -continue equals the uninterrupted
    one (the suite's own run of CONTINUED in work, on as many threads)"""
    whole = glob.glob(os.path.join(work, CONTINUED[0] + "-" + CONTINUED[1]))
    t.check("the uninterrupted %s %s run is there" % CONTINUED,
            len(whole) == 1, str(whole))
    if len(whole) != 1:
        return
    again = os.path.join(work, "continued")
    shutil.rmtree(again, ignore_errors=True)
    os.makedirs(again)
    case = os.path.join(again, os.path.basename(whole[0]))
    proc = subprocess.Popen(suite(again, threads, resume=False),
                            stdout=subprocess.DEVNULL,
                            stderr=subprocess.STDOUT, start_new_session=True)
    stopped = None
    try:
        while proc.poll() is None:
            done = [v for v, _ in times(case)] if os.path.isdir(case) \
                else []
            if done and done[-1] >= STOP_AT - 1e-9:
                stopped = done[-1]
                break
            time.sleep(0.05)
    finally:
        try:
            os.killpg(proc.pid, signal.SIGTERM)
        except ProcessLookupError:
            pass
        proc.wait()
    t.check("-continue: the first run stopped at %s s, before its end"
            % stopped, stopped is not None and stopped < 0.6 - 1e-9)
    if stopped is None:
        return
    out = subprocess.run(suite(again, threads), capture_output=True,
                         text=True)
    logs = glob.glob(os.path.join(case, "log.*.continued0"))
    t.check("-continue: the run is continued by its solver (%s), not made"
            " again" % [os.path.basename(f) for f in logs],
            len(logs) == 1 and os.path.isfile(os.path.join(case,
                                                           "Allrun.log")),
            out.stdout[-2000:])
    cost = run_cost(case)
    t.check("-continue: two runs (runCost files: %d), the last one"
            " complete" % cost["runs"], cost["runs"] == 2
            and cost["completed"], str(cost))
    last = times(whole[0])[-1][1]
    if times(case)[-1][1] != last:
        t.check("-continue: the continued run reached %s s" % last, False,
                "last time %s" % times(case)[-1][1])
        return
    a, b = read_cloud(whole[0], last, "water"), read_cloud(case, last,
                                                          "water")
    pos = dict(zip(a["id"], a["positions"]))
    same = sorted(a["id"]) == sorted(b["id"]) and len(pos) > 0
    diff = max((max(abs(p[c] - pos[i][c]) for c in range(3))
                for i, p in zip(b["id"], b["positions"]) if i in pos),
               default=float("inf"))
    t.check("-continue: its water at %s s is the uninterrupted run's: the"
            " same %d particles, largest difference %.3g m < 1e-9"
            % (last, len(b["id"]), diff), same and diff < 1e-9)
    before = len(glob.glob(os.path.join(case, "log.*.continued*")))
    out = subprocess.run(suite(again, threads), capture_output=True,
                         text=True)
    t.check("-continue: a finished run is only checked again (no solver"
            " run), its invariants met", before == len(glob.glob(
                os.path.join(case, "log.*.continued*")))
            and out.returncode == 0, out.stdout[-2000:])


if __name__ == "__main__":
    argv = sys.argv[1:]
    chosen = "-case" in argv or "-method" in argv
    sys.exit(stability.main(argv, "stabilitySuite",
                            None if chosen else reader_checks))
