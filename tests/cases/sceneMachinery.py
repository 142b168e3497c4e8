#!/usr/bin/python3
"""Case test: the machinery every solver shares, on the freeFall tutorial
(particleFoam: a kinematic block under gravity beside a fixed floor).

- the run matches the exact discrete free fall; the log lists the active
  effects, per-step times and the cost table; the run cost
  (postProcessing/runCost) has the time of each model and effect and of
  the writes, the particle-steps per second, and the run completed;
- ParaView's reader (VTK's vtkOpenFOAMReader) sees every body with its
  particle count and fields, in ascii and in binary writeFormat;
- restart: one run to t1 and a run to t1/2 restarted (startFrom latestTime)
  to t1, both with an adaptive step, give the same particles to round-off
  in as many steps (the run cost of each run);
- purgeWrite keeps the last N times; vtp output is readable by VTK;
- bad input stops with the file, the keyword and what was expected, and
  leaves every file of the case as it was;
- a blow-up stops with a diagnosis and the last good state on disk (a
  particle outside the scene's escapeBox).
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import (copy_case, project_dir, run, run_parts,  # noqa: E402
                      set_entry, snapshot)
from readClouds import read_clouds  # noqa: E402
from foamCloud import read_cloud, times  # noqa: E402
from foamMonitor import run_cost, run_costs  # noqa: E402

TUTORIAL = os.path.join(project_dir, "tutorials/particleFoam/freeFall")


def prepared(work, name):
    """A copy of the tutorial with its mesh and seeded particles."""
    case = copy_case(TUTORIAL, os.path.join(work, name))
    for cmd in (["blockMesh"], ["seedParticles"]):
        code, out = run(cmd, case)
        if code != 0:
            raise RuntimeError(out)
    return case


def test_tutorial(t, work):
    case = copy_case(TUTORIAL, os.path.join(work, "tutorial"))
    code, out = run(["./Allrun"], case)
    t.check("Allrun succeeds and matches the exact free fall",
            code == 0 and "free fall: PASS" in out, out[-1500:])
    log = open(os.path.join(case, "log.particleFoam")).read()
    for words in ("effect gravity", "model kinematic", "model fixed",
                  "ExecutionTime", "ClockTime", "remaining ~",
                  "Cost per model and effect", "Particle-steps per second"):
        t.check("log shows '%s'" % words, words in log)
    cost = run_cost(case)
    for part in ("drop.gravity", "drop.kinematic", "write"):
        t.check("run cost has the part %s" % part, part in cost["parts"],
                str(sorted(cost["parts"])))
    t.check("run cost: completed, %d steps of 400 + 250 particles at %.3g"
            " particle-steps per second" % (cost["steps"], cost["rate"]),
            cost["completed"] and cost["steps"] == 100
            and cost["particles"] == 650 and cost["rate"] > 0, str(cost))

    clouds = read_clouds(case, 0.1)
    t.check_equal("reader sees the bodies", sorted(clouds), ["drop", "floor"])
    if "drop" in clouds:
        t.check_equal("drop particles", clouds["drop"]["particles"], 400)
        t.check("drop fields", {"U", "acceleration", "id", "mass", "rho",
                                "volume"} <= set(clouds["drop"]["arrays"]),
                str(sorted(clouds["drop"]["arrays"])))
        uy = clouds["drop"]["arrays"]["U"]["range"]
        t.check_close("drop speed at 0.1 s (|U| = g t)", uy[1], 0.981, 1e-5)
    if "floor" in clouds:
        t.check_equal("floor particles", clouds["floor"]["particles"], 250)


def test_restart(t, work):
    one = prepared(work, "oneGo")
    two = prepared(work, "restarted")
    for case in (one, two):
        set_entry(case, "system/controlDict", "adjustTimeStep", "yes")
        set_entry(case, "system/controlDict", "maxCo", 0.2)
        # The first part ends on a write time of the uninterrupted run
        set_entry(case, "system/controlDict", "writeInterval", 0.01)
    set_entry(two, "system/controlDict", "endTime", 0.05)
    code1, out1 = run(["particleFoam"], one)
    code2, out2 = run(["particleFoam"], two)
    set_entry(two, "system/controlDict", "startFrom", "latestTime")
    set_entry(two, "system/controlDict", "endTime", 0.1)
    code3, out3 = run(["particleFoam"], two)
    t.check("three runs succeed", code1 == code2 == code3 == 0,
            (out1 + out2 + out3)[-1500:])
    starts = [float(r["startTime"]) for r in run_costs(two)]
    t.check("the second part starts from 0.05 (run costs from %s)" % starts,
            starts == [0, 0.05])
    a = read_cloud(one, "0.1", "drop")
    b = read_cloud(two, "0.1", "drop")
    t.check_equal("same fields after restart", sorted(a), sorted(b))
    t.check_equal("same ids after restart", a["id"], b["id"])
    diff = 0.0
    for field in ("positions", "U", "acceleration"):
        for u, v in zip(a[field], b[field]):
            diff = max(diff, max(abs(p - q) for p, q in zip(u, v)))
    t.check("restart matches the uninterrupted run (max diff %.2e)" % diff,
            diff < 1e-12)
    t.check_equal("restart takes the same number of steps",
                  run_cost(two)["steps"], run_cost(one)["steps"])
    t.check("the adaptive run ends on endTime",
            os.path.isdir(os.path.join(one, "0.1")), str(os.listdir(one)))


def test_binary_and_purge(t, work):
    case = prepared(work, "binary")
    set_entry(case, "system/controlDict", "writeFormat", "binary")
    set_entry(case, "system/controlDict", "purgeWrite", 2)
    set_entry(case, "constant/particleProperties", "vtp", "yes")
    code, out = run(["particleFoam"], case)
    t.check("binary run succeeds", code == 0, out[-1500:])
    names = [n for _, n in times(case)]
    t.check_equal("purgeWrite 2 keeps the last two times", names,
                  ["0", "0.08", "0.1"])
    header = open(os.path.join(case, "0.1/lagrangian/drop/U"), "rb").read(800)
    t.check("fields are binary", b"format      binary" in header)
    clouds = read_clouds(case, 0.1)
    drop = clouds.get("drop", {"particles": 0, "arrays": {}})
    t.check_equal("reader: binary drop particles", drop["particles"], 400)
    t.check("reader: binary fields", {"U", "id", "mass"} <= set(drop["arrays"]),
            str(sorted(drop["arrays"])))
    if "U" in drop["arrays"]:
        t.check_close("reader: binary U", drop["arrays"]["U"]["range"][1],
                      0.981, 1e-5)

    import vtk
    pvd = os.path.join(case, "VTK", "drop.pvd")
    t.check("vtp collection written", os.path.exists(pvd))
    if os.path.exists(pvd):
        entries = [l for l in open(pvd) if "<DataSet" in l]
        t.check_equal("vtp collection lists every write time", len(entries), 5)
        r = vtk.vtkXMLPolyDataReader()
        r.SetFileName(os.path.join(case, "VTK", "drop", "drop_0.1.vtp"))
        r.Update()
        poly = r.GetOutput()
        t.check_equal("vtp particles", poly.GetNumberOfPoints(), 400)
        arrays = {poly.GetPointData().GetArrayName(i)
                  for i in range(poly.GetPointData().GetNumberOfArrays())}
        t.check("vtp fields", {"U", "id", "mass"} <= arrays, str(arrays))


BAD = [
    # what, file, old text, new text, words the message must contain
    ("unknown model", "constant/particleProperties", "model       kinematic;",
     "model       kinematik;", ["kinematik", "kinematic", "fixed",
                               "particleProperties"]),
    ("unknown effect", "constant/particleProperties", "gravity { value",
     "gravitee { value", ["gravitee", "gravity", "damping"]),
    ("missing density", "constant/particleProperties",
     "density     1000;", "", ["density", "particleProperties"]),
    ("negative density", "constant/particleProperties",
     "density     1000;", "density     -1000;",
     ["density", "-1000", "> 0"]),
    ("body not seeded", "constant/particleProperties", "    drop\n",
     "    droplet\n", ["droplet", "drop", "floor", "seedParticles"]),
    ("effects on a fixed body", "constant/particleProperties",
     "density     2500;",
     "density     2500; effects { gravity { value (0 -9.81 0); } }",
     ["floor", "fixed", "effects"]),
    ("negative spacing", "constant/particleProperties",
     "density     1000;", "density     1000; spacing -0.002;",
     ["spacing", "-0.002", "> 0", "particleProperties"]),
    ("unknown wall body", "constant/particleProperties",
     "model       kinematic;", "model ulph; soundSpeed 20; walls (tonk);"
     " kernel { type gaussian; smoothingLengthRatio 1.2; }",
     ["tonk", "drop", "floor", "particleProperties"]),
    ("3D gravity in 2D", "constant/particleProperties", "(0 -9.81 0)",
     "(0 -9.81 1)", ["value", "z component"]),
    ("zero damping", "constant/particleProperties",
     "gravity { value (0 -9.81 0); }",
     "gravity { value (0 -9.81 0); } damping { coefficient 0; }",
     ["coefficient", "> 0"]),
    ("negative wall repulsion", "constant/particleProperties",
     "gravity { value (0 -9.81 0); }",
     "gravity { value (0 -9.81 0); } wallRepulsion { strength -10; }",
     ["strength", "-10", "> 0", "particleProperties"]),
    ("wall repulsion exponents reversed", "constant/particleProperties",
     "gravity { value (0 -9.81 0); }",
     "gravity { value (0 -9.81 0); }"
     " wallRepulsion { strength 10; exponents (4 12); }",
     ["exponents", "p1 > p2 > 0", "particleProperties"]),
    ("unknown kernel", "constant/particleProperties", "density     1000;",
     "density     1000; kernel { type quintic; smoothingLengthRatio 1.3; }",
     ["quintic", "wendlandC2", "cubicSpline", "gaussian"]),
    ("escape box inside the mesh", "constant/particleProperties",
     "vtp         no;",
     "vtp         no; escapeBox { min (0 0 0); max (0.01 0.01 0.01); }",
     ["escapeBox", "bounds", "particleProperties"]),
    ("negative maxCo", "system/controlDict", "maxCo           0.25;",
     "maxCo           -1;", ["maxCo", "controlDict", "> 0"]),
    ("adaptive without maxCo", "system/controlDict",
     "adjustTimeStep  no;", "adjustTimeStep  yes; maxCo_ 1;",
     ["maxCo", "controlDict"]),
]


def test_bad_input(t, work):
    case = prepared(work, "bad")
    for what, rel, old, new, words in BAD:
        path = os.path.join(case, rel)
        good = open(path).read()
        if old not in good:
            t.check(what + ": test text found", False, old)
            continue
        if what == "adaptive without maxCo":
            new_text = good.replace(old, new).replace(
                "maxCo           0.25;", "")
        else:
            new_text = good.replace(old, new, 1)
        open(path, "w").write(new_text)
        before = snapshot(case)
        code, out = run(["particleFoam"], case)
        after = snapshot(case)
        open(path, "w").write(good)
        t.check(what + ": fails", code != 0, out[-400:])
        missing = [w for w in words if w not in out]
        t.check(what + ": message names " + ", ".join(words), not missing,
                out[-900:])
        t.check(what + ": nothing on disk changed", before == after,
                str(set(after) ^ set(before)))


def test_blow_up(t, work):
    case = prepared(work, "blowUp")
    path = os.path.join(case, "constant/particleProperties")
    text = open(path).read().replace(
        "gravity { value (0 -9.81 0); }",
        "gravity { value (0 -9.81 0); } damping { coefficient 5000; }")
    # c dt = 5: the explicit update diverges; out of the scene's escape box
    text += "\nescapeBox { min (-5 -5 -1); max (5 5 1); }\n"
    open(path, "w").write(text)
    code, out = run(["particleFoam"], case)
    t.check("blow-up stops the run", code != 0, out[-500:])
    for words in ("Blow-up at time", "body drop", "left the domain",
                  "(-5 -5 -1) (5 5 1)",
                  "Last good state on disk: time 0", "deltaT"):
        t.check("diagnosis says '%s'" % words, words in out, out[-1200:])
    t.check("the warning at start named the unstable step",
            "exceeds the stable step" in out)
    drop = read_cloud(case, "0", "drop")
    t.check_equal("last good state intact", len(drop["positions"]), 400)


if __name__ == "__main__":
    sys.exit(run_parts("sceneMachinery", test_tutorial, test_restart,
                       test_binary_and_purge, test_bad_input, test_blow_up))
