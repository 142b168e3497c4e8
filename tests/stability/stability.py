#!/usr/bin/python3
"""The stability suite: every method on its hardest cases, run to the end,
and the same invariants checked at every written time of every run.

Usage: tests/stability/Allrun [-full] [-case C] [-method M] [-threads N]
                              [-work DIR] [-keep] [-continue]

  (default)   the coarse form (./Alltest runs it): coarse spacings, and
              the cases too costly for the CI budget cut short (the
              table says where)
  -full       the tutorials' own spacings and end times (hours); writes
              tests/stability/result.md when every case and method ran
              (not with -case or -method)
  -case C     only case C (repeatable)
  -method M   only method M (repeatable)
  -threads N  OpenMP threads of every run (default 2)
  -work DIR   where the runs go (default a scratch folder, removed at the
              end unless -keep)
  -continue   with -work: a run already in DIR made by this form is
              continued from its latest written time (the solver again,
              startFrom latestTime; its wall time adds up over the
              restarts), or only checked when it reached its end; the
              others are made afresh. The full form's longest run (the
              ISPH rolling tank, hours) can so be made in pieces. Each
              run folder lists the builds that made it (stabilityBuilds:
              SHA-1 of the library and the solver); the table says when a
              run was made by more than one

A run is a copy of the method's tutorial made by its own Allrun with the
arguments of the form asked for, and an energy monitor of the suite's own
(every step; seen from the moving tank for a case whose tank moves, so
that the total less the tank's work is what the models may only lower:
monitors::energy, frame). The invariants, at every written time (the
solvers stop a run on a NaN or an escaped particle, and the first check
says whether the run reached its end):

  - reached: the run reached its end time;
  - finite: no non-finite value in any field of any body;
  - particles: every body keeps its particles; with open boundaries, a
    fluid's count is its start plus what came in less what went out
    (postProcessing/openBoundaries);
  - depth: no fluid particle deeper than 0.5 dx (its own spacing) inside
    a wall (ghost walls: the face lies the wall particle's wallDistance
    in front of it, along its normal, which points into the wall, for the
    wall particles that lie along their normal from the fluid particle;
    a splash that has flown over a wall body, above every particle of it
    at a written time, counts only inside that wall's cells, not beside
    the tank) or a structure (its face half the solid's spacing beyond its
    outer particles, the outward normal from the solid's own neighbours;
    a fluid particle whose nearest solid particle is inside the solid is
    at least one solid spacing deep);
  - energy: the total (kinetic + strain + potential of every moving body,
    less the work of a moving tank) never above its lowest earlier value
    by more than ENERGY_RISE of the largest kinetic energy of the run;
    with open boundaries the inflow's work is not measured and the check
    is not made (the table says so);
  - splash: a fluid particle without another fluid particle within its
    kernel's support carries no pressure (|p| <= 1e-9 of the largest).

Prints one table, case x method: each invariant's figure and met/MISSED,
steps, wall time. Exit status 1 when an invariant is missed or a run did
not start.

Adding a method to a case, or a case, is one entry in CASES.
"""
import argparse
import collections
import hashlib
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(PROJECT, "etc", "python"))
sys.path.insert(0, os.path.join(PROJECT, "tests", "lib"))

from foamCloud import read_cloud, times  # noqa: E402
from caseTest import copy_case  # noqa: E402
from foamDict import lookup, put_entry, read_dictionary  # noqa: E402
from foamMonitor import monitor_rows, run_cost, run_costs  # noqa: E402
from fsiChecks import largest_rise  # noqa: E402

#: The energy check's bound: the largest rise of the total above its lowest
#: earlier value, as a fraction of the run's largest kinetic energy
ENERGY_RISE = 0.05

#: Depth of a fluid particle inside a wall or structure, in its spacings
DEPTH = 0.5

FLUIDS = ("ulph", "riemannWcsph", "isph")
SOLIDS = ("tlsph", "nosbPd")
WALLS = ("ghostWall",)

