#!/usr/bin/python3
"""Case test: restarts and writes that survive a crash.

- Kill test (freeFall, particleFoam, adaptive step, a write every step
  with purgeWrite 5, vtp output, an energy monitor): the run is killed
  (SIGKILL) at random moments 20 times, each time continued with
  startFrom latestTime. After every kill each time directory left is
  complete (every field its restart manifest lists, with the particle
  count of entries) and no temporary directory is visible to the time
  scan; the .pvd collections parse and list only .vtp files that exist.
  The continued run ends bitwise equal to an uninterrupted one, and every
  energy line written by the pieces equals the uninterrupted run's at the
  same time.
- Coupled restart (ulphPdHydrostatic: ulph water, nosbPd plate, ghostWall
  tank, ulphPd coupling, adaptive step): stopped at a write time and
  continued it is bitwise equal to the uninterrupted run, positions,
  velocities, stresses and monitor series, when the plate has no
  velocity-dependent force. With the plate's damping the restart is not
  exact yet (nosbPd restarts its Verlet acceleration from the full-step
  velocity; see the restart-state list of issue 23): run and reported as
  XFAIL, not counted.
"""
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import time
import xml.dom.minidom

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import (CaseTest, copy_case, project_dir, run,  # noqa: E402
                      scratch, set_entry)

sys.path.insert(0, os.path.join(project_dir, "etc", "python"))
from foamCloud import read_cloud, read_list, times  # noqa: E402
from foamMonitor import read_rows as table  # noqa: E402

FREEFALL = os.path.join(project_dir, "tutorials/particleFoam/freeFall")
HYDROSTATIC = os.path.join(here, "ulphPdHydrostatic")
CD = "system/controlDict"
PP = "constant/particleProperties"
KILLS = 20


def manifest_problems(case, name):
    """What is wrong with a written time directory (its manifest's fields
    and files), as a list of strings"""
    path = os.path.join(case, name, "uniform", "restartManifest")
    if not os.path.exists(path):
        return ["%s: no restart manifest" % name]
    text = open(path).read()
    problems = []
    bodies = re.search(r"\nbodies\s*\{(.*)\n\}\s*\nfiles", text, re.S)
    if not bodies:
        return ["%s: manifest without bodies" % name]
    for body, n, fields in re.findall(
            r"\n    (\w+)\s*\{\s*particles\s+(\d+);\s*fields\s*\{([^}]*)\}",
            bodies.group(1)):
        for field, cls in re.findall(r"(\w+)\s+([\w<>]+);", fields):
            f = os.path.join(case, name, "lagrangian", body, field)
            try:
                if len(read_list(f)) != int(n):
                    problems.append("%s: %s/%s has the wrong length"
                                    % (name, body, field))
            except Exception as e:     # missing, empty, truncated
                problems.append("%s: %s/%s: %s" % (name, body, field, e))
    files = re.search(r"\nfiles\s+\d*\s*\(([^)]*)\)", text)
    for f in re.findall(r'"([^"]+)"', files.group(1) if files else ""):
        if not os.path.exists(os.path.join(case, name, f)):
            problems.append("%s: %s missing" % (name, f))
    return problems


def pvd_problems(case):
    problems = []
    vtk = os.path.join(case, "VTK")
    if not os.path.isdir(vtk):
        return problems
    for f in os.listdir(vtk):
        if not f.endswith(".pvd"):
            continue
        try:
            doc = xml.dom.minidom.parse(os.path.join(vtk, f))
        except Exception as e:
            problems.append("%s does not parse: %s" % (f, e))
            continue
        for d in doc.getElementsByTagName("DataSet"):
            if not os.path.exists(os.path.join(vtk, d.getAttribute("file"))):
                problems.append("%s lists a missing %s"
                                % (f, d.getAttribute("file")))
    return problems


