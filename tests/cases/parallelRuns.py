#!/usr/bin/python3
"""Case test: the solvers run in parallel the OpenFOAM way (decomposePar,
mpirun -np N solver -parallel, reconstructPar) and give the serial run's
particles.

Every case is written in binary: decomposePar writes the exact positions
at controlDict's precision, and ascii's 10 digits move them off the seeded
lattice (a pair at a kernel's exact reach, as on a PD solid's lattice, is
then in or out of its relation).
- riemannSphFoam, the dam break at 2 mm (2261 particles, 186 steps to
  0.08 s), serially and decomposed three ways: simple (2 1 1: all the
  water on one processor, the other holding none, the walls split),
  hierarchical (1 3 1: the water column cut in three, its upper parts
  falling into the lower processors' parts) and scotch (2).
  Reconstructed at 0.04 and 0.08 s, every particle (by id) and every
  written field equals the serial run's to RTOL of the field's largest
  magnitude: the sums over neighbours run in another order (halo
  particles follow a processor's own), so the last bits differ (about
  1e-11 at 0.08 s). The time steps are the serial run's, bit for bit
  (the stable step is reduced over the processors), and the energy and
  pressure probe monitors (sums over every processor's particles,
  written by the master) equal the serial ones to their 12 printed
  digits.
- A parallel restart (hierarchical 1 3 1, startFrom latestTime on the
  decomposed case at 0.04 s) ends at 0.08 s equal, bit for bit, to the
  uninterrupted parallel run. Processors whose latest times differ (a
  kill between their commits of a write) stop the run (OpenFOAM's Time
  checks it); the commits wait for every processor's files.
- ulphPdFoam, its dam break at 2 mm to 0.01 s (the ULPH fluid on ghost
  walls, with its density filter), hierarchical (1 3 1): the same
  particles to RTOL.
- isphTlsphFoam, the ISPH dam break at 2 mm to 0.04 s with its walls'
  pressures solved, hierarchical (1 3 1): the pressure Poisson equation
  is one system over the processors (BoomerAMG, tolerance 1e-12: the
  multigrid's coarsening follows the partition, so the iterates differ
  at the tolerance), the same particles to ISPH_RTOL (1e-12 at 0.02 s,
  up to 7e-10 at 0.04 s in the accelerations, (u - u0)/dt). Later the
  runs part by more (1e-6 at 0.08 s): the free surface's and the walls'
  wetting are thresholds that a particle crosses in one run and not the
  other.
  With pressureSolver BiCGStab (one processor's) the run stops and asks
  for BoomerAMG.
- riemannSphFoam, the periodic Taylor-Green vortex (1/50, 40 steps to
  0.25 s), hierarchical (3 1 1): halos reach across the periodic sides,
  particles migrate across the processors' and the period's boundaries;
  the same particles to RTOL.
- Solids, held whole by every processor and owned particle by particle
  by the processor of the nearest cell (particleDistribution):
  - riemannSphFoam, the elastic gate coupled by riemannTlsph at 2.5 mm
    (gate 128 particles, owned 44/42/42 by 3 processors, hierarchical
    1 3 1) to 0.02 s, with the gate's explicit (verlet) and implicit
    integrators: every field to RTOL but the rates (RATES: accelerations,
    density rates, dissipative forces) to RATES_RTOL: a stiff solid's
    accelerations are its positions' last bits times c^2/h^2 (5e9 here), so positions equal to
    an ulp give accelerations equal to about 2e-8. A parallel restart of
    the coupled case (verlet, at 0.01 s) ends bit for bit on the
    uninterrupted parallel run. (The implicit integrator makes its
    tangent again at a restart, so Newton's iterates differ at its
    tolerance, serially too.)
  - ulphPdFoam, the fracturing obstacle at 4 mm (NOSB-PD, owned by one
    of 3 processors, bonds breaking from a stretch of 2e-5: 36 broken at
    0.01 s): the water to RTOL (1e-11), the obstacle bit for bit; a
    parallel restart at 0.005 s (the master writes the broken bonds, every
    processor reads them) ends bit for bit on the uninterrupted run.
  - riemannSphFoam, the Turek-Hron channel at 2 cm (inflow buffer and
    outflow, riemannTlsph flag) to 1 s, hierarchical (3 1 1): 159
    particles emitted, 40 leave; the copies' ids follow their sources'
    ids over every processor, so the same particles carry the same ids as
    serially; fields to RTOL (rates and dissipative forces to
    RATES_RTOL), the open boundaries' counts (reduced) equal.
  - isphTlsphFoam, the oscillating plate alone (TLSPH, 1050 particles,
    2 processors): bit for bit (every processor steps the whole solid).
  - isphTlsphFoam, the hydrostatic plate (isphTlsph coupling, the plate's
    particles in the distributed Poisson equation, owned 120/104/128 by
    3 processors), its interface iterations (IQN-ILS) to 1e-10 and the
    pressure to 1e-12: to ISPH_RTOL (1e-10 in the water, 3e-9 in the
    plate's velocities, which are tiny). With the tutorials' interface
    tolerance 1e-4 the iterations amplify the last bits to the tolerance,
    so such runs agree only to it.
- ulphPdFoam, the sluice gate at 3.5 mm to 0.002 s, simple (2 1 1): the
  tank's ghost particles whose supports reach past its deepest seeded
  layer have their shape tensors completed; the deepest layer is the
  whole wall's (a processor's part may lack a corner's deepest
  particles: the corner's fluid particle then moved 40 % differently
  after a step). The same particles to RTOL, and as many completed.
- ulphPdFoam, the cantilever beam at 2 cm (NOSB-PD, clamped on a
  cellZone), simple (2 1 1): every processor holds the whole beam but
  only its part of the mesh, so a constraint's region of cells is
  combined over the processors; bit for bit.
- riemannSphFoam, the Liao plate at 2 mm (TLSPH, `walls (tank)`) pushed
  over by a body force of 300 m/s^2, hierarchical (4 1 1: the plate's
  right face on the cut at x = 0.6 m, so that it folds from one
  processor's part into the next's): it lies on the floor at 0.03 s (its
  lowest particle dx/2 above it; through it without the contact) and
  springs back by 0.06 s; the contact of each particle is its owner's,
  shared: the same particles to RTOL.
- The distributed linear solve (tests/parallel/parallelLinearSolve):
  a symmetric and a non-symmetric system of 3600 rows split over 2 and 3
  processors, solved by BoomerAMG on every processor's rows, to the
  exact solution, with the whole system's residual; the same serially.
- particleFoam, the free fall split across the fall (hierarchical 1 2 1):
  the drop's particles migrate from the upper processor to the lower one
  and the reconstructed clouds equal the serial ones bit for bit (no pair
  interactions, so no summation order). In three slabs (1 3 1) the middle
  processor holds no particle at the first write (OpenFOAM makes the
  mesh's tet base points with a collective exchange when first asked
  for: such a processor never asked, and the run hung there); bit for
  bit too.
"""
import os
import re
import shutil
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import copy_case, project_dir, run, run_parts  # noqa: E402
from caseTest import set_entry  # noqa: E402

