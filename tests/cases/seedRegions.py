#!/usr/bin/python3
"""Case test: seedParticles' regions on small meshes written here.

3D: a 20 mm cube meshed by blockMesh, seeded at 1 mm with a box, the same
box as a closed STL (triSurfaceMesh), a sphere, their union, intersection
and difference, and the mesh minus the box; every count is compared with
the lattice points counted here, and the sphere's volume with the analytic
one. 2D: a disk (a cylinder along z through the mid-plane) against pi r^2;
a wall plate (a gate of ghost particles) seeded in a box with a uniform
'normal', written normalised on every particle; bad normals refused.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))), "lib"))
from caseTest import run_parts  # noqa: E402
from foamCloud import read_cloud  # noqa: E402
import seedCase  # noqa: E402

DX = 0.001

CUBE = """
vertices ((0 0 0) (0.02 0 0) (0.02 0.02 0) (0 0.02 0)
          (0 0 0.02) (0.02 0 0.02) (0.02 0.02 0.02) (0 0.02 0.02));
blocks (hex (0 1 2 3 4 5 6 7) (10 10 10) simpleGrading (1 1 1));
boundary (walls { type wall; faces ((0 3 2 1) (4 5 6 7) (0 1 5 4)
                                    (2 3 7 6) (0 4 7 3) (1 2 6 5)); });
"""

SQUARE_2D = """
vertices ((0 0 0) (0.04 0 0) (0.04 0.04 0) (0 0.04 0)
          (0 0 0.001) (0.04 0 0.001) (0.04 0.04 0.001) (0 0.04 0.001));
