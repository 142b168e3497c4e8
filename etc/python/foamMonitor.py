"""Read what a meshlessFoam run leaves besides the clouds: the monitors'
time series (postProcessing/<name>/<startTime>/<name>.dat, one folder per
start of a run, joined in time order) and the cost figures of its log."""
import os
import re


def read_monitor(case, name):
    """Columns of monitor <name> as a dict: {'time': [...], column: [...]}"""
    base = os.path.join(case, "postProcessing", name)
    starts = sorted(os.listdir(base), key=float)
    columns, rows = None, []
    for start in starts:
        path = os.path.join(base, start, name + ".dat")
        for line in open(path):
            if line.startswith("# time"):
                columns = line[2:].split()
            elif line.strip() and not line.startswith("#"):
                values = [float(v) for v in line.split()]
                # a restart repeats its first time: keep the later run's
                while rows and rows[-1][0] >= values[0]:
                    rows.pop()
                rows.append(values)
    if columns is None:
        raise RuntimeError("monitor %s has no header in %s" % (name, base))
    return {c: [r[k] for r in rows] for k, c in enumerate(columns)}


def run_cost(log_file):
    """Steps, wall time of the time loop [s], particle-steps per second and
    particle count of a solver log"""
    log = open(log_file).read()
    loop = re.findall(r"time loop \(all\)\s+([0-9.e+-]+)", log)
    rate = re.findall(r"Particle-steps per second: ([0-9.e+-]+)", log)
    particles = re.findall(r"particles = (\d+)", log)
    return {
        "steps": len(re.findall(r"^Time = ", log, re.M)),
        "wall": float(loop[-1]) if loop else float("nan"),
        "rate": float(rate[-1]) if rate else float("nan"),
        "particles": int(particles[-1]) if particles else 0,
    }