from foamCloud import read_cloud  # noqa: E402

RTOL = 1e-10
ISPH_RTOL = 1e-8
RATES_RTOL = 1e-7
RATES = ("acceleration", "averageAcceleration", "densityRate",
         "dissipativeAcceleration", "fluidDissipativeForce")
MONITOR_RTOL = 1e-9
HEADER = "FoamFile { version 2.0; format ascii; class dictionary;" \
    " object %s; }\n"
DAM_BREAK = [
    ("simple", 2, "coeffs { n (2 1 1); }"),
    ("hierarchical", 3, "coeffs { n (1 3 1); order xyz; }"),
    ("scotch", 2, ""),
]
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMP_NUM_THREADS="1",
               OMPI_MCA_mpi_yield_when_idle="1")


def mpirun(n, solver, case):
    import subprocess
    p = subprocess.run(["mpirun", "--oversubscribe", "-np", str(n), solver,
                        "-parallel"], cwd=case, capture_output=True,
                       text=True, env=MPI_ENV)
    return p.returncode, p.stdout + p.stderr


def decompose_dict(case, method, n, coeffs):
    with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
        f.write(HEADER % "decomposeParDict"
                + "numberOfSubdomains %d;\nmethod %s;\n%s\n"
                % (n, method, coeffs))


