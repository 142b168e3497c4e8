#!/usr/bin/python3
"""Case test: OpenFOAM's decomposePar and reconstructPar carry every body's
cloud, unchanged, by the cells the clouds' coordinates name.

The case: the fracturing obstacle of ulphPdFoam (tutorial obstacleFracture
at 4 mm, bonds breaking from a stretch of 2e-5) run serially to 0.01 s in
binary, so that a water body, a ghost wall whose particles lie outside the
mesh and a peridynamic solid with broken bonds (a list of ids per particle)
are written at 0 and 0.01 s.

For the decompositions simple (2 1 1), hierarchical (3 1 1) and scotch
(3 processors):
- decomposePar (-time 0,0.01) succeeds and re-locates no particle;
- at 0 and 0.01 s every body's particles are split among the processors,
  each exactly once, and every field of every particle (the exact
  positions, the solid's reference positions and broken bonds included)
  equals the serial case's, bit for bit;
- simple and hierarchical (slabs in x): every particle inside the mesh
  is on the processor whose slab holds it;
- reconstructPar (in a copy holding only the processors' folders) gives
  back every cloud equal to the serial case's, bit for bit, the positions
  read as the solver reads them; ParaView's reader (VTK's) opens them.
The reconstructed 0.01 s (scotch) restarts: the solver continues from it
for 6 steps (to 0.0101 s) and ends within RESTART_RTOL of the serial case's
own continuation: the particles come back in another order, so sums run in
another order (the obstacle's velocities differ by 5e-15 relative after a
step, and grow about that much per step; over 0.005 s bonds then break a
step apart in the two runs and the water's velocities differ by 1e-3).
The decomposed case (simple) continues from 0.01 s in parallel (2
processors, each starting from its own files of the obstacle's broken
bonds, which they share: the solid is whole on every processor) and ends
within RESTART_RTOL of the serial continuation. decomposePar writes no
legacy positions (ParaView's reader needs them); the solver adds them at
its start, and ParaView's reader then opens each processor's start time
with every particle once.
"""
import math
import os
import shutil
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import copy_case, project_dir, run, run_parts  # noqa: E402
from caseTest import set_entry  # noqa: E402

from foamCloud import read_cloud  # noqa: E402
from readClouds import read_clouds  # noqa: E402

TUTORIAL = "tutorials/ulphPdFoam/obstacleFracture"
SOLVER = "ulphPdFoam"
BODIES = ("water", "tank", "obstacle")
TIMES = ("0", "0.01")
RESTART_RTOL = 1e-12
RESTART_END = 0.0101

DECOMPOSITIONS = [
    ("simple", 2, "coeffs { n (2 1 1); }"),
    ("hierarchical", 3, "coeffs { n (3 1 1); order xyz; }"),
    ("scotch", 3, ""),
]

HEADER = "FoamFile { version 2.0; format ascii; class dictionary;" \
    " object %s; }\n"


def write_system(case, name, body):
    with open(os.path.join(case, "system", name), "w") as f:
        f.write(HEADER % name + body + "\n")


def set_up(case):
    """The tutorial at 4 mm to 0.01 s, writing every 0.005 s in binary,
    with the dictionaries reconstructPar needs (it builds an fvMesh)"""
    copy_case(os.path.join(project_dir, TUTORIAL), case)
    with open(os.path.join(case, "system", "resolution"), "w") as f:
        f.write("dx 0.004;\n")
    set_entry(case, "constant/particleProperties",
              "bodies/obstacle/failure/criticalStretch", 2e-5)
    for key, value in (("endTime", 0.01), ("writeInterval", 0.005),
                       ("writeFormat", "binary")):
        set_entry(case, "system/controlDict", key, value)
    write_system(case, "fvSchemes",
                 "ddtSchemes {} gradSchemes {} divSchemes {}"
                 " laplacianSchemes {} interpolationSchemes {}"
                 " snGradSchemes {}")
    write_system(case, "fvSolution", "")


