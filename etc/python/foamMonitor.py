"""Read what a meshlessFoam run leaves besides the clouds: the monitors'
time series (postProcessing/<name>/<startTime>/<name>.dat, one folder per
start of a run, joined in time order) and the cost figures of its log."""
import os
import re


def monitor_runs(case, name):
    """Monitor <name> per run, in time order: [(columns, rows)], one per
    start folder (a run and each of its restarts)"""
    base = os.path.join(case, "postProcessing", name)
    runs = []
    for start in sorted(os.listdir(base), key=float):
        columns, rows = None, []
        for line in open(os.path.join(base, start, name + ".dat")):
            if line.startswith("# time"):
                columns = line[2:].split()
            elif line.strip() and not line.startswith("#"):
                rows.append([float(v) for v in line.split()])
        if columns is None:
            raise RuntimeError("monitor %s has no header in %s/%s"
                               % (name, base, start))
        runs.append((columns, rows))
    return runs


def read_monitor(case, name):
    """Columns of monitor <name> as a dict: {'time': [...], column: [...]},
    a run and its restarts joined"""
    columns, rows = None, []
    for columns, own in monitor_runs(case, name):
        # a restart repeats its first time: keep the later run's
        while own and rows and rows[-1][0] >= own[0][0]:
            rows.pop()
        rows.extend(own)
    if columns is None:
        raise RuntimeError("monitor %s has no runs in %s"
                           % (name, os.path.join(case, "postProcessing")))
    return {c: [r[k] for r in rows] for k, c in enumerate(columns)}


def run_cost(log_file):
    """Steps, wall and CPU time [s], particle-steps per second, particle
    count and number of runs of a solver log. The log may hold a run and its
    restarts (the solver's output appended, each run from 'Create time'):
    their times add up. A run's wall time is its time loop's, from its cost
    table; a run that stopped (or is still going) has no table, and its last
    ClockTime stands for it. 'threads' is the last run's OpenMP thread
    count from the scene summary. The solver's particle-steps per second cover
    one whole run; otherwise the rate follows from the steps, particles and
    wall time."""
    log = open(log_file).read()
    runs = re.split(r"^Create time$", log, flags=re.M)[1:] or [log]
    timed = []
    for run in runs:
        loop = re.findall(r"time loop \(all\)\s+([0-9.e+-]+)", run)
        clock = re.findall(r"ClockTime = ([0-9.]+) s", run)
        cpu = re.findall(r"ExecutionTime = ([0-9.e+-]+) s", run)
        if clock:
            timed.append((float((loop or clock)[-1]), float(cpu[-1])))
    rate = re.findall(r"Particle-steps per second: ([0-9.e+-]+)", log)
    particles = re.findall(r"particles = (\d+)", log)
    threads = re.findall(r"OpenMP threads: (\d+)", log)
    cost = {
        "steps": len(re.findall(r"^Time = ", log, re.M)),
        "wall": sum(w for w, _ in timed) if timed else float("nan"),
        "cpu": sum(c for _, c in timed) if timed else float("nan"),
        "particles": int(particles[-1]) if particles else 0,
        "runs": len(runs),
        # the threads of the last run; 0 when the log predates the record
        "threads": int(threads[-1]) if threads else 0,
    }
    if len(runs) == 1 and rate:
        cost["rate"] = float(rate[-1])
    else:
        cost["rate"] = (cost["steps"] * cost["particles"] / cost["wall"]
                        if cost["wall"] > 0 else float("nan"))
    return cost


def wall_time(cost):
    """The wall time of run_cost with the threads it ran on, for tables:
    '150 s on 2 threads' (or '150 s' for a log without the record)"""
    n = cost.get("threads", 0)
    if not n:
        return "%.0f s" % cost["wall"]
    return "%.0f s on %d thread%s" % (cost["wall"], n, "" if n == 1 else "s")


def body_cost(case, body, walls=None, solver="ulphPdFoam"):
    """run_cost of the case's log.<solver> (a run and its restarts add up)
    with, from the scene summary at its start, the body's particle count
    (key: the body's name), spacing ("dx") and kernel's smoothing length
    ("h", nan for a body without a kernel), and the particle count of a
    walls body ("walls") when one is named"""
    log_file = os.path.join(case, "log." + solver)
    cost = run_cost(log_file)
    log = open(log_file).read()
    line = re.search(r"%s: (\d+) particles, spacing ([0-9.e-]+)(.*)" % body,
                     log)
    cost[body] = int(line.group(1)) if line else 0
    cost["dx"] = float(line.group(2)) if line else float("nan")
    h = re.search(r"kernel \w+ \(h ([0-9.e-]+)\)", line.group(3)) \
        if line else None
    cost["h"] = float(h.group(1)) if h else float("nan")
    if walls:
        nwall = re.search(r"%s: (\d+) particles" % walls, log)
        cost["walls"] = int(nwall.group(1)) if nwall else 0
    return cost


def case_spacing(case, default):
    """The particle spacing a tutorial's Allrun -dx wrote into
    system/resolution ('dx <value>;'), or the tutorial's default"""
    res = os.path.join(case, "system", "resolution")
    if os.path.exists(res):
        m = re.search(r"dx\s+([0-9.eE+-]+)", open(res).read())
        if m:
            return float(m.group(1))
    return default


def interp(t, ts, vs):
    """Linear interpolation of the series (ts, vs) at t, held constant
    beyond its ends"""
    if t <= ts[0]:
        return vs[0]
    for k in range(1, len(ts)):
        if t <= ts[k]:
            a = (t - ts[k - 1]) / (ts[k] - ts[k - 1])
            return vs[k - 1] + a * (vs[k] - vs[k - 1])
    return vs[-1]


def dictionary_entry(case, key, dictionary="constant/particleProperties"):
    """An entry of a case dictionary ('/'-scoped key, e.g. bodies/beam/density)
    with its $variables and #eval expanded, read through foamDictionary.
    Run from the case: foamDictionary takes $FOAM_CASE (the tutorials'
    #includeIfPresent "$FOAM_CASE/system/runParameters") from its working
    directory, so from elsewhere it would read the defaults"""
    import subprocess
    out = subprocess.run(
        ["foamDictionary", "-entry", key, "-value", dictionary],
        cwd=case, env=dict(os.environ, PWD=os.path.abspath(case)),
        check=True, capture_output=True, text=True).stdout
    return out.strip()


def save_run(folder, name, run):
    """One run's figures as 'key value' lines in <folder>/<name>.txt"""
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name + ".txt"), "w") as f:
        for k, v in run.items():
            f.write("%s %s\n" % (k, v))


def load_runs(folder):
    """Every run saved in folder, numbers as floats"""
    runs = []
    for name in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
        run = {}
        for line in open(os.path.join(folder, name)):
            k, v = line.split(None, 1)
            v = v.strip()
            try:
                run[k] = float(v)
            except ValueError:
                run[k] = v
        runs.append(run)
    return runs


def pyplot():
    """matplotlib's pyplot for writing PNGs (no display), or None with a
    message when matplotlib is missing (the figures are still written)"""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        return plt
    except ImportError:
        print("matplotlib missing: no plot")
        return None