def prepared(t, tutorial, case, dx, end, interval, entries=(), files=()):
    copy_case(os.path.join(project_dir, tutorial), case)
    for name, text in files:
        with open(os.path.join(case, name), "w") as f:
            f.write(text)
    for dictionary, key, value in entries:
        if value is None:
            code, out = run(["foamDictionary", dictionary, "-entry", key,
                             "-remove"], case)
            if code != 0:
                raise RuntimeError(out)
        else:
            set_entry(case, dictionary, key, value)
    if dx:
        # a spacing, or the tutorial's own resolution entries
        with open(os.path.join(case, "system", "resolution"), "w") as f:
            f.write(dx if isinstance(dx, str) else "dx %s;\n" % dx)
    # binary: decomposePar writes the exact positions at controlDict's
    # precision (ascii 10 digits would move them off the seeded lattice,
    # and a pair at a kernel's exact reach in or out of it)
    for key, value in (("endTime", end), ("writeInterval", interval),
                       ("writeFormat", "binary")):
        set_entry(case, "system/controlDict", key, value)
    for cmd in ("blockMesh", "seedParticles"):
        code, out = run([cmd], case)
        if code != 0:
            t.check("%s: %s succeeds" % (case, cmd), False, out[-1500:])
            return False
    return True


def seeded_copy(src, dst):
    """The seeded case without its results"""
    shutil.copytree(src, dst, ignore=shutil.ignore_patterns(
        "processor*", "log.*", "postProcessing", "0.*", "[1-9]*"))
    return dst


def parallel_run(t, case, solver, name, method, n, coeffs):
    decompose_dict(case, method, n, coeffs)
    code, out = run(["decomposePar"], case)
    t.check("%s: decomposePar succeeds" % name, code == 0, out[-1500:])
    if code != 0:
        return False
    code, out = mpirun(n, solver, case)
    with open(os.path.join(case, "log." + solver), "w") as f:
        f.write(out)
    t.check("%s: mpirun -np %d %s -parallel succeeds" % (name, n, solver),
            code == 0, out[-2000:])
    if code != 0:
        return False
    code, out = run(["reconstructPar"], case)
    t.check("%s: reconstructPar succeeds" % name, code == 0, out[-1500:])
    return code == 0


def worst_difference(a, b):
    """Largest |a - b| over the particles (matched by id) of every field,
    relative to the field's largest magnitude; None when the ids differ"""
    ia = {i: k for k, i in enumerate(a["id"])}
    ib = {i: k for k, i in enumerate(b["id"])}
    if set(ia) != set(ib):
        return None
    worst = {}
    for f in sorted(a):
        if f == "id" or f not in b:
            continue
        diff = scale = 0.0
        for i, ka in ia.items():
            va, vb = a[f][ka], b[f][ib[i]]
            if not isinstance(va, (list, tuple)):
                va, vb = [va], [vb]
            for x, y in zip(va, vb):
                diff = max(diff, abs(x - y))
                scale = max(scale, abs(x))
        worst[f] = diff / scale if scale > 0 else diff
    return worst


def same_clouds(t, name, serial, case, bodies, times, rtol, rates=None):
    """Every field of every body equal to rtol; with rates, the rates
    (RATES: accelerations, density rates) to that tolerance apart"""
    for time in times:
        for body in bodies:
            w = worst_difference(read_cloud(serial, time, body),
                                 read_cloud(case, time, body))
            if w is None:
                t.check("%s: %s at %s s has the serial run's particles"
                        % (name, body, time), False)
                continue
            groups = [("", rtol, w)]
            if rates is not None:
                groups = [
                    ("", rtol, {f: v for f, v in w.items()
                                if f not in RATES}),
                    (" rates", rates, {f: v for f, v in w.items()
                                       if f in RATES})]
            for what, tol, fields in groups:
                if not fields:
                    continue
                field, value = max(fields.items(), key=lambda kv: kv[1])
                t.check("%s: %s%s at %s s equals the serial run to %g"
                        " (largest difference %.1e, %s)"
                        % (name, body, what, time, tol, value, field),
                        value <= tol)