def by_id(cloud):
    """{id: {field: value}} of a cloud read with read_cloud"""
    out = {}
    for k, i in enumerate(cloud["id"]):
        out[i] = {f: v[k] for f, v in cloud.items() if f != "id"}
    return out


def processors(case):
    return sorted((d for d in os.listdir(case) if d.startswith("processor")),
                  key=lambda d: int(d[len("processor"):]))


def compare(serial, other, fields_of=None):
    """Differences between two clouds by id: ids missing or extra, and per
    field the number of particles whose value is not the same"""
    a, b = by_id(serial), by_id(other)
    missing = sorted(set(a) - set(b))[:5]
    extra = sorted(set(b) - set(a))[:5]
    fields = fields_of or sorted(set(serial) - {"id"})
    differ = {}
    for f in fields:
        n = sum(1 for i in set(a) & set(b) if a[i].get(f) != b[i].get(f))
        if n:
            differ[f] = n
    return missing, extra, differ


def serial_run(t, work):
    case = os.path.join(work, "serial")
    set_up(case)
    for cmd in ("blockMesh", "seedParticles", SOLVER):
        code, out = run([cmd], case)
        if code != 0:
            t.check("serial: %s succeeds" % cmd, False, out[-1500:])
            return None
    broken = read_cloud(case, "0.01", "obstacle")["brokenBonds"]
    t.check("serial: bonds broke by 0.01 s (%d broken bond sides)"
            % sum(len(b) for b in broken), any(broken))
    return case


def decomposed(t, work, serial, method, n, coeffs):
    name = "%s%d" % (method, n)
    case = os.path.join(work, name)
    shutil.copytree(serial, case, ignore=shutil.ignore_patterns(
        "processor*", "log.*", "postProcessing"))
    write_system(case, "decomposeParDict",
                 "numberOfSubdomains %d;\nmethod %s;\n%s" % (n, method, coeffs))
    code, out = run(["decomposePar", "-time", ",".join(TIMES)], case)
    t.check("%s: decomposePar succeeds" % name, code == 0, out[-1500:])
    if code != 0:
        return None
    relocated = "particle::locate" in out or "outside of the mesh" in out
    t.check("%s: decomposePar re-locates no particle" % name,
            not relocated, out[out.find("locate") - 400:][:800])
    procs = processors(case)
    t.check("%s: %d processor folders" % (name, n), len(procs) == n,
            str(procs))

    # The slabs of simple and hierarchical (n 1 1): each processor's part
    # of the mesh spans an x range
    slabs = None
    if method in ("simple", "hierarchical"):
        slabs = [mesh_x_range(os.path.join(case, p)) for p in procs]
    for time in TIMES:
        for body in BODIES:
            whole = read_cloud(serial, time, body)
            held = [p for p in procs
                    if os.path.isdir(os.path.join(case, p, time,
                                                  "lagrangian", body))]
            parts = [read_cloud(os.path.join(case, p), time, body)
                     for p in held]
            ids = [i for c in parts for i in c["id"]]
            t.check("%s: %s at %s split among the processors, each particle"
                    " once (%d particles)" % (name, body, time, len(ids)),
                    sorted(ids) == sorted(whole["id"]),
                    "%d ids against %d, %d distinct"
                    % (len(ids), len(whole["id"]), len(set(ids))))
            merged = {f: [v for c in parts for v in c[f]]
                      for f in parts[0]} if parts else {"id": []}
            missing, extra, differ = compare(whole, merged)
            t.check("%s: %s at %s: every field of every particle equal to"
                    " the serial case's (%d fields)"
                    % (name, body, time, len(whole) - 1),
                    not missing and not extra and not differ,
                    "missing %s, extra %s, fields differing %s"
                    % (missing, extra, differ))
            if slabs is not None:
                wrong = []
                inside = inside_mesh(serial, time, body)
                for p, c in zip(held, parts):
                    lo, hi = slabs[int(p[len("processor"):])]
                    for i, x in zip(c["id"], c["positions"]):
                        if inside[i] and \
                                not lo - 1e-12 <= x[0] <= hi + 1e-12:
                            wrong.append((p, x[0], lo, hi))
                t.check("%s: %s at %s: each particle inside the mesh on"
                        " the processor whose part of the mesh holds it"
                        % (name, body, time), not wrong, str(wrong[:5]))
    return case


