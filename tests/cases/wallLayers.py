#!/usr/bin/python3
"""Case test: wall particles (seedParticles bodies with patches + layers).

Small meshes written here, seeded at dx = 1 mm with 3 layers, and checked
against sets computed here from the rule (lattice points outside the mesh
within N dx of the chosen patches, not overhanging an open patch):

  - a 2D open-top tank: exact count (also in closed form), normals exactly
    the axis behind flat walls, wall distances, lattice alignment with the
    fluid, and no gap: every lattice point outside the mesh within the
    Wendland C2 support (2.6 dx) of a fluid particle is a wall particle
    (except beyond the open top);
  - a 2D tank with an inclined side: walls behind the slope only; exact
    set, distance to the slope's plane <= N dx, normals = its normal;
  - a 2D quarter annulus: walls behind the curved outer patch, radial
    normals, the band R < r <= R + N dx filled;
  - a closed 3D box: exact count and no gap in 3D.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))), "lib"))
from caseTest import run_parts  # noqa: E402
import seedCase  # noqa: E402

DX = 0.001
N = 3
SUPPORT = 2 * 1.3 * DX      # Wendland C2, h = 1.3 dx
DZ = 0.001
Z_MID = DZ / 2


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def nearest_on_segment(p, a, b):
    ab = sub(b, a)
    t = max(0.0, min(1.0, dot(sub(p, a), ab) / dot(ab, ab)))
    q = tuple(a[i] + t * ab[i] for i in range(2))
    return q, math.dist(p, q), t


def outward_normal(a, b):
    """Outward normal of a counter-clockwise polygon's edge a -> b"""
    e = sub(b, a)
    n = (e[1], -e[0])
    m = math.hypot(*n)
    return (n[0] / m, n[1] / m)


def expected_walls_2d(segments, chosen, outside, index_range):
    """Lattice indices (i, j) -> (distance, unit normal) of the wall
    particles of a 2D polygon: segments {patch: [(a, b), ...]} (counter-
    clockwise), chosen patch names, outside(p) the mesh test."""
    tol = 1e-9 * DX
    walls = [(a, b) for name in chosen for a, b in segments[name]]
    others = [(a, b) for name, segs in segments.items() if name not in chosen
              for a, b in segs]
    result = {}
    (i0, i1), (j0, j1) = index_range
    for j in range(i0 if False else j0, j1 + 1):
        for i in range(i0, i1 + 1):
            p = ((i + 0.5) * DX, (j + 0.5) * DX)
            best = None
            for a, b in walls:
                q, d, _ = nearest_on_segment(p, a, b)
                if best is None or d < best[1]:
                    best = (q, d, outward_normal(a, b))
            q, d, nf = best
            if d > N * DX + tol or not outside(p):
                continue
            r = sub(p, q)
            if dot(r, nf) < -tol and others:
                dOther = min(nearest_on_segment(p, a, b)[1] for a, b in others)
                if dOther < d + 1e-6 * DX:
                    continue
            result[(i, j)] = (d, (r[0] / d, r[1] / d))
    return result


def particles_by_index(cloud, dim=2):
    """Lattice index -> particle number; None if a particle is off-lattice"""
    out = {}
    for k, p in enumerate(cloud["points"]):
        idx = tuple(seedCase.lattice_index(p[d], 0.0, DX) for d in range(dim))
        if None in idx:
            return None
        out[idx] = k
    return out


def block_2d(vertices, hex_cells, patches, edges=""):
    """A one-block 2D blockMeshDict; vertices (x, y) of the bottom face"""
    v = " ".join("(%.10g %.10g 0)" % xy for xy in vertices)
    v += " " + " ".join("(%.10g %.10g %g)" % (xy + (DZ,)) for xy in vertices)
    b = "\n".join("    %s { type %s; faces (%s); }" % (n, t, f)
                  for n, t, f in patches)
    return ("vertices (%s);\nblocks (hex (0 1 2 3 4 5 6 7) (%s) "
            "simpleGrading (1 1 1));\nedges (%s);\nboundary\n(\n%s\n"
            "    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }\n);\n"
            % (v, hex_cells, edges, b))