#: Kernel support over h when the kernel dictionary names no horizon
SUPPORT = {"cubicSpline": 2.0, "wendlandC2": 2.0, "gaussian": 3.0}


class Method:
    """A method on a case: its name, its tutorial (project-relative), the
    Allrun arguments of the coarse form and of the full one, and, for the
    coarse form, the end time when the run is cut short (None: the
    tutorial's own); frame: the moving tank whose frame the energy is
    seen from (None: a fixed one)"""

    def __init__(self, name, tutorial, coarse, full=(), coarse_end=None,
                 frame=None):
        self.name = name
        self.tutorial = tutorial
        self.coarse = list(coarse)
        self.full = list(full)
        self.coarse_end = coarse_end
        self.frame = frame


Case = collections.namedtuple("Case", "name title methods")

# The hard cases and the methods that run them: one line per method
CASES = [
    Case("damBreak", "dam break through the impact and the plunging wave"
         " (0.6 s)", [
             Method("ULPH", "tutorials/ulphPdFoam/damBreak",
                    ["-dx", "0.003"]),
             Method("Riemann WCSPH", "tutorials/riemannSphFoam/damBreak",
                    ["-dx", "0.003"]),
             Method("ISPH", "tutorials/isphTlsphFoam/damBreak",
                    ["-dx", "0.002"]),
         ]),
    Case("liaoPlate", "Liao plate: a violent impact on a thin elastic"
         " plate (1 s)", [
             Method("Riemann WCSPH + TLSPH",
                    "tutorials/riemannSphFoam/liaoPlate", ["-dx", "0.002"]),
             Method("ISPH + TLSPH",
                    "tutorials/isphTlsphFoam/liaoPlate", ["-dx", "0.002"]),
         ]),
    Case("rollingTankBaffle", "rolling tank with an elastic baffle"
         " (10 periods, 12.11 s)", [
             Method("Riemann WCSPH + TLSPH",
                    "tutorials/riemannSphFoam/rollingTankBaffle", [],
                    coarse_end=0.3, frame="tank"),
             Method("ISPH + TLSPH",
                    "tutorials/isphTlsphFoam/rollingTankBaffle", [],
                    coarse_end=0.3, frame="tank"),
         ]),
    Case("turekHronFSI2", "Turek-Hron FSI2 flag (10 periods and the"
         " start, 15 s)", [
             Method("Riemann WCSPH + TLSPH",
                    "tutorials/riemannSphFoam/turekHronFSI2",
                    ["-dx", "0.02"], coarse_end=2),
         ]),
    Case("obstacleFracture", "baffle fracture (0.4 s)", [
        Method("ULPH + NOSB-PD", "tutorials/ulphPdFoam/obstacleFracture",
               ["-dx", "0.004"]),
    ]),
    Case("sloshingTank", "sloshing tank at resonance (6 s)", [
        Method("ULPH", "tutorials/ulphPdFoam/sloshingTank", ["-dx", "0.02"],
               coarse_end=3, frame="tank"),
        # The coarse form is the tutorial's spacing, cut short: the tank,
        # 1.73 m wide, is 86.5 spacings of 0.02 m, and seedParticles puts
        # the water's last column on the right wall's face (x = 1.73 m);
        # from there an ISPH contact-line particle is 0.61 dx deep at
        # 2.275 s
        Method("ISPH", "tutorials/isphTlsphFoam/sloshingTank", [],
               coarse_end=2, frame="tank"),
    ]),
]


def verdict(good):
    return "met" if good else "MISSED"


# * * * * * * * * * * * * * * * * The runs  * * * * * * * * * * * * * * * //

#: The file of a run folder naming the form that made it (-continue)
FORM_FILE = "stabilityForm"


def run_form(method, full):
    """The Allrun arguments and end time of a method's run in a form"""
    return {"tutorial": method.tutorial,
            "args": method.full if full else method.coarse,
            "end": None if full else method.coarse_end}