def log_steps(case, solver):
    with open(os.path.join(case, "log." + solver)) as f:
        return [line.split()[2] for line in f if line.startswith("deltaT =")]


def monitor_rows(case, name):
    path = os.path.join(case, "postProcessing", name, "0", name + ".dat")
    with open(path) as f:
        return [[float(v) for v in line.split()] for line in f
                if not line.startswith("#")]


def same_monitor(t, name, serial, case, monitor):
    a, b = monitor_rows(serial, monitor), monitor_rows(case, monitor)
    if len(a) != len(b):
        t.check("%s: %s monitor has the serial run's %d rows (got %d)"
                % (name, monitor, len(a), len(b)), False)
        return
    scale = [max(abs(r[c]) for r in a) or 1 for c in range(len(a[0]))]
    worst = max(abs(x - y) / s for ra, rb in zip(a, b)
                for x, y, s in zip(ra, rb, scale))
    t.check("%s: %s monitor equals the serial one to %g (largest %.1e)"
            % (name, monitor, MONITOR_RTOL, worst), worst <= MONITOR_RTOL)


def processor_count(case, proc, time, body):
    d = os.path.join(case, "processor%d" % proc, time, "lagrangian", body)
    if not os.path.isdir(d):
        return 0
    return len(read_cloud(os.path.join(case, "processor%d" % proc), time,
                          body)["id"])


def dam_break(t, work):
    solver = "riemannSphFoam"
    serial = os.path.join(work, "damBreak")
    if not prepared(t, "tutorials/riemannSphFoam/damBreak", serial, 0.002,
                    0.08, 0.04):
        return
    seeded = seeded_copy(serial, os.path.join(work, "damBreakSeeded"))
    code, out = run([solver], serial)
    with open(os.path.join(serial, "log." + solver), "w") as f:
        f.write(out)
    t.check("serial run succeeds", code == 0, out[-1500:])
    if code != 0:
        return
    steps = log_steps(serial, solver)
    for method, n, coeffs in DAM_BREAK:
        name = "%s%d" % (method, n)
        case = seeded_copy(seeded, os.path.join(work, name))
        if not parallel_run(t, case, solver, name, method, n, coeffs):
            continue
        same_clouds(t, name, serial, case, ("water", "walls"),
                    ("0.04", "0.08"), RTOL)
        t.check_equal("%s: the time steps are the serial run's (%d)"
                      % (name, len(steps)), log_steps(case, solver), steps)
        for monitor in ("energy", "sensor"):
            same_monitor(t, name, serial, case, monitor)
        counts = [[processor_count(case, p, time, "water")
                   for p in range(n)] for time in ("0", "0.08")]
        print("    %s: water per processor at 0 and 0.08 s: %s"
              % (name, counts))
        if method == "hierarchical":
            t.check("%s: the water column is split at 0 s %s"
                    % (name, counts[0]), min(counts[0][:2]) > 0)
            t.check("%s: water moved to the lowest processor %s"
                    % (name, counts), counts[1][0] > counts[0][0])
            restart(t, seeded, case, solver, method, n, coeffs)
        if method == "simple":
            t.check("%s: a processor holds no water %s" % (name, counts[0]),
                    min(counts[0]) == 0)


def restart(t, seeded, uninterrupted, solver, method, n, coeffs,
            name="restart", bodies=("water", "walls"), times=("0.04", "0.08"),
            kill=True):
    """The decomposed case run to times[0], continued to times[1]: bit for
    bit the uninterrupted parallel run"""
    case = seeded_copy(seeded, os.path.join(os.path.dirname(seeded), name))
    set_entry(case, "system/controlDict", "endTime", times[0])
    if not parallel_run(t, case, solver, "%s to %s s" % (name, times[0]),
                        method, n, coeffs):
        return
    set_entry(case, "system/controlDict", "endTime", times[1])
    set_entry(case, "system/controlDict", "startFrom", "latestTime")
    code, out = mpirun(n, solver, case)
    t.check("%s: the decomposed case continues from %s s" % (name, times[0]),
            code == 0 and "Create polyMesh for time = %s" % times[0] in out,
            out[-1500:])
    if code != 0:
        return
    code, out = run(["reconstructPar", "-latestTime"], case)
    t.check("%s: reconstructPar succeeds" % name, code == 0, out[-1500:])
    same_clouds(t, name, uninterrupted, case, bodies, (times[1],), 0)
    if not kill:
        return

    # As a kill between the processors' commits of a write leaves them:
    # one processor without the latest time
    shutil.rmtree(os.path.join(case, "processor1", times[1]))
    set_entry(case, "system/controlDict", "endTime",
              "%g" % (1.5*float(times[1]) - 0.5*float(times[0])))
    code, out = mpirun(n, solver, case)
    t.check("%s: processors at different latest times stop the run"
            " (OpenFOAM's Time: start time not the same)" % name,
            code != 0 and "Start time is not the same" in out, out[-1500:])


