#!/usr/bin/python3
"""Case test: the seeded dam-break tank tutorial.

blockMesh -> seedParticles -> checkParticles on a scratch copy, then the
clouds are opened with VTK's vtkOpenFOAMReader (ParaView's reader) and
checked against numbers known independently: lattice counts (the wall
layers' in closed form), masses, ids, the neighbour count of a 2D lattice at
radius 2.6 dx, and the lattice kernel sum computed here from the Wendland C2
formula. Then bad seedParticlesDicts: each must fail with a message naming
the file and keyword and leave no cloud on disk.
"""
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
from caseTest import copy_case, project_dir, run_parts  # noqa: E402
from readClouds import read_clouds  # noqa: E402
import seedCase  # noqa: E402


def wendland_lattice_sum(ratio=1.3):
    """sum_j W(|x_j|) dx^2 over a 2D unit lattice, Wendland C2, h = ratio dx"""
    h = ratio
    sigma = 7.0 / (4.0 * math.pi * h * h)
    total = 0.0
    n = int(2 * h) + 1
    for i in range(-n, n + 1):
        for j in range(-n, n + 1):
            q = math.hypot(i, j) / h
            if q < 2:
                total += sigma * (1 - q / 2) ** 4 * (2 * q + 1)
    return total


def open_tank_wall_count(nx, ny, layers):
    """Wall particles behind the left, bottom and right walls of an nx x ny
    (in dx) open-top 2D tank, lattice offset 1/2: the layers behind each
    wall, plus at each of the two bottom corners and behind each of the two
    rims the lattice points of the corner square within layers*dx of the
    corner (a quarter disk: the normals fan out from the corner)"""
    half = [k + 0.5 for k in range(layers)]
    quarter = sum(1 for a in half for b in half
                  if a * a + b * b <= layers * layers)
    return layers * (ny + nx + ny) + 2 * quarter + 2 * quarter


TUTORIAL = os.path.join(project_dir, "tutorials/seedParticles/damBreakTank")


def seeded_tank(t, work):
    case = copy_case(TUTORIAL, os.path.join(work, "damBreakTank"))
    run = subprocess.run(["./Allrun"], cwd=case, capture_output=True,
                         text=True)
    t.check("Allrun succeeds", run.returncode == 0, run.stderr[-2000:])
    if run.returncode != 0:
        return

    clouds = read_clouds(case, 0)
    t.check("reader sees the three clouds",
            sorted(clouds) == ["obstacle", "walls", "water"],
            str(sorted(clouds)))
    water, obstacle = clouds.get("water"), clouds.get("obstacle")
    walls = clouds.get("walls")
    if not water or not obstacle or not walls:
        return

    # 0.057 m column at 1 mm: 57 x 57; obstacle 6 mm x 40 mm at 0.5 mm
    t.check_equal("water particles", water["particles"], 57 * 57)
    t.check_equal("obstacle particles", obstacle["particles"], 12 * 80)
    # Tank 0.228 x 0.114 m at 1 mm, 3 layers: 3 (114 + 228 + 114) + 32
    t.check_equal("wall particles", walls["particles"],
                  open_tank_wall_count(228, 114, 3))
    expected = {"id", "volume", "mass", "rho", "nNeighbours", "kernelSum"}
    for name, c in clouds.items():
        t.check(name + " fields", expected <= set(c["arrays"]),
                str(sorted(c["arrays"])))
    t.check("walls fields normal, wallDistance",
            {"normal", "wallDistance"} <= set(walls["arrays"]),
            str(sorted(walls["arrays"])))
    if "wallDistance" in walls["arrays"]:
        d = walls["arrays"]["wallDistance"]["range"]
        t.check("wall distances from dx/2 to at most 3 dx",
                abs(d[0] - 0.0005) < 1e-9 and d[1] <= 0.003, str(d))
    b = walls["bounds"]
    t.check("walls around the tank, the top open",
            abs(b[0] + 0.0025) < 1e-7 and abs(b[1] - 0.2305) < 1e-7
            and abs(b[2] + 0.0025) < 1e-7 and b[3] < 0.114 + 0.003,
            str(b))
    t.check_close("water mass per particle",
                  water["arrays"]["mass"]["range"][1], 1000 * 1e-6, 1e-6)
    t.check_equal("water ids 0..n-1", water["arrays"]["id"]["range"],
                  [0.0, 57 * 57 - 1.0])
    b = water["bounds"]
    t.check("water inside the column",
            b[0] > 0 and b[1] < 0.057 and b[2] > 0 and b[3] < 0.057,
            str(b))

    # A lattice at radius 2.6 dx has 20 neighbours in 2D (the walls are
    # 3 layers thin: fewer)
    for name, c in (("water", water), ("obstacle", obstacle)):
        t.check_equal(name + " interior neighbours",
                      c["arrays"]["nNeighbours"]["range"][1], 20.0)
        t.check_close(name + " interior kernel sum",
                      c["arrays"]["kernelSum"]["range"][1],
                      wendland_lattice_sum(), 1e-6)