#: The file of a run folder listing the builds that made it, one line a
#: run or continuation
BUILD_FILE = "stabilityBuilds"


def build_id(case):
    """The build a run is made with: the first 12 hexadecimal digits of the
    SHA-1 of the project's library and of the case's solver"""
    digest = hashlib.sha1()
    solver = lookup(read_dictionary(case, "system/controlDict"),
                    "application", "")
    for f in (os.path.join(PROJECT, "platforms", "lib", "libmeshless.so"),
              os.path.join(PROJECT, "platforms", "bin", solver)):
        if os.path.isfile(f):
            with open(f, "rb") as b:
                digest.update(b.read())
    return digest.hexdigest()[:12]


def note_build(case, how):
    with open(os.path.join(case, BUILD_FILE), "a") as f:
        f.write("%s %s\n" % (how, build_id(case)))


def builds(case):
    """The distinct builds that made a run (BUILD_FILE)"""
    try:
        with open(os.path.join(case, BUILD_FILE)) as f:
            return sorted({line.split()[-1] for line in f if line.split()})
    except OSError:
        return []


def end_reached(case, cost):
    """The case's endTime and whether its runs (cost: run_cost) reached it
    with a completed run"""
    end = float(lookup(read_dictionary(case, "system/controlDict"),
                       "endTime"))
    return end, cost["completed"] and abs(cost["time"] - end) < 1e-9


def continue_run(case, env):
    """Continues a run from its latest written time with the solver of its
    controlDict, in the project's environment; returns (exit code, wall
    seconds). A run that reached its end time is left as it is (exit code
    0, 0 s)"""
    try:
        if end_reached(case, run_cost(case))[1]:
            return 0, 0.0
    except Exception:
        pass
    try:
        solver = lookup(read_dictionary(case, "system/controlDict"),
                        "application")
        put_entry(case, "system/controlDict", "startFrom", "latestTime")
        n = sum(1 for f in os.listdir(case)
                if f.startswith("log.%s.continued" % solver))
        note_build(case, "continued")
        start = time.time()
        with open(os.path.join(case, "log.%s.continued%d" % (solver, n)),
                  "w") as log:
            code = subprocess.run(
                ["bash", "-c", '. "$MESHLESS_PROJECT/etc/bashrc" && exec'
                 ' "$0"', solver], cwd=case, env=env, stdout=log,
                stderr=subprocess.STDOUT).returncode
        return code, time.time() - start
    except Exception as e:
        print("%s: not continued: %s" % (case, e))
        return 1, 0.0


def make_run(method, full, work, threads, resume=False):
    """A clean copy of the tutorial run by its Allrun; returns (case, Allrun
    exit code, wall seconds). resume: a copy already made by the same form
    is continued (continue_run) instead"""
    tutorial = os.path.join(PROJECT, method.tutorial)
    case = os.path.join(work, os.path.basename(method.tutorial) + "-"
                        + "".join(c for c in method.name if c.isalnum()))
    env = dict(os.environ, OMP_NUM_THREADS=str(threads),
               MESHLESS_PROJECT=PROJECT)
    made = run_form(method, full)
    form = repr(made)
    formFile = os.path.join(case, FORM_FILE)
    # A run that reached its solver (a runCost file) made by this form
    if resume and os.path.isfile(formFile) \
            and open(formFile).read().strip() == form \
            and run_costs(case):
        code, seconds = continue_run(case, env)
        return case, code, seconds
    if os.path.isdir(case):
        shutil.rmtree(case)
    copy_case(tutorial, case, stored_results=False)
    subprocess.run(["./Allclean"], cwd=case, capture_output=True)
    monitor = "{ type energy; interval 1; %s}" % (
        "frame %s; " % method.frame if method.frame else "")
    put_entry(case, "constant/particleProperties",
              "monitors/stabilityEnergy", monitor)
    args, end = list(made["args"]), made["end"]
    if end is not None:
        put_entry(case, "system/controlDict", "endTime", "%g" % end)
        # The tutorials' own '-end' writes system/runTime, which wins
        if open(os.path.join(case, "Allrun")).read().find("-end)") >= 0:
            args = args + ["-end", "%g" % end]
    with open(formFile, "w") as f:
        f.write(form + "\n")
    note_build(case, "made")
    start = time.time()
    with open(os.path.join(case, "Allrun.log"), "w") as log:
        code = subprocess.run(["./Allrun"] + args, cwd=case, env=env,
                              stdout=log, stderr=subprocess.STDOUT
                              ).returncode
    return case, code, time.time() - start


