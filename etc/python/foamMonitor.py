"""Read what a meshlessFoam run leaves besides the clouds, and the pieces the
validation scripts share:
- the monitors' time series (postProcessing/<name>/<startTime>/<name>.dat,
  one folder per start of a run, joined in time order) and other tables
  (reference data, the coupling's forces): read_rows, monitor_runs,
  monitor_rows, read_monitor;
- the run cost (postProcessing/runCost/<startTime>/runCost, one per start
  of a run, read through foamDictionary; a run and its restarts add up):
  run_costs, run_cost, body_cost, cost_figures, wall_time;
- linear interpolation of a series (interp), matplotlib for PNGs (pyplot),
  a validation script's arguments and result names (arguments,
  case_spacing, result_suffix), and runs kept as 'key value' files
  (save_run, load_runs).
Dictionary entries: foamDict.
"""
import math
import os
import sys

from foamDict import dictionary_entry, read_dictionary


def _number(word):
    try:
        return float(word)
    except ValueError:
        return word


def read_rows(path):
    """Rows of a whitespace-separated text file: '#' starts a comment, blank
    lines are skipped, numbers are floats and other words strings"""
    rows = []
    with open(path) as f:
        for line in f:
            words = line.split("#", 1)[0].split()
            if words:
                rows.append([_number(w) for w in words])
    return rows


def _starts(case, name):
    """The start-time folders of postProcessing/<name>, in time order"""
    base = os.path.join(case, "postProcessing", name)
    names = os.listdir(base) if os.path.isdir(base) else []
    starts = []
    for start in names:
        try:
            starts.append((float(start), start))
        except ValueError:
            pass
    return [os.path.join(base, start) for _, start in sorted(starts)]


def monitor_runs(case, name, file=None):
    """Monitor <name> per run, in time order: [(columns, rows)], one per
    start folder (a run and each of its restarts); file: the .dat's name
    when it is not <name>.dat (the coupling's forces.dat). The columns are
    the words of the '# time ...' header line"""
    runs = []
    for folder in _starts(case, name):
        path = os.path.join(folder, file or name + ".dat")
        columns = None
        with open(path) as f:
            for line in f:
                if line.startswith("# time"):
                    columns = line[2:].split()
                    break
        if columns is None:
            raise RuntimeError("monitor %s has no header in %s" % (name, path))
        runs.append((columns, read_rows(path)))
    if not runs:
        raise RuntimeError("monitor %s has no runs in %s"
                           % (name, os.path.join(case, "postProcessing")))
    return runs


def monitor_rows(case, name, file=None):
    """(columns, rows) of monitor <name> over a run and its restarts: a
    restart repeats its first time, the later run's row is kept"""
    columns, rows = None, []
    for columns, own in monitor_runs(case, name, file):
        while own and rows and rows[-1][0] >= own[0][0]:
            rows.pop()
        rows.extend(own)
    return columns, rows


def read_monitor(case, name):
    """Columns of monitor <name> as a dict: {'time': [...], column: [...]},
    a run and its restarts joined"""
    columns, rows = monitor_rows(case, name)
    return {c: [r[k] for r in rows] for k, c in enumerate(columns)}


def run_costs(case):
    """The runCost dictionary of each run of the case (a run and each of
    its restarts), in time order; [] when there is none"""
    return [read_dictionary(case, os.path.relpath(
        os.path.join(folder, "runCost"), case))
        for folder in _starts(case, "runCost")]