def serial_and_parallel(t, work, name, tutorial, solver, dx, times,
                        method, n, coeffs, entries=(), files=()):
    """The tutorial run serially and decomposed to the last of times
    (written at each), with entries [(dictionary, key, value)] set; the
    cases (serial, parallel), or None"""
    serial = os.path.join(work, name)
    if not prepared(t, tutorial, serial, dx, float(times[-1]),
                    float(times[0]), entries, files):
        return None
    case = seeded_copy(serial, os.path.join(work, name + "Parallel"))
    code, out = run([solver], serial)
    with open(os.path.join(serial, "log.serial"), "w") as f:
        f.write(out)
    t.check("%s: serial run succeeds" % name, code == 0, out[-1500:])
    if code != 0 or not parallel_run(t, case, solver, name, method, n,
                                     coeffs):
        return None
    return serial, case


def compared(t, work, name, tutorial, solver, dx, times, method, n,
             coeffs, bodies, rtol, rates=None, entries=(), files=()):
    """serial_and_parallel, then every body's clouds compared at times
    (same_clouds); the cases (serial, parallel), or None"""
    cases = serial_and_parallel(t, work, name, tutorial, solver, dx, times,
                                method, n, coeffs, entries, files)
    if cases:
        same_clouds(t, name, cases[0], cases[1], bodies, times, rtol,
                    rates)
    return cases


def ulph_dam_break(t, work):
    cases = serial_and_parallel(
        t, work, "ulph", "tutorials/ulphPdFoam/damBreak", "ulphPdFoam",
        0.002, ("0.005", "0.01"), "hierarchical", 3,
        "coeffs { n (1 3 1); order xyz; }")
    if cases:
        same_clouds(t, "ulph", cases[0], cases[1], ("water", "walls"),
                    ("0.005", "0.01"), RTOL)


def isph_dam_break(t, work):
    cases = serial_and_parallel(
        t, work, "isph", "tutorials/isphTlsphFoam/damBreak", "isphTlsphFoam",
        0.002, ("0.02", "0.04"), "hierarchical", 3,
        "coeffs { n (1 3 1); order xyz; }",
        [("constant/particleProperties", "bodies/water/pressureSolver",
          "{ solver BoomerAMG; tolerance 1e-12; maxIter 2000; }")])
    if not cases:
        return
    same_clouds(t, "isph", cases[0], cases[1], ("water", "walls"),
                ("0.02", "0.04"), ISPH_RTOL)
    # A solver of one processor's system is refused by name
    set_entry(cases[1], "constant/particleProperties",
              "bodies/water/pressureSolver/solver", "BiCGStab")
    code, out = mpirun(3, "isphTlsphFoam", cases[1])
    t.check("isph: pressureSolver BiCGStab in parallel stops, asking for"
            " BoomerAMG", code != 0 and "expected solver BoomerAMG" in out,
            out[-1500:])


def taylor_green(t, work):
    cases = serial_and_parallel(
        t, work, "taylorGreen", "tutorials/riemannSphFoam/taylorGreen",
        "riemannSphFoam", None, ("0.125", "0.25"), "hierarchical", 3,
        "coeffs { n (3 1 1); order xyz; }")
    if not cases:
        return
    serial, case = cases
    same_clouds(t, "taylorGreen", serial, case, ("water",),
                ("0.125", "0.25"), RTOL)
    counts = [[processor_count(case, p, time, "water") for p in range(3)]
              for time in ("0", "0.25")]
    t.check("taylorGreen: particles migrated %s" % counts,
            counts[0] != counts[1] and sum(counts[0]) == sum(counts[1]))


