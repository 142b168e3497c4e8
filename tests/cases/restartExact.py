#!/usr/bin/python3
"""Case test: a restart continues exactly, for every solver and coupling.

Each case is a tutorial (or test case) made coarse and short, with the
adaptive time step on, written in ascii at the default precision (the
clouds are written at full precision whatever writePrecision says) and
binary for one of them. It runs straight to t1 with a write at tm, and
again stopped at tm and continued with startFrom latestTime. Checks, per
case:

- every field of every body at t1 equal to 1e-12 relative (largest
  difference over the particles, matched by id, divided by the largest
  value of that field; positions by the body's extent);
- every monitor file (postProcessing/<name>/<start>/*.dat) of the
  continued run: its rows equal the straight run's rows at the same times
  to 1e-12 relative per column (the energy included: it continues, not
  restarts from zero);
- the same number of time steps.

Cases: particleFoam (freeFall), ulphPdFoam fluid only with fixed walls
(damBreak) and moving walls (sloshingTank), ulphPd couplings with a
damped plate (ulphPdHydrostatic), an elastic gate (with the solid's step
acceleration in its ghosts, too) and breaking bonds (obstacleFracture), nosbPd alone (cantileverBeam, damped), riemannSphFoam's
Riemann fluid with its acoustic steps (riemannDamBreak) and with open
boundaries that add and remove particles (riemannChannel: the ids, the
counters and the mass through them continue, and the body's spacing does
not depend on its particle count), isphTlsphFoam
TLSPH with the Verlet (oscillatingPlate) and RK4 integrators (clampedBeam,
damped).
"""
import math
import os
import re
import shutil
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import (copy_case, project_dir, run, run_parts,  # noqa: E402
                      set_entry)

sys.path.insert(0, os.path.join(project_dir, "etc", "python"))
from foamCloud import read_cloud  # noqa: E402
from foamMonitor import read_rows  # noqa: E402

CD = "system/controlDict"
PP = "constant/particleProperties"
TOL = 1e-12

# name: (source, resolution file and line, t1, tm, solver, extra entries)
CASES = {
    "freeFall": ("tutorials/particleFoam/freeFall", None, 0.1, 0.05,
                 "particleFoam", []),
    "damBreak": ("tutorials/ulphPdFoam/damBreak",
                 ("resolution", "dx 0.004;"), 0.02, 0.01, "ulphPdFoam", []),
    "sloshingTank": ("tutorials/ulphPdFoam/sloshingTank",
                     ("resolution", "dx 0.04;"), 0.1, 0.05, "ulphPdFoam",
                     []),
    "ulphPdHydrostatic": ("tests/cases/ulphPdHydrostatic", None, 0.004,
                          0.002, "ulphPdFoam", []),
    "elasticGate": ("tutorials/ulphPdFoam/elasticGate",
                    ("resolution", "dx 0.0025;"), 0.004, 0.002,
                    "ulphPdFoam", []),
    "elasticGateStepAcceleration": ("tutorials/ulphPdFoam/elasticGate",
                                    ("resolution", "dx 0.0025;"), 0.004,
                                    0.002, "ulphPdFoam",
                                    [(PP, "coupling/solidAcceleration",
                                      "step")]),
    "obstacleFracture": ("tutorials/ulphPdFoam/obstacleFracture",
                         ("resolution", "dx 0.004;"), 0.01, 0.005,
                         "ulphPdFoam",
                         [(PP, "bodies/obstacle/failure/criticalStretch",
                           2e-5)]),
    "cantileverBeam": ("tutorials/ulphPdFoam/cantileverBeam",
                       ("resolution", "dx 0.02;"), 0.006, 0.003,
                       "ulphPdFoam", []),
    "oscillatingPlate": ("tutorials/isphTlsphFoam/oscillatingPlate",
                         ("runParameters", "dx 0.002;"), 0.01, 0.005,
                         "isphTlsphFoam", [(CD, "writeFormat", "binary")]),
    "riemannDamBreak": ("tutorials/riemannSphFoam/damBreak",
                        ("resolution", "dx 0.004;"), 0.04, 0.02,
                        "riemannSphFoam", []),
    "riemannChannel": ("tests/cases/riemannChannel", None, 0.3, 0.15,
                       "riemannSphFoam",
                       []),
    "clampedBeam": ("tutorials/isphTlsphFoam/clampedBeam",
                    ("runParameters", "dx 0.004;"), 0.0004, 0.0002,
                    "isphTlsphFoam", []),
}


def set_up(name, case):
    source, resolution, t1, tm, solver, entries = CASES[name]
    src = os.path.join(project_dir, source)
    copy_case(src, case)
    shutil.rmtree(os.path.join(case, "validation"), ignore_errors=True)
    if resolution:
        with open(os.path.join(case, "system", resolution[0]), "w") as f:
            f.write(resolution[1] + "\n")
    allrun = os.path.join(src, "Allrun")
    if os.path.exists(allrun):
        # A motion table that the tutorial's Allrun writes (its awk command)
        m = re.search(r"^awk 'BEGIN.*?> constant/tankMotion.dat", open(
            allrun).read(), re.S | re.M)
        if m:
            code, out = run(["bash", "-c", m.group(0)], case)
            if code != 0:
                raise RuntimeError(out)
    for key, value in (("endTime", t1), ("writeInterval", tm),
                       ("writeControl", "adjustableRunTime"),
                       ("adjustTimeStep", "yes"), ("purgeWrite", 0),
                       ("startFrom", "latestTime")):
        set_entry(case, CD, key, value)
    for dict_file, key, value in entries:
        set_entry(case, dict_file, key, value)
    for cmd in ("blockMesh", "seedParticles"):
        code, out = run([cmd], case)
        if code != 0:
            raise RuntimeError("%s: %s failed\n%s" % (name, cmd, out[-1500:]))
    return solver, t1, tm


