"""Histories of a scene that the solvers' tutorials share (liaoPlate,
rollingTankBaffle), written by each tutorial's validation as a small text
file and read by the others' to plot beside their own: no measured history
exists for these scenes, so the solvers are compared with each other.

    from solverComparison import (resample, write_history, read_history,
                                  other_solvers, best_shift)
    write_history(path, header, resample(step, ts, xs, ys))
    for solver, rows in other_solvers(here, "liaoPlate", "riemannSphFoam"):
        ...
"""
import glob
import math
import os

from foamMonitor import interp, wall_time


def resample(step, ts, *series):
    """Each series of ts linearly interpolated every 'step' seconds from 0
    to the last time: [(t, v1, v2, ...)]"""
    n = int(math.floor(ts[-1] / step + 1e-9))
    return [(k * step,) + tuple(interp(k * step, ts, s) for s in series)
            for k in range(n + 1)]


def write_history(path, header, rows):
    """Rows of numbers, after the header's lines as '#' comments"""
    with open(path, "w") as f:
        for line in header:
            f.write("# %s\n" % line)
        for row in rows:
            f.write(" ".join("%.6e" % v for v in row) + "\n")


def read_history(path):
    """The rows of write_history, '#' lines skipped: [(t, v1, ...)]"""
    rows = []
    for line in open(path):
        if line.strip() and not line.startswith("#"):
            rows.append(tuple(float(v) for v in line.split()))
    return rows


def other_solvers(here, scene, solver, name="tip.dat"):
    """[(other solver, rows)] of every other solver's tutorial of the scene
    whose validation has the history 'name' (its default run), 'here'
    being this tutorial's validation folder
    (tutorials/<solver>/<scene>/validation)"""
    tutorials = os.path.abspath(os.path.join(here, "..", "..", ".."))
    out = []
    for path in sorted(glob.glob(os.path.join(tutorials, "*", scene,
                                              "validation", name))):
        other = path.split(os.sep)[-4]
        if other != solver:
            out.append((other, read_history(path)))
    return out


def best_shift(rows, others, column, start, most):
    """How far this history lags another's: rows and others are
    histories on the same time grid (resample with the same step); of the
    shifts within +-most seconds, the one that makes the RMS difference of
    'column' from time 'start' on least, this history read that much
    later. Returns (shift [s], RMS at it, RMS unshifted), or None when
    the histories do not overlap by more than 'most' after 'start'"""
    n = min(len(rows), len(others))
    step = rows[1][0] - rows[0][0] if n > 1 else 0.0
    reach = int(round(most / step)) if step > 0 else 0
    first = next((i for i in range(n) if rows[i][0] >= start - 1e-9), n)
    if n - first <= reach:
        return None

    def rms(k):
        pairs = [(rows[i + k][column], others[i][column])
                 for i in range(max(first, first - k), min(n, n - k))]
        return math.sqrt(sum((a - b) ** 2 for a, b in pairs) / len(pairs))

    k = min(range(-reach, reach + 1), key=rms)
    return k * step, rms(k), rms(0)


def own_spacings(here, name, own):
    """[(label, rows)] of this tutorial's other histories of the same kind
    (<name>.dat of the default spacing, <name>-dx<spacing>.dat of others)
    but the file 'own' just written"""
    out = []
    for path in sorted(glob.glob(os.path.join(here, name + "*.dat"))):
        if os.path.abspath(path) == os.path.abspath(own):
            continue
        tag = os.path.basename(path)[len(name):-len(".dat")].lstrip("-")
        out.append((tag or "default spacing", read_history(path)))
    return out


def step_rows(cost, fluid):
    """Rows (quantity, value) of a coupled run's steps from run_cost:
    advection steps, the fluid's acoustic steps (its sub-steps, when it
    takes them), and the solid's steps per fluid (acoustic) step (the
    coupling's sub-steps; one when the solid is implicit and takes the
    fluid's)"""
    rows = [("fluid steps (advection)", "%d" % cost["steps"])]
    own = cost["subSteps"].get(fluid)
    if own is not None:
        rows.append(("acoustic steps", "%d (%.2f per advection step, at"
                     " most %d)" % (round(own["mean"] * cost["steps"]),
                                    own["mean"], own["most"])))
    solid = cost["subSteps"].get("coupling")
    rows.append(("solid steps per %s step" % ("fluid" if own is None else
                                               "acoustic"),
                 "one (the solid's step is"
                 " the fluid's)" if solid is None else
                 "%.2f (at most %d)" % (solid["mean"], solid["most"])))
    return rows


def cost_rows(cost, fluid):
    """Rows (quantity, value) of a coupled run's cost for its result.md:
    the particles of each body, the steps (step_rows) and the wall time"""
    rows = [("particles: %s (%s)" % (name, b["model"]), "%d" % b["particles"])
            for name, b in sorted(cost["bodies"].items())]
    rows += step_rows(cost, fluid)
    rows.append(("wall time", "%s%s" % (wall_time(cost), "" if cost["runs"]
                                        == 1 else " in %d runs (restarts)"
                                        % cost["runs"])))
    return rows


def plot_comparison(ax, here, scene, solver, own, column):
    """Onto the axes ax: column 'column' of this tutorial's histories at
    its other spacings (dashed) and of the other solvers' tutorials of the
    scene (solid), 'own' being the history this run just wrote"""
    for tag, rows in own_spacings(here, "tip", own):
        ax.plot([r[0] for r in rows], [r[column] for r in rows], "--",
                lw=1, label="%s, %s" % (solver, tag))
    for other, rows in other_solvers(here, scene, solver):
        ax.plot([r[0] for r in rows], [r[column] for r in rows], "-",
                lw=1.2, label="%s (its tutorial's run)" % other)