def seed_dict(walls_patches, fluid=True):
    s = "bodies\n{\n"
    if fluid:
        s += "    water { spacing %g; density 1000; region { type mesh; } }\n" \
            % DX
    s += ("    walls { spacing %g; density 1000; patches (%s); layers %d; }\n"
          % (DX, walls_patches, N))
    return s + "}\n"


def run_case(t, work, name, block_mesh, seed):
    case = os.path.join(work, name)
    mesh = seedCase.make_case(case, block_mesh, seed)
    t.check(name + ": blockMesh", mesh.returncode == 0, mesh.stderr[-1000:])
    run = seedCase.seed(case)
    t.check(name + ": seedParticles succeeds", run.returncode == 0,
            (run.stdout + run.stderr)[-2000:])
    if run.returncode != 0:
        return None
    return seedCase.clouds(case)


def check_against(t, name, walls, expected, dim=2):
    """Same lattice points, distances and normals as expected"""
    got = particles_by_index(walls, dim)
    t.check(name + ": wall particles on the fluid's lattice", got is not None)
    if got is None:
        return
    t.check_equal(name + ": wall particle count", walls["particles"],
                  len(expected))
    missing = sorted(set(expected) - set(got))
    extra = sorted(set(got) - set(expected))
    t.check(name + ": same lattice points as computed here",
            not missing and not extra,
            "missing %s, extra %s" % (missing[:10], extra[:10]))
    normals = walls["values"]["normal"]
    dists = walls["values"]["wallDistance"]
    bad_n = [k for k, (d, n) in expected.items() if k in got
             and math.dist(normals[got[k]][:dim], n) > 1e-6]
    bad_d = [k for k, (d, n) in expected.items() if k in got
             and abs(dists[got[k]][0] - d) > 1e-6 * DX]
    t.check(name + ": normals = (x - nearest wall point)/distance",
            not bad_n, str(bad_n[:10]))
    t.check(name + ": wallDistance = distance to the patches", not bad_d,
            str(bad_d[:10]))
    t.check(name + ": normals unit length",
            all(abs(math.sqrt(dot(n, n)) - 1) < 1e-6 for n in normals))


def no_gap(t, name, fluid, walls, outside, excluded, dim):
    """Every lattice point outside the mesh within the support of a fluid
    particle is a wall particle (points excluded(p) aside)"""
    have = set(particles_by_index(walls, dim) or {})
    reach = int(math.ceil(SUPPORT / DX))
    gaps = set()
    needed = set()
    for f in fluid["points"]:
        fi = [seedCase.lattice_index(f[d], 0.0, DX) for d in range(dim)]
        for off in __import__("itertools").product(range(-reach, reach + 1),
                                                   repeat=dim):
            idx = tuple(fi[d] + off[d] for d in range(dim))
            p = tuple((idx[d] + 0.5) * DX for d in range(dim))
            if math.dist(p, f[:dim]) > SUPPORT or not outside(p) \
                    or excluded(p):
                continue
            needed.add(idx)
            if idx not in have:
                gaps.add(idx)
    t.check(name + ": no gap within the fluid's kernel support (%d points)"
            % len(needed), needed and not gaps, str(sorted(gaps)[:10]))


def check_tank(t, work):
    L, H = 0.030, 0.020
    block = block_2d([(0, 0), (L, 0), (L, H), (0, H)], "15 10 1", [
        ("walls", "wall", "(0 4 7 3) (1 2 6 5) (0 1 5 4)"),
        ("top", "patch", "(3 7 6 2)"),
    ])
    c = run_case(t, work, "tank", block, seed_dict("walls"))
    if not c:
        return
    segments = {"walls": [((0, H), (0, 0)), ((0, 0), (L, 0)),
                          ((L, 0), (L, H))],
                "top": [((L, H), (0, H))]}

    def outside(p):
        return not (0 <= p[0] <= L and 0 <= p[1] <= H)
    expected = expected_walls_2d(segments, ["walls"], outside,
                                 ((-N - 1, 30 + N), (-N - 1, 20 + N)))
    # Closed form: N layers behind each wall, the corner squares without
    # the points beyond N dx (8 of 9 for N = 3: (2.5, 2.5) dx is 3.54 dx
    # away), the same rounded cap behind each rim, nothing above the top
    closed = N * (20 + 30 + 20) + 2 * 8 + 2 * 8
    t.check_equal("tank: expected count = closed form", len(expected), closed)
    walls, water = c.get("walls"), c.get("water")
    if not walls or not water:
        t.check("tank: clouds water and walls", False, str(sorted(c)))
        return
    check_against(t, "tank", walls, expected)
    t.check_equal("tank: fluid particles", water["particles"], 30 * 20)
    normals = walls["values"]["normal"]
    flat = [(k, p) for k, p in enumerate(walls["points"])
            if (0 < p[1] < H) != (0 < p[0] < L)]
    axis = all(
        math.dist(normals[k][:2],
                  (-1, 0) if p[0] < 0 else (1, 0) if p[0] > L else (0, -1))
        < 1e-9 for k, p in flat)
    t.check("tank: normals exactly the axis behind flat walls (%d)"
            % len(flat), flat and axis)
    t.check("tank: normals point out of the tank",
            all(dot(normals[k][:2], sub(p[:2], (L / 2, H / 2))) > 0
                for k, p in enumerate(walls["points"])))
    no_gap(t, "tank", water, walls, outside,
           lambda p: 0 < p[0] < L and p[1] > H, 2)