def mesh_x_range(case):
    """x range of a (processor's) mesh: its points (ascii or binary)"""
    from foamCloud import read_list
    pts = read_list(os.path.join(case, "constant", "polyMesh", "points"))
    return min(p[0] for p in pts), max(p[0] for p in pts)


def inside_mesh(case, time, body):
    """{id: whether the particle is inside the mesh}, from the serial
    cloud's coordinates (barycentric in a tet of its cell: all of them
    non-negative inside; a particle outside the mesh, e.g. a wall's ghost,
    has its nearest cell's and negative ones)"""
    from foamCloud import read_list
    ids = read_cloud(case, time, body)["id"]
    bary = read_list(os.path.join(case, time, "lagrangian", body,
                                  "coordinates"))
    return {i: min(b) >= -1e-9 for i, b in zip(ids, bary)}


def reconstructed(t, work, serial, decomposed_case, name):
    case = os.path.join(work, name + ".reconstructed")
    os.makedirs(case)
    for d in ["constant", "system"] + processors(decomposed_case):
        shutil.copytree(os.path.join(decomposed_case, d),
                        os.path.join(case, d), symlinks=True)
    code, out = run(["reconstructPar", "-withZero"], case)
    t.check("%s: reconstructPar succeeds" % name, code == 0, out[-1500:])
    if code != 0:
        return None
    for time in TIMES:
        for body in BODIES:
            whole = read_cloud(serial, time, body)
            back = read_cloud(case, time, body)
            missing, extra, differ = compare(whole, back)
            t.check("%s: reconstructed %s at %s equal to the serial case's,"
                    " bit for bit" % (name, body, time),
                    not missing and not extra and not differ,
                    "missing %s, extra %s, fields differing %s"
                    % (missing, extra, differ))
    seen = read_clouds(case, 0.01)
    counts = {b: seen.get(b, {}).get("particles") for b in BODIES}
    expected = {b: len(read_cloud(serial, "0.01", b)["id"]) for b in BODIES}
    t.check("%s: ParaView's reader opens the reconstructed clouds (%s)"
            % (name, counts), counts == expected, str(expected))
    return case


def largest_difference(a, b, field):
    """Largest difference of a field between two clouds by id, relative to
    the field's largest magnitude"""
    va, vb = by_id(a), by_id(b)
    scale, worst = 0.0, 0.0
    for i in va:
        x, y = va[i][field], vb[i][field]
        x = x if isinstance(x, list) else [x]
        y = y if isinstance(y, list) else [y]
        scale = max([scale] + [abs(v) for v in x])
        worst = max([worst] + [abs(p - q) for p, q in zip(x, y)])
    return worst / scale if scale > 0 else worst


def same_continuation(t, what, serial, case):
    """case's bodies at RESTART_END within RESTART_RTOL of serial's"""
    for body in ("water", "obstacle"):
        a = read_cloud(serial, "%g" % RESTART_END, body)
        b = read_cloud(case, "%g" % RESTART_END, body)
        worst = {f: largest_difference(a, b, f)
                 for f in ("positions", "U") if f in a}
        t.check("%s: %s at %g s within %g of the serial continuation (%s)"
                % (what, body, RESTART_END, RESTART_RTOL,
                   ", ".join("%s %.1e" % kv for kv in worst.items())),
                all(v <= RESTART_RTOL and math.isfinite(v)
                    for v in worst.values()))


