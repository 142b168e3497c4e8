"""Small OpenFOAM cases for the seeding tests, written from Python: a
blockMeshDict, a controlDict and a seedParticlesDict, then blockMesh and
seedParticles, and the clouds read back through VTK's OpenFOAM reader."""
import os
import subprocess

from readClouds import read_clouds

HEADER = """FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      %s;
}
"""

CONTROL = """application seedParticles;
startFrom startTime; startTime 0; stopAt endTime; endTime 0; deltaT 1;
writeControl timeStep; writeInterval 1; writeFormat ascii;
writePrecision 15; writeCompression off; timeFormat general;
timePrecision 6;
"""


def write_dict(case, name, body):
    path = os.path.join(case, "system", name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(HEADER % name + body)


def make_case(case, block_mesh, seed_dict):
    """Write the case and run blockMesh; returns the blockMesh run."""
    os.makedirs(os.path.join(case, "constant"), exist_ok=True)
    write_dict(case, "controlDict", CONTROL)
    write_dict(case, "blockMeshDict", block_mesh)
    write_dict(case, "seedParticlesDict", seed_dict)
    return subprocess.run(["blockMesh"], cwd=case, capture_output=True,
                          text=True)


def seed(case, seed_dict=None):
    """Run seedParticles (optionally with a new dictionary); returns the run"""
    if seed_dict is not None:
        write_dict(case, "seedParticlesDict", seed_dict)
    return subprocess.run(["seedParticles"], cwd=case, capture_output=True,
                          text=True)


def clouds(case):
    return read_clouds(case, 0, per_particle=True)


def lattice_index(x, origin, dx, offset=0.5):
    """Lattice index of a coordinate, None when it is off the lattice (the
    reader gives positions in single precision: 1e-4 dx is far above their
    round-off and far below any misplacement)"""
    f = (x - origin) / dx - offset
    i = round(f)
    return i if abs(f - i) < 1e-4 else None


def write_stl_box(path, lo, hi, outward=True):
    """A closed box as 12 triangles (ascii STL), oriented outward (or, to
    test the check, inward)"""
    x = (lo[0], hi[0])
    y = (lo[1], hi[1])
    z = (lo[2], hi[2])

    def v(i, j, k):
        return (x[i], y[j], z[k])
    # Each face as a quad, counter-clockwise seen from outside
    quads = [
        ((0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)),  # -x
        ((1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1)),  # +x
        ((0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)),  # -y
        ((0, 1, 0), (0, 1, 1), (1, 1, 1), (1, 1, 0)),  # +y
        ((0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)),  # -z
        ((0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)),  # +z
    ]
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write("solid box\n")
        for q in quads:
            if not outward:
                q = q[::-1]
            for tri in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
                f.write(" facet normal 0 0 0\n  outer loop\n")
                for c in tri:
                    f.write("   vertex %.10g %.10g %.10g\n" % v(*c))
                f.write("  endloop\n endfacet\n")
        f.write("endsolid box\n")