# * * * * * * * * * * * * * * * The invariants  * * * * * * * * * * * * * //

class Grid:
    """Points in buckets of size r, for the neighbours within r"""

    def __init__(self, points, r):
        self.r = r
        self.points = points
        self.cells = {}
        for k, p in enumerate(points):
            self.cells.setdefault(self.key(p), []).append(k)

    def key(self, p):
        return (int(math.floor(p[0] / self.r)),
                int(math.floor(p[1] / self.r)))

    def near(self, p):
        """Indices of the points within r of p (p itself included)"""
        i, j = self.key(p)
        r2 = self.r * self.r
        for di in (-1, 0, 1):
            for dj in (-1, 0, 1):
                for k in self.cells.get((i + di, j + dj), ()):
                    q = self.points[k]
                    if (q[0] - p[0]) ** 2 + (q[1] - p[1]) ** 2 <= r2:
                        yield k

    def nearest(self, p):
        """(index, distance) of the nearest point within r, or None"""
        best = None
        for k in self.near(p):
            q = self.points[k]
            d = math.hypot(q[0] - p[0], q[1] - p[1])
            if best is None or d < best[1]:
                best = (k, d)
        return best


def finite(cloud):
    """The name of a field holding a non-finite value, or None"""
    for name, values in cloud.items():
        for v in values:
            for c in (v if isinstance(v, (list, tuple)) else (v,)):
                if isinstance(c, float) and not math.isfinite(c):
                    return name
    return None


def lattice_axes(points, dx):
    """The axes of the lattice a wall's particles lie on (a moving tank's
    turn with it): the direction between two of its particles one spacing
    dx apart, and the perpendicular; the x and y axes when no two are"""
    grid = Grid(points, 1.01 * dx)
    for p in points[:100]:
        for k in grid.near(p):
            q = points[k]
            r = math.hypot(q[0] - p[0], q[1] - p[1])
            if abs(r - dx) < 0.01 * dx:
                e = ((q[0] - p[0]) / r, (q[1] - p[1]) / r)
                return e, (-e[1], e[0])
    return (1.0, 0.0), (0.0, 1.0)