def flat(values):
    return [x for v in values for x in (v if isinstance(v, list) else [v])]


def cloud_difference(a, b, time):
    """Largest relative difference per body/field at a time (particles by
    id), and the bodies present on one side only"""
    worst = {}
    bodies = sorted(os.listdir(os.path.join(a, time, "lagrangian")))
    for body in bodies:
        ca = read_cloud(a, time, body)
        cb = read_cloud(b, time, body)
        ids_a = ca.get("id", list(range(len(ca["positions"]))))
        ids_b = cb.get("id", list(range(len(cb["positions"]))))
        if sorted(ids_a) != sorted(ids_b) or sorted(ca) != sorted(cb):
            worst[body] = math.inf
            continue
        where = {i: k for k, i in enumerate(ids_b)}
        order = [where[i] for i in ids_a]
        n = len(ids_a)
        for f in ca:
            va = ca[f]
            if len(va) == n and len(cb[f]) == n:
                vb = [cb[f][k] for k in order]
            else:
                vb = cb[f]          # not one value per particle: as stored
            if f == "positions":
                lo = [min(c) for c in zip(*va)]
                hi = [max(c) for c in zip(*va)]
                scale = max(h - l for h, l in zip(hi, lo))
            else:
                scale = max((abs(x) for x in flat(va)), default=0.0)
            diff = max((abs(x - y) for x, y in zip(flat(va), flat(vb))),
                       default=0.0)
            worst[body + "/" + f] = diff / scale if scale else diff
    return worst


def monitor_difference(a, b, tm):
    """Per monitor file of the continued run: rows compared with the
    straight run's at the same times (a monitor sampling every n steps
    also writes the last step of a run, and the restart's start: rows at
    the stop time tm the straight run may lack). Returns {file: worst
    relative difference}, and the rows the straight run lacks"""
    worst = {}
    missing = []
    base_b = os.path.join(b, "postProcessing")
    for name in sorted(os.listdir(base_b)) if os.path.isdir(base_b) else []:
        if name == "runCost":
            continue            # wall times differ
        for start in os.listdir(os.path.join(base_b, name)):
            for f in os.listdir(os.path.join(base_b, name, start)):
                if not f.endswith(".dat"):
                    continue
                rows_b = read_rows(os.path.join(base_b, name, start, f))
                path_a = os.path.join(a, "postProcessing", name, "0", f)
                rows_a = read_rows(path_a) if os.path.exists(path_a) else []
                by_time = {r[0]: r for r in rows_a}
                key = "%s/%s/%s" % (name, start, f)
                w = 0.0
                cols = len(rows_a[0]) if rows_a else 0
                scale = [max(abs(r[c]) for r in rows_a) or 1.0
                         for c in range(cols)]
                for r in rows_b:
                    ra = by_time.get(r[0])
                    if ra is None and abs(r[0] - tm) <= 1e-12 * tm:
                        continue    # the stop's last or the start's row
                    if ra is None or len(ra) != len(r):
                        missing.append("%s t = %g" % (key, r[0]))
                        continue
                    for c in range(1, len(r)):
                        w = max(w, abs(r[c] - ra[c]) / scale[c])
                worst[key] = w
    return worst, missing


def monitors(case):
    base = os.path.join(case, "postProcessing")
    return [m for m in os.listdir(base) if m != "runCost"] \
        if os.path.isdir(base) else []


def restart_case(name):
    def part(t, work):
        straight = os.path.join(work, name + ".straight")
        solver, t1, tm = set_up(name, straight)
        cont = os.path.join(work, name + ".continued")
        shutil.copytree(straight, cont)

        code, out_s = run([solver], straight)
        t.check("%s: straight run succeeds" % name, code == 0, out_s[-1500:])
        set_entry(cont, CD, "endTime", tm)
        code, out_1 = run([solver], cont)
        t.check("%s: run to %g succeeds" % (name, tm), code == 0,
                out_1[-1500:])
        set_entry(cont, CD, "endTime", t1)
        code, out_2 = run([solver], cont)
        t.check("%s: continued run succeeds" % name, code == 0,
                out_2[-1500:])
        if code != 0:
            return

        steps = [o.count("\nTime = ") for o in (out_s, out_1, out_2)]
        t.check_equal("%s: same number of steps (%d + %d)"
                      % (name, steps[1], steps[2]), steps[1] + steps[2],
                      steps[0])
        end = "%g" % t1
        worst = cloud_difference(straight, cont, end)
        bad = {k: "%.1e" % v for k, v in worst.items() if v > TOL}
        t.check("%s: fields at %s equal to %g (%d fields, largest %.1e)"
                % (name, end, TOL, len(worst), max(worst.values())),
                not bad, str(bad))
        if name == "obstacleFracture":
            damage = read_cloud(straight, end, "obstacle")["damage"]
            t.check("%s: bonds broke (largest damage %.3g)"
                    % (name, max(damage)), max(damage) > 0)
        mon, missing = monitor_difference(straight, cont, tm)
        bad = {k: "%.1e" % v for k, v in mon.items() if v > TOL}
        t.check("%s: monitor series continue the straight run's (%s)"
                % (name, ", ".join(sorted(mon)) or "none"),
                not bad and not missing and (mon or not monitors(straight)),
                str(bad) + " " + str(missing[:5]))
    part.__name__ = name
    return part


if __name__ == "__main__":
    names = sys.argv[1:] or list(CASES)
    sys.exit(run_parts("restartExact", *[restart_case(n) for n in names]))