def bad_inputs(t, work):
    """Each bad dictionary fails with file + keyword, and writes nothing."""
    cases = {
        "negative spacing": ("spacing     0.001;", "spacing     -0.001;",
                             ["spacing", "seedParticlesDict", "> 0"]),
        "zero density": ("density     1000;", "density     0;",
                         ["density", "seedParticlesDict", "> 0"]),
        "unknown zone": ("zone water;", "zone oil;",
                         ["oil", "water", "seedParticlesDict"]),
        "unknown region type": ("type cellZone;", "type blob;",
                                ["blob", "seedParticlesDict", "cellZone",
                                 "mesh", "union", "intersection",
                                 "difference", "searchableSphere", "sphere",
                                 "triSurfaceMesh"]),
        "unknown type in a set operation": (
            "type cellZone; zone water;",
            "type union; regions ({ type mesh; } { type blob; });",
            ["blob", "seedParticlesDict", "cellZone", "triSurfaceMesh"]),
        "set operation of one region": (
            "type cellZone; zone water;",
            "type difference; regions ({ type mesh; });",
            ["regions", "at least two", "seedParticlesDict"]),
        "surface with no inside": (
            "type cellZone; zone water;",
            "type plate; origin (0 0 0); span (0.1 0.1 0);",
            ["plate", "encloses no volume", "seedParticlesDict"]),
        "missing surface file": (
            "type cellZone; zone water;",
            'type triSurfaceMesh; file "gate.stl";',
            ["file", "gate.stl", "constant/triSurface", "seedParticlesDict"]),
        "inside-out surface": (
            "type cellZone; zone water;",
            'type triSurfaceMesh; file "inverted.stl";',
            ["OUTSIDE", "inward", "seedParticlesDict"]),
        "unknown patch": ("patches     (walls);", "patches     (wall);",
                          ["patches", "wall", "walls", "top",
                           "seedParticlesDict"]),
        "zero layers": ("layers      3;", "layers      0;",
                        ["layers", "> 0", "seedParticlesDict"]),
        "negative layers": ("layers      3;", "layers      -2;",
                            ["layers", "> 0", "seedParticlesDict"]),
        "missing layers": ("layers      3;", "",
                           ["layers", "seedParticlesDict"]),
        "both region and patches": (
            "patches     (walls);",
            "patches     (walls); region { type mesh; }",
            ["walls", "both", "region", "patches", "seedParticlesDict"]),
        "neither region nor patches": (
            "patches     (walls);", "",
            ["walls", "neither", "region", "patches", "seedParticlesDict"]),
        "layers with a region": (
            "region      { type cellZone; zone water; }",
            "region      { type cellZone; zone water; } layers 3;",
            ["water", "layers", "patches", "seedParticlesDict"]),
        "missing spacing": ("spacing     0.001;", "",
                            ["spacing", "seedParticlesDict"]),
        "empty region": ("max (0.12 0.04 1)", "max (0.1141 0.00001 1)",
                         ["obstacle", "no particle"]),
    }
    base = copy_case(TUTORIAL, os.path.join(work, "bad"))
    env = os.environ.copy()
    subprocess.run(["blockMesh"], cwd=base, capture_output=True, env=env,
                   check=True)
    # A closed box with its normals pointing inward
    seedCase.write_stl_box(os.path.join(base, "constant/triSurface/"
                                        "inverted.stl"),
                           (0.01, 0.01, -1), (0.02, 0.02, 1), outward=False)
    dict_path = os.path.join(base, "system/seedParticlesDict")
    good = open(dict_path).read()
    for what, (old, new, words) in cases.items():
        assert old in good, old
        open(dict_path, "w").write(good.replace(old, new, 1))
        run = subprocess.run(["seedParticles"], cwd=base, capture_output=True,
                             text=True, env=env)
        out = run.stdout + run.stderr
        t.check(what + ": fails", run.returncode != 0, out[-500:])
        missing = [w for w in words if w not in out]
        t.check(what + ": message names " + ", ".join(words), not missing,
                out[-800:])
        t.check(what + ": nothing written",
                not os.path.exists(os.path.join(base, "0/lagrangian")))
    open(dict_path, "w").write(good)


if __name__ == "__main__":
    sys.exit(run_parts("seededTank", seeded_tank, bad_inputs))