def wall_depth(fluid, wall, dxw, reach, over=None):
    """Deepest fluid particle inside a ghost wall [m]: of the wall particles
    within reach that lie along their own normal from it (the offset
    across the normal within half the wall's spacing dxw), the face is the
    wall particle's wallDistance in front of it along its normal (which
    points into the wall); the deepest of those. A depth above zero counts
    only for a particle inside the wall, the union of its particles'
    lattice cells, or behind a wall particle of a plane face (gone
    through the wall): at the open end of a wall (a tank without a lid)
    the particles that wrap round the end have normals from the end's
    edge, and the plane through the edge across such a normal cuts the
    open air beside the end, where a particle that rises past the wall's
    top is in no wall's cell. over: per fluid particle, whether it has
    flown over this wall (above every particle of it at a written time): a
    splash that lands beside the tank is behind a wall's face without
    having gone through it, so for such a particle only a wall's cells
    count"""
    x = wall["positions"]
    n, d = wall.get("normal"), wall.get("wallDistance")
    if n is None or d is None:
        return -math.inf
    grid = Grid(x, reach)
    axes = lattice_axes(x, dxw)
    half = 0.5 * dxw * (1 + 1e-9)

    def flat(s):
        """Whether the wall particle's normal is a lattice axis: its face
        a plane, not an edge"""
        return max(abs(n[s][0] * e[0] + n[s][1] * e[1]) for e in axes) \
            > 1 - 1e-6

    def inside(p):
        for s in grid.near(p):
            rx, ry = x[s][0] - p[0], x[s][1] - p[1]
            if all(abs(rx * e[0] + ry * e[1]) <= half for e in axes):
                return True
        return False

    deepest = -math.inf
    for k, p in enumerate(fluid):
        flown = over is not None and over[k]
        for s in grid.near(p):
            rx, ry = x[s][0] - p[0], x[s][1] - p[1]
            along = rx * n[s][0] + ry * n[s][1]
            if math.hypot(rx - along * n[s][0], ry - along * n[s][1]) \
                    > half:
                continue
            depth = d[s] - along
            if depth > deepest and (depth <= 0 or inside(p)
                                    or (along < 0 and flat(s)
                                        and not flown)):
                deepest = depth
    return deepest


def solid_depth(fluid, solid, dxs):
    """Deepest fluid particle inside a structure [m] (see the module's
    docstring)"""
    x = solid
    grid = Grid(x, 1.5 * dxs)
    outward = []
    for k, p in enumerate(x):
        cx = cy = 0.0
        m = 0
        for j in grid.near(p):
            if j != k:
                cx += x[j][0] - p[0]
                cy += x[j][1] - p[1]
                m += 1
        size = math.hypot(cx, cy)
        outward.append(None if m == 0 or size < 0.2 * dxs * m / 2
                       else (-cx / size, -cy / size))
    far = Grid(x, 2 * dxs)
    deepest = -math.inf
    for p in fluid:
        hit = far.nearest(p)
        if hit is None:
            continue
        s, dist = hit
        o = outward[s]
        if o is None:
            depth = max(dxs, 0.5 * dxs - dist)
        else:
            depth = 0.5 * dxs - ((p[0] - x[s][0]) * o[0]
                                 + (p[1] - x[s][1]) * o[1])
        deepest = max(deepest, depth)
    return deepest


def support(case, body, h):
    """The kernel support radius of a body [m]"""
    kernel = lookup(read_dictionary(case, "constant/particleProperties"),
                    "bodies/%s/kernel" % body, {})
    horizon = kernel.get("horizon")
    if horizon is None:
        horizon = SUPPORT.get(kernel.get("type"), 2.0)
    return float(horizon) * h


def open_counts(case, bodies):
    """{body: [(time, particles)]} of the open-boundary monitor (columns
    <body>.particles), or {} without open boundaries"""
    if not os.path.isdir(os.path.join(case, "postProcessing",
                                      "openBoundaries")):
        return {}
    columns, rows = monitor_rows(case, "openBoundaries")
    out = {}
    for k, c in enumerate(columns):
        b, _, what = c.partition(".")
        if what == "particles" and b in bodies:
            out[b] = [(r[0], r[k]) for r in rows]
    return out