def riemann_gate(t, work):
    for integrator in ("verlet", "implicit"):
        name = "riemannGate-" + integrator
        cases = serial_and_parallel(
            t, work, name, "tutorials/riemannSphFoam/elasticGate",
            "riemannSphFoam", 0.0025, ("0.01", "0.02"), "hierarchical", 3,
            "coeffs { n (1 3 1); order xyz; }",
            [("constant/particleProperties", "bodies/gate/integrator",
              integrator)])
        if not cases:
            continue
        same_clouds(t, name, cases[0], cases[1], ("water", "gate"),
                    ("0.01", "0.02"), RTOL, RATES_RTOL)
        if integrator == "verlet":
            # (the implicit integrator's tangent is made again at a
            # restart: Newton's iterates differ at its tolerance, serially
            # too)
            restart(t, cases[0], cases[1], "riemannSphFoam", "hierarchical",
                    3, "coeffs { n (1 3 1); order xyz; }",
                    name="riemannGateRestart", bodies=("water", "gate"),
                    times=("0.01", "0.02"), kill=False)


def pd_obstacle(t, work):
    cases = serial_and_parallel(
        t, work, "pdObstacle", "tutorials/ulphPdFoam/obstacleFracture",
        "ulphPdFoam", 0.004, ("0.005", "0.01"), "hierarchical", 3,
        "coeffs { n (3 1 1); order xyz; }",
        [("constant/particleProperties",
          "bodies/obstacle/failure/criticalStretch", 2e-5)])
    if not cases:
        return
    same_clouds(t, "pdObstacle", cases[0], cases[1], ("water", "obstacle"),
                ("0.005", "0.01"), RTOL, RATES_RTOL)
    restart(t, cases[0], cases[1], "ulphPdFoam", "hierarchical", 3,
            "coeffs { n (3 1 1); order xyz; }", name="pdObstacleRestart",
            bodies=("water", "obstacle"), times=("0.005", "0.01"),
            kill=False)


def open_channel(t, work):
    cases = compared(
        t, work, "openChannel", "tutorials/riemannSphFoam/turekHronFSI2",
        "riemannSphFoam", 0.02, ("0.5", "1"), "hierarchical", 3,
        "coeffs { n (3 1 1); order xyz; }", ("water", "flag"), RTOL,
        RATES_RTOL)
    if not cases:
        return
    flux = [monitor_rows(c, "openBoundaries")[-1] for c in cases]
    t.check("openChannel: the particles in and out (inflow, outflow) as"
            " serially: %s, %s" % (flux[0][1:], flux[1][1:]),
            flux[0] == flux[1] and flux[0][2] > 0)
    # The serial case's 0.5 s decomposed and continued in parallel: every
    # processor finds the serial counts in its copy of the time's uniform
    # folder, which the master continues
    cont = os.path.join(work, "openChannelContinued")
    shutil.copytree(cases[0], cont, ignore=shutil.ignore_patterns(
        "processor*", "postProcessing", "log.*", "1"))
    set_entry(cont, "system/controlDict", "startFrom", "latestTime")
    decompose_dict(cont, "hierarchical", 3, "coeffs { n (3 1 1); order xyz; }")
    code, out = run(["decomposePar", "-latestTime"], cont)
    t.check("openChannel: decomposePar of the serial 0.5 s", code == 0,
            out[-1500:])
    if code != 0:
        return
    code, out = mpirun(3, "riemannSphFoam", cont)
    t.check("openChannel: the decomposed 0.5 s continues in parallel",
            code == 0, out[-1500:])
    if code != 0:
        return
    path = os.path.join(cont, "postProcessing", "openBoundaries", "0.5",
                        "openBoundaries.dat")
    with open(path) as f:
        last = [[float(v) for v in line.split()] for line in f
                if not line.startswith("#")][-1]
    t.check("openChannel: the continued counts at 1 s are the serial"
            " run's: %s, %s" % (last[1:], flux[0][1:]), last == flux[0])