blocks (hex (0 1 2 3 4 5 6 7) (20 20 1) simpleGrading (1 1 1));
boundary
(
    walls { type wall; faces ((0 1 5 4) (2 3 7 6) (0 4 7 3) (1 2 6 5)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
"""

BOX_LO = (0.0042, 0.0031, 0.0057)
BOX_HI = (0.0133, 0.0144, 0.0121)
CENTRE = (0.0101, 0.0098, 0.0103)
RADIUS = 0.0061


def vec(v):
    return "(%s)" % " ".join("%.10g" % c for c in v)


BOX = "{ type box; min %s; max %s; }" % (vec(BOX_LO), vec(BOX_HI))
STL = '{ type triSurfaceMesh; file "box.stl"; }'
SPHERE = "{ type sphere; centre %s; radius %.10g; }" % (vec(CENTRE), RADIUS)


def body(name, region):
    return ("    %s { spacing %g; density 1000; region %s }\n"
            % (name, DX, region))


def lattice3(n=20):
    r = [(i + 0.5) * DX for i in range(n)]
    return [(x, y, z) for z in r for y in r for x in r]


def in_box(p):
    return all(BOX_LO[d] <= p[d] <= BOX_HI[d] for d in range(3))


def in_sphere(p):
    return math.dist(p, CENTRE) < RADIUS


def on_lattice(points, dim):
    return all(seedCase.lattice_index(p[d], 0.0, DX) is not None
               for p in points for d in range(dim))


def check_3d(t, work):
    case = os.path.join(work, "cube")
    seedCase.write_stl_box(os.path.join(case, "constant/triSurface/box.stl"),
                           BOX_LO, BOX_HI)
    bodies = (body("box", BOX) + body("stl", STL) + body("sphere", SPHERE)
              + body("union", "{ type union; regions (%s %s); }"
                     % (BOX, SPHERE))
              + body("intersection", "{ type intersection; regions (%s %s); }"
                     % (SPHERE, STL))
              + body("difference", "{ type difference; regions (%s %s); }"
                     % (SPHERE, BOX))
              + body("meshMinusBox", "{ type difference; regions "
                     "({ type mesh; } %s); }" % BOX)
              + body("nested", "{ type difference; regions ({ type union; "
                     "regions (%s %s); } %s); }" % (BOX, SPHERE, SPHERE)))
    mesh = seedCase.make_case(case, CUBE, "bodies\n{\n%s}\n" % bodies)
    t.check("3D: blockMesh", mesh.returncode == 0, mesh.stderr[-1000:])
    run = seedCase.seed(case)
    t.check("3D: seedParticles succeeds", run.returncode == 0,
            (run.stdout + run.stderr)[-2000:])
    if run.returncode != 0:
        return
    c = seedCase.clouds(case)
    lat = lattice3()
    nBox = sum(in_box(p) for p in lat)
    nSphere = sum(in_sphere(p) for p in lat)
    nBoth = sum(in_box(p) and in_sphere(p) for p in lat)
    expected = {
        "box": nBox,
        "stl": nBox,
        "sphere": nSphere,
        "union": nBox + nSphere - nBoth,
        "intersection": nBoth,
        "difference": nSphere - nBoth,
        "meshMinusBox": len(lat) - nBox,
        "nested": nBox - nBoth,
    }
    t.check("3D: the lattice is not degenerate",
            0 < nBoth < nBox and nBoth < nSphere, str((nBox, nSphere, nBoth)))
    for name, n in expected.items():
        t.check_equal("3D: %s particles" % name,
                      c.get(name, {}).get("particles"), n)
    if "box" in c and "stl" in c:
        t.check("3D: STL region gives the box region's points",
                sorted(c["box"]["points"]) == sorted(c["stl"]["points"]))
        t.check("3D: box particles on the case's lattice",
                on_lattice(c["box"]["points"], 3))
    if "sphere" in c:
        # The lattice cubes of the points inside cover the sphere shrunk by
        # the cube's half-diagonal and lie in the sphere grown by it
        V = c["sphere"]["particles"] * DX**3
        h = math.sqrt(3) / 2 * DX
        t.check("3D: sphere volume within the lattice bounds",
                4 / 3 * math.pi * (RADIUS - h)**3 <= V
                <= 4 / 3 * math.pi * (RADIUS + h)**3,
                "V %g, analytic %g" % (V, 4 / 3 * math.pi * RADIUS**3))
        t.check_close("3D: sphere volume", V, 4 / 3 * math.pi * RADIUS**3,
                      0.05)
        vol = c["sphere"]["arrays"]["volume"]["range"]
        t.check_close("3D: particle volume dx^3", vol[1], DX**3, 1e-6)


def check_2d(t, work):
    case = os.path.join(work, "square")
    centre = (0.0201, 0.0197)
    r = 0.0123
    disk = ("{ type cylinder; point1 (%g %g -1); point2 (%g %g 1); "
            "radius %g; }" % (centre + centre + (r,)))
    mesh = seedCase.make_case(case, SQUARE_2D,
                              "bodies\n{\n%s}\n" % body("disk", disk))
    t.check("2D: blockMesh", mesh.returncode == 0, mesh.stderr[-1000:])
    run = seedCase.seed(case)
    t.check("2D: seedParticles succeeds", run.returncode == 0,
            (run.stdout + run.stderr)[-2000:])
    if run.returncode != 0:
        return
    c = seedCase.clouds(case).get("disk", {})
    rr = [(i + 0.5) * DX for i in range(40)]
    n = sum(math.hypot(x - centre[0], y - centre[1]) < r
            for y in rr for x in rr)
    t.check_equal("2D: disk particles", c.get("particles"), n)
    A = c.get("particles", 0) * DX**2
    h = math.sqrt(2) / 2 * DX
    t.check("2D: disk area within the lattice bounds",
            math.pi * (r - h)**2 <= A <= math.pi * (r + h)**2,
            "A %g, analytic %g" % (A, math.pi * r * r))
    t.check_close("2D: disk area", A, math.pi * r * r, 0.02)
    if c:
        t.check("2D: particles in the mid-plane",
                all(abs(p[2] - 0.0005) < 1e-9 for p in c["points"]))


def check_normal(t, work):
    case = os.path.join(work, "gate")
    gate = ("    gate { spacing %g; density 1000; normal (-2 0 0);"
            " region { type box; min (0.01 0 -1); max (0.014 0.03 1); } }\n"
            % DX)
    mesh = seedCase.make_case(case, SQUARE_2D, "bodies\n{\n%s}\n" % gate)
    t.check("normal: blockMesh", mesh.returncode == 0, mesh.stderr[-1000:])
    run = seedCase.seed(case)
    t.check("normal: seedParticles succeeds", run.returncode == 0,
            (run.stdout + run.stderr)[-2000:])
    if run.returncode != 0:
        return
    cloud = read_cloud(case, "0", "gate")
    n = cloud.get("normal", [])
    t.check_equal("normal: a gate 4 x 30 particles", len(n), 120)
    t.check("normal: (-1 0) on every particle",
            n and all(abs(v[0] + 1) < 1e-12 and abs(v[1]) < 1e-12
                      for v in n), str(n[:3]))
    for what, entry, words in (
            ("zero", "normal (0 0 0);", ["normal", "non-zero"]),
            ("out of the plane", "normal (0 0 1);", ["normal", "plane"])):
        bad = gate.replace("normal (-2 0 0);", entry)
        run = seedCase.seed(case, "bodies\n{\n%s}\n" % bad)
        out = run.stdout + run.stderr
        t.check("normal: %s refused naming %s" % (what, words),
                run.returncode != 0 and all(w in out for w in words),
                out[-1500:])
    walls = ("    tank { spacing %g; density 1000; patches (walls); layers 2;"
             " normal (1 0 0); }\n" % DX)
    run = seedCase.seed(case, "bodies\n{\n%s}\n" % walls)
    out = run.stdout + run.stderr
    t.check("normal: on wall layers refused naming the keyword",
            run.returncode != 0 and "'normal'" in out and "tank" in out,
            out[-1500:])


if __name__ == "__main__":
    sys.exit(run_parts("seedRegions", check_3d, check_2d, check_normal))