def energy_rows(case):
    """Every complete line of every energy.dat below postProcessing, by
    its time column"""
    rows = {}
    base = os.path.join(case, "postProcessing", "energy")
    for start in os.listdir(base) if os.path.isdir(base) else []:
        path = os.path.join(base, start, "energy.dat")
        for line in open(path).read().split("\n")[:-1]:
            if line and not line.startswith("#"):
                rows.setdefault(line.split()[0], []).append(line)
    return rows


def freefall_case(work, name):
    case = copy_case(FREEFALL, os.path.join(work, name))
    for cmd in (["blockMesh"], ["seedParticles"]):
        code, out = run(cmd, case)
        if code != 0:
            raise RuntimeError(out[-1500:])
    for key, value in (("adjustTimeStep", "yes"), ("maxCo", 0.1),
                       ("writeControl", "timeStep"), ("writeInterval", 1),
                       ("purgeWrite", 5), ("startFrom", "latestTime")):
        set_entry(case, CD, key, value)
    set_entry(case, PP, "vtp", "yes")
    with open(os.path.join(case, PP), "a") as f:
        f.write("\nmonitors { energy { type energy; interval 3; } }\n")
    return case


def test_kills(t, work):
    straight = freefall_case(work, "straight")
    set_entry(straight, CD, "maxCo", 0.02)      # more steps, more writes
    killed = os.path.join(work, "killed")
    shutil.copytree(straight, killed)
    start = time.time()
    code, out = run(["particleFoam"], straight)
    duration = time.time() - start
    t.check("uninterrupted run succeeds", code == 0, out[-1500:])

    random.seed(23)
    problems = []
    hidden_seen = 0
    removed = 0
    kills = 0
    last = times(straight)[-1][1]
    for k in range(5 * KILLS):
        if times(killed)[-1][1] == last or kills >= KILLS:
            break
        log = open(os.path.join(killed, "log.%03d" % k), "w")
        p = subprocess.Popen(["particleFoam"], cwd=killed, stdout=log,
                             stderr=subprocess.STDOUT)
        # Kill within the start-up or up to a thirtieth of the run later,
        # so that the kills fall anywhere (also in writes) and at least
        # KILLS of them before the end, however fast the machine (with a
        # fifteenth, 18 kills ended the run where the uninterrupted run
        # that set the duration shared the machine with other work)
        time.sleep(0.1 + random.uniform(0, duration / 30))
        if p.poll() is None:
            p.send_signal(signal.SIGKILL)
            kills += 1
        p.wait()
        log.close()
        text = open(os.path.join(killed, "log.%03d" % k)).read()
        if "FOAM FATAL" in text:
            problems.append("run %d failed: %s" % (k, text[-800:]))
            break
        removed += text.count("Removing .incomplete.") + text.count(
            "Removing .purged.")
        hidden_seen += len([d for d in os.listdir(killed)
                            if d.startswith((".incomplete.", ".purged."))])
        for _, name in times(killed):
            if name != "0":
                problems += manifest_problems(killed, name)
        problems += pvd_problems(killed)
    t.check("%d kills: every time directory left is complete, every .pvd"
            " sound" % kills, not problems and kills >= KILLS,
            "\n".join(problems[:10]))
    t.check("killed writes were left as hidden directories (%d) and removed"
            " at the next start (%d)" % (hidden_seen, removed),
            removed >= 1 and removed <= hidden_seen)

    if times(killed)[-1][1] != last:
        code, out = run(["particleFoam"], killed)
        t.check("the continued run ends", code == 0 and "End" in out,
                out[-1500:])
    t.check_equal("both end at the same time", times(killed)[-1][1], last)
    t.check("no temporary directory left",
            not [d for d in os.listdir(killed) if d.startswith(".")])
    for body in ("drop", "floor"):
        a = read_cloud(straight, last, body)
        b = read_cloud(killed, last, body)
        same = all(a[f] == b.get(f) for f in a)
        t.check("%s after %d kills equals the uninterrupted run (bitwise)"
                % (body, kills), same and sorted(a) == sorted(b),
                str([f for f in a if a[f] != b.get(f)]))
    rows_a = energy_rows(straight)
    rows_b = energy_rows(killed)
    common = [k for k in rows_b if k in rows_a]
    differ = [k for k in common if any(r != rows_a[k][0] for r in rows_b[k])]
    t.check("energy series of the pieces equal the uninterrupted run's"
            " (%d common times)" % len(common),
            len(common) > 20 and not differ, str(differ[:5]))