def check_inclined(t, work):
    L, H, s = 0.020, 0.015, 0.0073
    verts = [(0, 0), (L, 0), (L + s, H), (0, H)]
    block = block_2d(verts, "10 8 1", [
        ("walls", "wall", "(0 4 7 3) (0 1 5 4)"),
        ("slope", "wall", "(1 2 6 5)"),
        ("top", "patch", "(3 7 6 2)"),
    ])
    c = run_case(t, work, "inclined", block, seed_dict("slope"))
    if not c:
        return
    segments = {"walls": [((0, H), (0, 0)), ((0, 0), (L, 0))],
                "slope": [((L, 0), (L + s, H))],
                "top": [((L + s, H), (0, H))]}
    n = outward_normal((L, 0), (L + s, H))

    def outside(p):
        inside = (p[0] >= 0 and 0 <= p[1] <= H
                  and dot(sub(p, (L, 0)), n) <= 0)
        return not inside
    expected = expected_walls_2d(
        segments, ["slope"], outside,
        ((int((L - N * DX) / DX) - 2, int((L + s + N * DX) / DX) + 1),
         (-N - 1, int(H / DX) + N)))
    walls = c.get("walls")
    if not walls:
        t.check("inclined: cloud walls", False, str(sorted(c)))
        return
    check_against(t, "inclined", walls, expected)
    pts = walls["points"]
    normals = walls["values"]["normal"]
    plane = [dot(sub(p[:2], (L, 0)), n) for p in pts]
    t.check("inclined: behind the slope's plane, within N dx of it",
            all(-1e-6 * DX < d <= N * DX * (1 + 1e-6) for d in plane),
            "range %g .. %g" % (min(plane), max(plane)))
    interior = [k for k, p in enumerate(pts)
                if 1e-3 < nearest_on_segment(p[:2], (L, 0),
                                             (L + s, H))[2] < 1 - 1e-3]
    t.check("inclined: normals = the slope's normal (%d particles)"
            % len(interior),
            interior and all(math.dist(normals[k][:2], n) < 1e-6
                             for k in interior))