def invariants(case):
    """{invariant: (figure text, met)} and the run's cost of a finished
    run"""
    cost = run_cost(case)
    bodies = cost["bodies"]
    fluids = [b for b, v in bodies.items() if v["model"] in FLUIDS]
    solids = [b for b, v in bodies.items() if v["model"] in SOLIDS]
    walls = [b for b, v in bodies.items() if v["model"] in WALLS]
    series = times(case)
    out = {}

    end, reached = end_reached(case, cost)
    out["reached"] = ("%g of %g s" % (cost["time"], end), reached)

    counts = open_counts(case, bodies)
    n0, lost, bad, deepest, splash = {}, None, None, -math.inf, 0.0
    deepest_where = ""
    # Per fluid and wall body, the ids seen above every particle of the
    # wall at a written time
    flew = {(f, w): set() for f in fluids for w in walls}
    for value, name in series:
        clouds = {b: read_cloud(case, name, b) for b in bodies
                  if os.path.isdir(os.path.join(case, name, "lagrangian", b))}
        for b, cloud in clouds.items():
            field = finite(cloud)
            if field and bad is None:
                bad = "%s %s at %g s" % (b, field, value)
            n = len(cloud["positions"])
            if b not in n0:
                n0[b] = n
            expected = n0[b]
            if b in counts:
                # The open-boundary monitor's count at this time
                rows = [c for t, c in counts[b] if t <= value + 1e-12]
                expected = int(round(rows[-1])) if rows else n0[b]
            if n != expected and lost is None:
                lost = "%s: %d, expected %d at %g s" % (b, n, expected,
                                                         value)
        # The top of each wall body at this time
        tops = {w: max((q[1] for q in clouds[w]["positions"]),
                       default=math.inf) for w in walls if w in clouds}
        for f in fluids:
            if f not in clouds:
                continue
            xf = clouds[f]["positions"]
            dxf = bodies[f]["spacing"]
            ids = clouds[f].get("id")
            for w in walls:
                if w in clouds:
                    over = None
                    if ids is not None:
                        flew[f, w].update(i for i, q in zip(ids, xf)
                                          if q[1] > tops[w])
                        over = [i in flew[f, w] for i in ids]
                    dxw = bodies[w]["spacing"]
                    d = wall_depth(xf, clouds[w], dxw,
                                   max(2 * dxf, 2 * dxw), over) / dxf
                    if d > deepest:
                        deepest, deepest_where = d, "%s in %s at %g s" % (
                            f, w, value)
            for s in solids:
                if s in clouds:
                    d = solid_depth(xf, clouds[s]["positions"],
                                    bodies[s]["spacing"]) / dxf
                    if d > deepest:
                        deepest, deepest_where = d, "%s in %s at %g s" % (
                            f, s, value)
            if "p" in clouds[f]:
                p = clouds[f]["p"]
                top = max((abs(v) for v in p), default=0.0)
                R = support(case, f, bodies[f]["h"])
                grid = Grid(xf, R)
                for k, q in enumerate(xf):
                    if abs(p[k]) > 1e-9 * top and \
                            not any(j != k for j in grid.near(q)):
                        splash = max(splash, abs(p[k]))
    out["finite"] = ("all finite" if bad is None else bad, bad is None)
    out["particles"] = ("kept" if lost is None else lost, lost is None)
    out["depth"] = ("%.2f dx%s" % (deepest, " (%s)" % deepest_where
                                   if deepest > DEPTH else ""),
                    deepest <= DEPTH)
    out["splash"] = ("none with p" if splash == 0 else
                     "largest |p| %.3g Pa" % splash, splash == 0)

    if counts:
        out["energy"] = ("not measured (open boundaries)", True)
    else:
        columns, rows = monitor_rows(case, "stabilityEnergy")
        total = [r[columns.index("total")] for r in rows]
        kin = [k for k, c in enumerate(columns) if c.endswith(":kinetic")]
        scale = max(sum(r[k] for k in kin) for r in rows)
        rise = largest_rise(total) / scale if scale > 0 else math.inf
        out["energy"] = ("rise %.3f of the largest kinetic energy" % rise,
                         rise <= ENERGY_RISE)
    return out, cost


INVARIANTS = ("reached", "finite", "particles", "depth", "energy", "splash")