def tlsph_plate(t, work):
    cases = serial_and_parallel(
        t, work, "tlsphPlate", "tutorials/isphTlsphFoam/oscillatingPlate",
        "isphTlsphFoam", None, ("0.005", "0.01"), "hierarchical", 2,
        "coeffs { n (2 1 1); order xyz; }",
        files=[("system/runParameters", "dx 0.002;\n")])
    if cases:
        # Every processor steps the whole solid in the same order
        same_clouds(t, "tlsphPlate", cases[0], cases[1], ("plate",),
                    ("0.005", "0.01"), 0)


def isph_plate(t, work):
    cases = serial_and_parallel(
        t, work, "isphPlate", "tutorials/isphTlsphFoam/hydrostaticPlate",
        "isphTlsphFoam", "n 4;\n", ("0.005", "0.01"), "hierarchical", 3,
        "coeffs { n (3 1 1); order xyz; }",
        [("constant/particleProperties", "bodies/water/pressureSolver",
          "{ solver BoomerAMG; tolerance 1e-12; maxIter 2000; }"),
         ("constant/particleProperties", "coupling/iterations",
          "{ maxIterations 50; tolerance 1e-10; }")])
    if cases:
        same_clouds(t, "isphPlate", cases[0], cases[1], ("water", "plate"),
                    ("0.005", "0.01"), ISPH_RTOL, RATES_RTOL)


def wall_corner(t, work):
    """A ghost wall's shape tensors completed behind its deepest layer:
    the deepest layer over the whole wall (a processor's part may lack a
    corner's deepest particles)"""
    cases = compared(
        t, work, "wallCorner", "tutorials/ulphPdFoam/sluiceGate",
        "ulphPdFoam", 0.0035, ("0.001", "0.002"), "simple", 2,
        "coeffs { n (2 1 1); }", ("water", "gate"), RTOL, RATES_RTOL)
    if not cases:
        return
    completed = []
    for case, log in zip(cases, ("log.serial", "log.ulphPdFoam")):
        path = os.path.join(case, log)
        text = open(path).read() if os.path.isfile(path) else ""
        m = re.search(r"completed behind the seeded layers for (\d+)", text)
        completed.append(m and int(m.group(1)))
    t.check("wallCorner: the tank's shape tensors completed for as many"
            " particles as serially %s" % completed,
            completed[0] is not None and completed[0] == completed[1] > 0)


def clamp_zone(t, work):
    """A solid's constraint on a region of cells (cellZone), alone and in
    a difference: every processor holds the whole solid but only its
    part of the mesh"""
    compared(t, work, "clampZone", "tutorials/ulphPdFoam/cantileverBeam",
             "ulphPdFoam", 0.02, ("5e-05", "0.0001"), "simple", 2,
             "coeffs { n (2 1 1); }", ("beam",), 0)
    # The same clamp as a difference: a box reaching into the other
    # processor's part, less the beam's zone (each particle's answer is
    # that of the processor holding its cell)
    region = ("{ type difference; regions ({ type box; min (-1 -1 -1);"
              " max (0.75 1 1); } { type cellZone; zone beam; }); }")
    cases = compared(
        t, work, "clampDifference", "tutorials/ulphPdFoam/cantileverBeam",
        "ulphPdFoam", 0.02, ("5e-05", "0.0001"), "simple", 2,
        "coeffs { n (2 1 1); }", ("beam",), 0,
        entries=[("constant/particleProperties",
                  "bodies/beam/constraints/root/region", region)])
    if cases:
        held = [re.findall(r"constraint root: .*",
                           open(os.path.join(c, f)).read())
                for c, f in zip(cases, ("log.serial", "log.ulphPdFoam"))]
        t.check("clampDifference: the clamp holds as many particles as"
                " serially %s" % held, held[0] == held[1] != [])