def check_curved(t, work):
    r1, R, nTheta = 0.010, 0.025, 40
    c45 = math.cos(math.pi / 4)
    block = block_2d([(r1, 0), (R, 0), (0, R), (0, r1)], "15 %d 1" % nTheta, [
        ("inner", "wall", "(0 4 7 3)"),
        ("outer", "wall", "(1 2 6 5)"),
        ("sides", "symmetry", "(0 1 5 4) (3 7 6 2)"),
    ], edges="arc 1 2 (%.12g %.12g 0) arc 5 6 (%.12g %.12g %g) "
             "arc 0 3 (%.12g %.12g 0) arc 4 7 (%.12g %.12g %g)"
             % (R * c45, R * c45, R * c45, R * c45, DZ,
                r1 * c45, r1 * c45, r1 * c45, r1 * c45, DZ))
    c = run_case(t, work, "curved", block, seed_dict("outer"))
    if not c:
        return
    walls = c.get("walls")
    if not walls:
        t.check("curved: cloud walls", False, str(sorted(c)))
        return
    # The patch is the arc's inscribed polygon: within sag of the circle
    sag = R * (1 - math.cos(math.pi / 4 / nTheta / 2))
    pts = walls["points"]
    normals = walls["values"]["normal"]
    dist = walls["values"]["wallDistance"]
    t.check("curved: particles on the lattice",
            particles_by_index(walls) is not None)
    rho = [math.hypot(p[0], p[1]) for p in pts]
    t.check("curved: R - sag <= r, wallDistance <= N dx",
            all(r > R - sag for r in rho)
            and all(d[0] <= N * DX * (1 + 1e-9) for d in dist),
            "r %g .. %g" % (min(rho), max(rho)))
    fan = [k for k, p in enumerate(pts) if p[0] > 0 and p[1] > 0]
    cosMax = math.cos(math.pi / 4 / nTheta + 1e-3)
    t.check("curved: radial normals behind the arc (%d particles)" % len(fan),
            fan and all(dot(normals[k][:2], (pts[k][0] / rho[k],
                                             pts[k][1] / rho[k])) > cosMax
                        for k in fan))
    t.check("curved: normals unit length",
            all(abs(math.sqrt(dot(nn, nn)) - 1) < 1e-6 for nn in normals))
    have = set(particles_by_index(walls) or {})
    band = [(i, j) for i in range(0, 40) for j in range(0, 40)
            if R + sag < math.hypot((i + 0.5) * DX, (j + 0.5) * DX)
            <= R + N * DX - sag]
    missing = [k for k in band if k not in have]
    t.check("curved: band R < r <= R + N dx filled (%d points)" % len(band),
            band and not missing, str(missing[:10]))


def check_box_3d(t, work):
    lo, hi = (0, 0, 0), (0.008, 0.006, 0.005)
    block = """
vertices ((0 0 0) (0.008 0 0) (0.008 0.006 0) (0 0.006 0)
          (0 0 0.005) (0.008 0 0.005) (0.008 0.006 0.005) (0 0.006 0.005));
blocks (hex (0 1 2 3 4 5 6 7) (4 3 5) simpleGrading (1 1 1));
boundary (walls { type wall; faces ((0 3 2 1) (4 5 6 7) (0 1 5 4)
                                    (2 3 7 6) (0 4 7 3) (1 2 6 5)); });
"""
    c = run_case(t, work, "box3D", block, seed_dict("walls"))
    if not c:
        return
    walls, water = c.get("walls"), c.get("water")
    if not walls or not water:
        t.check("box3D: clouds water and walls", False, str(sorted(c)))
        return
    n = [round(hi[d] / DX) for d in range(3)]

    def gap(p, d):
        return max(lo[d] - p[d], p[d] - hi[d], 0.0)

    def outside(p):
        return any(gap(p, d) > 0 for d in range(3))
    expected = {}
    for k in range(-N - 1, n[2] + N + 1):
        for j in range(-N - 1, n[1] + N + 1):
            for i in range(-N - 1, n[0] + N + 1):
                p = ((i + 0.5) * DX, (j + 0.5) * DX, (k + 0.5) * DX)
                d = math.sqrt(sum(gap(p, e)**2 for e in range(3)))
                if outside(p) and d <= N * DX * (1 + 1e-9):
                    g = [(p[e] - min(max(p[e], lo[e]), hi[e])) / d
                         for e in range(3)]
                    expected[(i, j, k)] = (d, tuple(g))
    # Closed form: faces, edges (quarter disks of the 3x3 square: 8
    # points), corners (octant of the 3x3x3 cube within 3 dx)
    corner = sum(1 for a in (0.5, 1.5, 2.5) for b in (0.5, 1.5, 2.5)
                 for cc in (0.5, 1.5, 2.5) if a * a + b * b + cc * cc <= 9)
    closed = (2 * N * (n[0] * n[1] + n[1] * n[2] + n[0] * n[2])
              + 4 * 8 * (n[0] + n[1] + n[2]) + 8 * corner)
    t.check_equal("box3D: expected count = closed form", len(expected),
                  closed)
    t.check_equal("box3D: fluid particles", water["particles"],
                  n[0] * n[1] * n[2])
    check_against(t, "box3D", walls, expected, dim=3)
    no_gap(t, "box3D", water, walls, outside, lambda p: False, 3)


if __name__ == "__main__":
    sys.exit(run_parts("wallLayers", check_tank, check_inclined,
                       check_curved, check_box_3d))