def main(argv, name="stability", after=None):
    """The suite; after(work, threads) (optional: more checks on the runs,
    before the work folder goes) returns (passed, failed) to add to the
    count"""
    parser = argparse.ArgumentParser(prog="Allrun", add_help=False,
                                     allow_abbrev=False)
    parser.add_argument("-full", action="store_true")
    parser.add_argument("-keep", action="store_true")
    parser.add_argument("-case", action="append", default=[])
    parser.add_argument("-method", action="append", default=[])
    parser.add_argument("-threads", type=int, default=2)
    parser.add_argument("-work")
    parser.add_argument("-continue", dest="resume", action="store_true")
    try:
        opts = parser.parse_args(argv)
    except SystemExit:
        print(__doc__)
        return 2
    full, keep = opts.full, opts.keep
    cases, methods, threads = opts.case, opts.method, opts.threads
    work = os.path.abspath(opts.work) if opts.work else None
    if opts.resume and work is None:
        print("-continue needs -work DIR: the folder of the runs to"
              " continue")
        return 2
    known = {c.name for c in CASES}
    for c in cases:
        if c not in known:
            print("no case %s: the cases are %s" % (c, ", ".join(
                sorted(known))))
            return 2
    scratch = work is None
    if scratch:
        work = tempfile.mkdtemp(prefix="stability.")
    os.makedirs(work, exist_ok=True)

    rows, failed, passed = [], 0, 0
    try:
        for case in CASES:
            if cases and case.name not in cases:
                continue
            for method in case.methods:
                if methods and method.name not in methods:
                    continue
                path, code, seconds = make_run(method, full, work, threads,
                                               opts.resume)
                try:
                    inv, cost = invariants(path)
                except Exception as e:
                    failed += 1
                    rows.append((case, method, None, None,
                                 "no run (Allrun exit %d): %s" % (code, e)))
                    print("%s, %s: no run: %s" % (case.name, method.name, e))
                    continue
                missed = [k for k in INVARIANTS if not inv[k][1]]
                failed += len(missed)
                passed += len(INVARIANTS) - len(missed)
                made = run_form(method, full)
                form = " ".join(made["args"]) or "default"
                if made["end"] is not None:
                    form += " to %g s" % made["end"]
                made_by = len(builds(path))
                if made_by > 1:
                    form += " (%d builds)" % made_by
                rows.append((case, method, inv, cost, form))
                print("%s, %s (%s): %s" % (
                    case.name, method.name, form,
                    "; ".join("%s %s: %s" % (k, verdict(inv[k][1]),
                                             inv[k][0])
                              for k in INVARIANTS)))
                sys.stdout.flush()
        if after is not None:
            more = after(work, threads)
            passed += more[0]
            failed += more[1]
    finally:
        if scratch and not keep:
            shutil.rmtree(work, ignore_errors=True)

    lines = ["| case | method | run | %s | steps | wall time |"
             % " | ".join(INVARIANTS),
             "|---|---|---|%s---|---|" % ("---|" * len(INVARIANTS))]
    for case, method, inv, cost, form in rows:
        if inv is None:
            lines.append("| %s | %s | %s |%s | | |" % (
                case.name, method.name, form, " |" * len(INVARIANTS)))
            continue
        lines.append("| %s | %s | %s | %s | %d | %.0f s on %d thread%s |"
                     % (case.name, method.name, form, " | ".join(
                         "%s: %s" % (verdict(inv[k][1]), inv[k][0])
                         for k in INVARIANTS), cost["steps"], cost["wall"],
                        cost["threads"], "" if cost["threads"] == 1 else "s"))
    print()
    print("\n".join(lines))
    if full and not cases and not methods:
        with open(os.path.join(HERE, "result.md"), "w") as f:
            f.write("# Stability suite, full form\n\nCommand:"
                    " `tests/stability/Allrun -full`\n\n%s\n\nEnergy:"
                    " largest rise above the lowest earlier total, bound"
                    " %g of the run's largest kinetic energy. Depth: in"
                    " the fluid's spacings, bound %g.\n"
                    % ("\n".join(lines), ENERGY_RISE, DEPTH))
    print()
    print("%s: %d passed, %d failed" % (name, passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