def wall_contact(t, work):
    """A solid's contact with a wall, computed by each particle's owner and
    shared: the Liao plate at 2 mm pushed over by a body force of 300
    m/s^2 (the gate held still) lies on the floor at 0.03 s and springs
    back by 0.06 s"""
    entries = [
        ("constant/particleProperties", "bodies/gate/motion", None),
        ("constant/particleProperties",
         "bodies/plate/effects/gravity/value", "(300 -9.81 0)")]
    cases = compared(
        t, work, "wallContact", "tutorials/riemannSphFoam/liaoPlate",
        "riemannSphFoam", 0.002, ("0.03", "0.06"), "hierarchical", 4,
        "coeffs { n (4 1 1); order xyz; }", ("water", "plate"), RTOL,
        RATES_RTOL, entries)
    if not cases:
        return
    # The contact acts: without it the plate goes into the floor
    free = os.path.join(work, "wallContactFree")
    if not prepared(t, "tutorials/riemannSphFoam/liaoPlate", free, 0.002,
                    0.06, 0.03, entries + [("constant/particleProperties",
                                            "bodies/plate/walls", None)]):
        return
    code, out = run(["riemannSphFoam"], free)
    t.check("wallContact: the run without the contact succeeds", code == 0,
            out[-1500:])
    if code != 0:
        return
    lowest = [min(y for x, y, *z in read_cloud(case, "0.03", "plate")
                  ["positions"] if x > 0.6) for case in (cases[0], free)]
    t.check("wallContact: at 0.03 s the folded plate lies on the floor"
            " (lowest particle right of its foot at %.4f m, dx/2 0.001 m)"
            " and without the contact goes through it (%.4f m)"
            % tuple(lowest), 0 < lowest[0] < 0.002 and lowest[1] < 0)


def linear_solve(t, work):
    import subprocess
    for n in (1, 2, 3):
        if n == 1:
            cmd = ["parallelLinearSolve"]
            p = subprocess.run(cmd, cwd=work, capture_output=True, text=True)
        else:
            cmd = ["mpirun", "--oversubscribe", "-np", str(n),
                   "parallelLinearSolve", "-parallel"]
            p = subprocess.run(cmd, cwd=work, capture_output=True, text=True,
                               env=MPI_ENV)
        out = p.stdout + p.stderr
        passes = out.count("[  PASS  ]")
        t.check("linear solve on %d processor(s): %d checks passed, none"
                " failed" % (n, passes),
                p.returncode == 0 and passes == 8 and "FAIL" not in out,
                out[-2000:])


def free_fall(t, work):
    cases = serial_and_parallel(
        t, work, "freeFall", "tutorials/particleFoam/freeFall",
        "particleFoam", None, ("0.02", "0.1"), "hierarchical", 2,
        "coeffs { n (1 2 1); order xyz; }")
    if not cases:
        return
    serial, case = cases
    counts = [[processor_count(case, p, time, "drop") for p in range(2)]
              for time in ("0", "0.1")]
    t.check("freeFall: the drop migrates to the lower processor %s" % counts,
            counts[0][0] < counts[1][0] and sum(counts[0]) == sum(counts[1]))
    same_clouds(t, "freeFall", serial, case, ("drop", "floor"),
                ("0.02", "0.1"), 0)
    # Three slabs: the middle processor holds no particle at the first
    # write (a processor that locates none still takes part in OpenFOAM's
    # collective set-up of the mesh's tet base points: it hung before)
    empty = seeded_copy(serial, os.path.join(work, "freeFall3"))
    if not parallel_run(t, empty, "particleFoam", "freeFall3",
                        "hierarchical", 3, "coeffs { n (1 3 1); order xyz; }"):
        return
    counts = [processor_count(empty, p, "0.02", "drop")
              + processor_count(empty, p, "0.02", "floor") for p in range(3)]
    t.check("freeFall3: the middle processor holds no particle at the first"
            " write %s" % counts, counts[1] == 0 and min(counts[::2]) > 0)
    same_clouds(t, "freeFall3", serial, empty, ("drop", "floor"),
                ("0.02", "0.1"), 0)


if __name__ == "__main__":
    if shutil.which("mpirun") is None:
        print("parallelRuns: no mpirun (openmpi-bin), nothing to test")
        sys.exit(1)
    sys.exit(run_parts("parallelRuns", dam_break, ulph_dam_break,
                       isph_dam_break, taylor_green, riemann_gate,
                       pd_obstacle, open_channel, tlsph_plate, isph_plate,
                       wall_corner, clamp_zone, wall_contact, linear_solve,
                       free_fall))