def restart(t, serial, back):
    """Both the serial case and the reconstructed one continue from 0.01 s
    to RESTART_END"""
    for case in (serial, back):
        set_entry(case, "system/controlDict", "endTime", RESTART_END)
        set_entry(case, "system/controlDict", "writeInterval", 0.0001)
        set_entry(case, "system/controlDict", "startFrom", "latestTime")
    ends = []
    read = None
    for case in (serial, back):
        code, out = run([SOLVER], case)
        t.check("restart of %s from 0.01 s succeeds"
                % os.path.basename(case), code == 0, out[-1500:])
        if code != 0:
            return None
        ends.append(case)
        if case == serial:
            import re
            m = re.search(r"\((\d+) broken bonds read\)", out)
            read = int(m.group(1)) if m else None
    same_continuation(t, "restart from the reconstructed case", serial,
                      back)
    return read


def mpirun(case, n=2):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMP_NUM_THREADS="1")
    import subprocess
    p = subprocess.run(["mpirun", "--oversubscribe", "-np", str(n), SOLVER,
                        "-parallel"], cwd=case, capture_output=True,
                       text=True, env=env)
    return p.returncode, p.stdout + p.stderr


def parallel_continuation(t, serial, case, serial_read):
    """The decomposed case (the obstacle's broken bonds in every processor's
    files) continues in parallel from 0.01 s to RESTART_END, as the serial
    case continued (restart)"""
    set_entry(case, "system/controlDict", "endTime", RESTART_END)
    set_entry(case, "system/controlDict", "writeInterval", 0.0001)
    set_entry(case, "system/controlDict", "startFrom", "latestTime")
    procs = [os.path.join(case, d) for d in processors(case)]
    legacy = [os.path.join(p, "0.01", "lagrangian", b, "positions")
              for p in procs for b in BODIES
              if os.path.isdir(os.path.join(p, "0.01", "lagrangian", b))]
    t.check("decomposePar wrote no legacy positions (%d clouds)"
            % len(legacy), legacy and not any(map(os.path.isfile, legacy)))
    code, out = mpirun(case)
    t.check("%s -parallel continues the decomposed case from 0.01 s"
            % SOLVER, code == 0, out[-3000:])
    if code != 0:
        return
    import re
    read = re.search(r"\((\d+) broken bonds read\)", out)
    t.check("the processors read every processor's broken bonds (%s, the"
            " serial restart %s)" % (read and read.group(1), serial_read),
            read is not None and int(read.group(1)) == serial_read > 0,
            out[-1500:])
    # The solver gave decomposePar's clouds the legacy positions ParaView's
    # reader needs: each processor's start time opens with its particles
    serial_counts = {b: len(read_cloud(serial, "0.01", b)["id"])
                     for b in BODIES}
    seen = {b: 0 for b in BODIES}
    for p in procs:
        for b, c in read_clouds(p, 0.01).items():
            seen[b] = seen.get(b, 0) + c["particles"]
    t.check("ParaView's reader opens the processors' clouds at the start"
            " time, every particle once (%s; serially %s)"
            % (seen, serial_counts), seen == serial_counts)
    code, out = run(["reconstructPar", "-latestTime"], case)
    t.check("reconstructPar of the parallel continuation succeeds",
            code == 0, out[-1500:])
    if code != 0:
        return
    same_continuation(t, "parallel continuation", serial, case)


def decomposition_test(t, work):
    serial = serial_run(t, work)
    if serial is None:
        return
    for method, n, coeffs in DECOMPOSITIONS:
        case = decomposed(t, work, serial, method, n, coeffs)
        if case is None:
            continue
        back = reconstructed(t, work, serial, case, "%s%d" % (method, n))
        if method == "simple":
            parallel_case = case
        if method == "scotch" and back is not None:
            serial_read = restart(t, serial, back)
            parallel_continuation(t, serial, parallel_case, serial_read)


if __name__ == "__main__":
    sys.exit(run_parts("decomposeClouds", decomposition_test))