def hydrostatic_pair(work, name, edit):
    """Straight to 0.004 s and stopped at 0.002 s and continued: the two
    case directories"""
    a = copy_case(HYDROSTATIC, os.path.join(work, name + ".straight"))
    for cmd in (["blockMesh"], ["seedParticles"]):
        code, out = run(cmd, a)
        if code != 0:
            raise RuntimeError(out[-1500:])
    for key, value in (("writePrecision", 12), ("endTime", 0.004),
                       ("writeInterval", 0.002), ("startFrom", "latestTime")):
        set_entry(a, CD, key, value)
    edit(a)
    b = os.path.join(work, name + ".restarted")
    shutil.copytree(a, b)
    outs = [run(["ulphPdFoam"], a)]
    set_entry(b, CD, "endTime", 0.002)
    outs.append(run(["ulphPdFoam"], b))
    set_entry(b, CD, "endTime", 0.004)
    outs.append(run(["ulphPdFoam"], b))
    return a, b, outs


def compare_hydrostatic(a, b):
    """Largest relative difference per body and field at 0.004 s, and
    whether the energy lines agree"""
    worst = {}
    for body in ("water", "plate"):
        ca = read_cloud(a, "0.004", body)
        cb = read_cloud(b, "0.004", body)
        for f in ca:
            flat = lambda v: [x for r in v for x in (
                r if isinstance(r, list) else [r])]
            fa, fb = flat(ca[f]), flat(cb[f])
            scale = max(abs(x) for x in fa) or 1.0
            worst[body + "/" + f] = max(
                abs(x - y) for x, y in zip(fa, fb)) / scale
    ea = table(os.path.join(a, "postProcessing/energy/0/energy.dat"))
    eb = table(os.path.join(b, "postProcessing/energy/0.002/energy.dat"))
    by_time = {r[0]: r for r in ea}
    energy_same = all(by_time.get(r[0]) == r for r in eb) and len(eb) > 10
    return worst, energy_same


def test_coupled(t, work):
    def no_damping(case):
        path = os.path.join(case, PP)
        text = open(path).read().replace("damping { coefficient 200; }", "")
        open(path, "w").write(text)

    a, b, outs = hydrostatic_pair(work, "coupled", no_damping)
    t.check("coupled runs succeed", all(c == 0 for c, _ in outs),
            "\n".join(o[-800:] for _, o in outs))
    worst, energy_same = compare_hydrostatic(a, b)
    bad = {k: v for k, v in worst.items() if v != 0}
    t.check("coupled restart at a write time is bitwise equal (positions,"
            " velocities, stresses, forces)", not bad, str(bad))
    t.check("coupled restart: energy series continues the uninterrupted"
            " run's", energy_same)
    steps = [o.count("\nTime = ") for _, o in outs]
    t.check_equal("coupled restart takes the same number of steps",
                  steps[1] + steps[2], steps[0])

    # With the plate's damping (a velocity-dependent force: the restart
    # needs the accelerations of the last step, written)
    a, b, outs = hydrostatic_pair(work, "damped", lambda case: None)
    worst, energy_same = compare_hydrostatic(a, b)
    bad = {k: "%.1e" % v for k, v in worst.items() if v != 0}
    t.check("coupled restart with the plate's damping is bitwise equal",
            not bad and all(c == 0 for c, _ in outs), str(bad))


def main():
    t = CaseTest("restartIO")
    work = scratch("restartIO")
    try:
        for test in (test_kills, test_coupled):
            try:
                test(t, work)
            except Exception as e:      # a crash is a failure, not a stop
                t.check(test.__name__ + " ran", False, repr(e))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return t.finish()


if __name__ == "__main__":
    sys.exit(main())