def run_cost(case):
    """The cost of a case's runs, from their runCost files (a run and its
    restarts add up):
      steps, wall and cpu [s] (the time loops'), runs, and rate
      (particle-steps per second: the solver's for one run, else the
      particle-steps over the wall time of all);
      of the last run: solver, threads (OpenMP), time (the last time
      reached), completed (False for a run that stopped or is still
      going: its figures are those of its last write), particles (all
      bodies'), bodies {name: {model, particles, spacing, h}} (h nan for
      a body without a kernel);
      subSteps {name: {minSubSteps, most, mean}}: the sub-steps of a solid
      running alone (by its name) or of a coupling ('coupling') per step,
      most over all runs, mean over all steps;
      parts {name: {seconds, calls, share, usPerParticleStep}}: the time
      of each model, effect, coupling, the neighbour relations and the
      writes, over all runs (share: of the wall time)"""
    runs = run_costs(case)
    if not runs:
        raise RuntimeError(
            "no run cost in %s (postProcessing/runCost/<startTime>/runCost):"
            " the solver has not run there" % case)
    last = runs[-1]

    def total(key):
        return sum(float(r[key]) for r in runs)

    steps = int(total("steps"))
    wall = total("wallTime")
    particle_steps = total("particleSteps")
    bodies = {
        name: {"model": b["model"], "particles": int(b["particles"]),
               "spacing": float(b["spacing"]),
               "h": float(b.get("smoothingLength", "nan"))}
        for name, b in last.get("bodies", {}).items()}
    sub = {}
    for r in runs:
        for name, s in r.get("subSteps", {}).items():
            n = int(r["steps"])
            own = sub.setdefault(name, {"most": 0, "sum": 0.0, "steps": 0})
            own["minSubSteps"] = int(s["minSubSteps"])
            own["most"] = max(own["most"], int(s["most"]))
            own["sum"] += float(s["mean"]) * n
            own["steps"] += n
    parts = {}
    for r in runs:
        for name, p in r.get("parts", {}).items():
            own = parts.setdefault(name, {"seconds": 0.0, "calls": 0})
            own["seconds"] += float(p["seconds"])
            own["calls"] += int(p["calls"])
    for p in parts.values():
        p["share"] = p["seconds"] / wall if wall > 0 else math.nan
        p["usPerParticleStep"] = (1e6 * p["seconds"] / particle_steps
                                  if particle_steps > 0 else math.nan)
    return {
        "solver": last["solver"],
        "steps": steps,
        "wall": wall,
        "cpu": total("cpuTime"),
        "runs": len(runs),
        "rate": (float(last["particleStepsPerSecond"]) if len(runs) == 1
                 else particle_steps / wall if wall > 0 else math.nan),
        "threads": int(last["threads"]),
        "time": float(last["time"]),
        "completed": last["completed"] in ("true", "yes", "on", "1"),
        "particles": sum(b["particles"] for b in bodies.values()),
        "bodies": bodies,
        "subSteps": {
            name: {"minSubSteps": s["minSubSteps"], "most": s["most"],
                   "mean": s["sum"] / s["steps"] if s["steps"] else math.nan}
            for name, s in sub.items()},
        "parts": parts,
    }


def body_cost(case, body, walls=None):
    """run_cost with the body's particle count (key: the body's name),
    spacing ("dx") and smoothing length ("h", nan without a kernel), and
    the particle count of a walls body ("walls") when one is named"""
    cost = run_cost(case)
    own = cost["bodies"][body]
    cost[body] = own["particles"]
    cost["dx"] = own["spacing"]
    cost["h"] = own["h"]
    if walls:
        cost["walls"] = cost["bodies"][walls]["particles"]
    return cost


def cost_figures(case):
    """The figures of run_cost a validation keeps with each run
    (save_run): particles, steps, wall [s], rate (particle-steps per
    second) and threads"""
    cost = run_cost(case)
    return {k: cost[k] for k in ("particles", "steps", "wall", "rate",
                                 "threads")}


def wall_time(cost):
    """The wall time of run_cost with the threads it ran on, for tables:
    '150 s on 2 threads'"""
    n = cost["threads"]
    return "%.0f s on %d thread%s" % (cost["wall"], n, "" if n == 1 else "s")


def arguments(doc=None):
    """(case, check) of a validation script's command line 'validate.py
    <case> [--check]'; without a case: '.', or with doc (the script's
    usage) the usage printed and exit 2"""
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if not args and doc is not None:
        print(doc)
        sys.exit(2)
    return (args[0] if args else "."), "--check" in sys.argv


def case_spacing(case, default):
    """The particle spacing a tutorial's Allrun -dx wrote into
    system/resolution ('dx <value>;'), or the tutorial's default"""
    if not os.path.exists(os.path.join(case, "system", "resolution")):
        return default
    return float(dictionary_entry(case, "dx", "system/resolution", default))


def result_suffix(dx, default):
    """The suffix of a validation's result files: '' at the tutorial's own
    spacing, else '-dx<spacing>'"""
    return "" if abs(dx - default) < 1e-9 else "-dx%g" % dx


def interp(t, ts, vs, hold=True):
    """Linear interpolation of the series (ts, vs) at t, held constant
    beyond its ends; with hold=False None outside [ts[0], ts[-1]]"""
    if t < ts[0] or t > ts[-1]:
        if not hold:
            return None
        return vs[0] if t < ts[0] else vs[-1]
    if t == ts[0]:
        return vs[0]
    for k in range(1, len(ts)):
        if t <= ts[k]:
            a = (t - ts[k - 1]) / (ts[k] - ts[k - 1])
            return vs[k - 1] + a * (vs[k] - vs[k - 1])
    return vs[-1]


def save_run(folder, name, run):
    """One run's figures as 'key value' lines in <folder>/<name>.txt"""
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name + ".txt"), "w") as f:
        for k, v in run.items():
            f.write("%s %s\n" % (k, v))


def load_runs(folder):
    """Every run saved in folder: whole numbers as int, other numbers as
    float, the rest as strings"""
    runs = []
    for name in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
        run = {}
        for line in open(os.path.join(folder, name)):
            k, v = line.split(None, 1)
            v = v.strip()
            try:
                run[k] = int(v)
            except ValueError:
                run[k] = _number(v)
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
