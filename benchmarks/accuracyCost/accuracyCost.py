#!/usr/bin/python3
"""What accuracy costs, method by method: every method on every shared
scene at a ladder of resolutions, each run's error against the scene's
reference and its wall time on this machine, in one report.

Usage: Allrun [-quick] [-scene S] [-method M] [-threads N] [-work DIR]
              [-report DIR]

  -quick      the two coarsest resolutions of each ladder only (minutes);
              writes result-quick.md and <scene>-quick.png
  -scene S    only scene S (repeatable)
  -method M   only method M (repeatable; a method's name as in SCENES)
  -threads N  OpenMP threads of every run (default 2)
  -work DIR   where the runs live (default runs/ beside this script)
  -report DIR where the report and its PNGs go (default beside this
              script)

A scene is one tutorial case per method: the same scene dictionaries, only
the model and its own parameters differ (the tutorials of the solvers on
that scene). A method's run is its tutorial's Allrun with a resolution
argument (-dx D or -n N) in a copy under the work folder, to the scene's
end time when it sets one. A run already made with the same inputs (the
tutorial's files, the arguments, the end time, the thread count and this
tree's solvers and library, by content) is reused, not run again.

The error of a run is the scene's (SCENES: the function that measures it
and what it measures); the cost is the wall time of the solver's time loop
and its parts from the run-cost file (postProcessing/runCost), so the
report also shows what each model, effect and coupling costs (its share of
the wall time). The observed order of convergence of a method is the slope
of log error against log spacing between successive resolutions.

Adding a method to a scene, or a scene, is one entry in SCENES.

Writes result.md (result-quick.md with -quick) and one PNG per scene: the
error (log) against the wall time (log), one line per method, each point
labelled by its resolution; a scene may add the same probes to every run
and report their figures beside the error (the dam break's far-wall
pressure, an experiment of another geometry beside it), and the report
ends with what an effect the scene does not name costs
(benchmarks/unusedEffect). Exits 1 when a run failed or gave no finite
error.
"""
import argparse
import collections
import hashlib
import importlib.util
import math
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(PROJECT, "etc", "python"))

import damBreakFront  # noqa: E402
import elasticGate  # noqa: E402
import hydrostaticPlate  # noqa: E402
from foamDict import put_entry  # noqa: E402
from foamMonitor import pyplot, run_cost  # noqa: E402


#: One run of the report: its method, resolution value, error, run cost
#: (None when the run gave none) and how it came (ran, reused, failed)
Run = collections.namedtuple("Run", "method value error cost note reported")


class Method:
    """A method on a scene: its name, its tutorial (project-relative), the
    Allrun flag that sets the resolution and the ladder of its values,
    coarsest first, the spacing a value stands for (for the order of
    convergence: the value itself for -dx, thickness/n for -n), and the
    Allrun arguments that select the method in a tutorial of another
    (e.g. -model nosbPd)"""

    def __init__(self, name, tutorial, flag, ladder, spacing=None,
                 args=()):
        self.name = name
        self.tutorial = tutorial
        self.flag = flag
        self.ladder = ladder
        self.spacing = spacing or (lambda v: v)
        self.args = list(args)


class Scene:
    """A scene: its name, a title, what its error measures, the function
    error(case, tutorial) giving a run's error (the absolute path of the
    method's tutorial, where its reference files are), the end time every
    run is cut to (None: the tutorials' own), and its methods; monitors:
    {name: dictionary text} added to every run's constant/
    particleProperties (the same probes for every method); reported:
    (what, function(case) giving the figures reported beside the error
    as text, a note on the experiment beside them) or None"""

    def __init__(self, name, title, measures, error, end, methods,
                 monitors=None, reported=None):
        self.name = name
        self.title = title
        self.measures = measures
        self.error = error
        self.end = end
        self.methods = methods
        self.monitors = monitors or {}
        self.reported = reported


_modules = {}


def tutorial_module(tutorial):
    """A tutorial's validation/validate.py as a module (its functions:
    analyse(case), ...); scripts run their main only as __main__"""
    if tutorial not in _modules:
        path = os.path.join(tutorial, "validation", "validate.py")
        spec = importlib.util.spec_from_file_location(
            "validate_%d" % len(_modules), path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        _modules[tutorial] = module
    return _modules[tutorial]


def dam_break_error(case, tutorial):
    """RMS of the front's x/H against the converged Navier-Stokes front
    (interFoam, no surface tension) at the experiment's times in the run"""
    ts, xs = damBreakFront.front(case)
    rows = damBreakFront.front_errors(ts, xs,
                                      os.path.join(tutorial, "validation"))
    return damBreakFront.rms([r[3] - r[2] for r in rows])


#: The dam break's wall-pressure probes: far wall (x = 4H) and back wall
#: at y = 0.2 H, every step
DAM_BREAK_SENSOR = ("{ type probes; body water; field p;"
                    " points ((0.228 0.0114 0) (0 0.0114 0)); }")


def dam_break_sensor(case):
    """The far-wall sensor (y = 0.2 H): the impact (first p > 0.1 rho0 g
    H) and the first peak (within sqrt(H/g) of it), in T = t sqrt(g/H)
    and p/(rho0 g H)"""
    from foamMonitor import monitor_rows
    H, g, rho0 = 0.057, 9.81, 1000.0
    _, rows = monitor_rows(case, "accuracyCostSensor")
    scale = rho0 * g * H
    t = [r[0] for r in rows]
    p = [r[1] / scale for r in rows]
    impact = next((k for k, v in enumerate(p) if v > 0.1), None)
    if impact is None:
        return "no impact by T = %.2f" % (t[-1] * math.sqrt(g / H))
    window = [k for k in range(impact, len(t))
              if t[k] <= t[impact] + math.sqrt(H / g)]
    k = max(window, key=lambda i: p[i])
    return "impact T = %.2f, first peak %.2f at T = %.2f" % (
        t[impact] * math.sqrt(g / H), p[k], t[k] * math.sqrt(g / H))


def buchner_note():
    """Buchner's (2002) sensor P1, another geometry (H x 2H column), as the
    Riemann dam break's validation keeps it: impact and peak"""
    path = os.path.join(PROJECT, "tutorials", "riemannSphFoam", "damBreak",
                        "validation", "buchnerP1.dat")
    rows = [[float(v) for v in line.split()] for line in open(path)
            if line.strip() and not line.startswith("#")]
    impact = next(r[0] for r in rows if r[1] > 0.1)
    peak = max(rows, key=lambda r: r[1])
    return ("Buchner (2002) sensor P1, the experiment reported beside it"
            " (another geometry: an H x 2H column in a 5.366 H tank; no"
            " wall pressure of the square column is published): impact T ="
            " %.2f, peak %.2f at T = %.2f (p/(rho0 g H))"
            % (impact, peak[1], peak[0]))


def gate_error(case, tutorial):
    """RMS of the free end's x(t) against Antoci et al.'s experiment [m]"""
    return elasticGate.rms_errors(
        case, os.path.join(tutorial, "validation"))["x"][0]


def plate_error(case, tutorial):
    """|period/theory - 1| of the oscillating plate"""
    run = tutorial_module(tutorial).analyse(case)
    return abs(run["period"] / run["periodTheory"] - 1)


def beam_error(case, tutorial):
    """|tip deflection/beam theory - 1| of the clamped beam"""
    run = tutorial_module(tutorial).analyse(case)
    return abs(run["deflection"] / run["reference"] - 1)


def hydrostatic_error(case, tutorial):
    """|mean mid-span deflection/static value with shear - 1| (both
    solvers' tutorials validate with etc/python/hydrostaticPlate.py)"""
    run, _ = hydrostaticPlate.analyse(case)
    return abs(run["deflection"] / run["reference"] - 1)


# The shared scenes and the methods that run them: one line per method
SCENES = [
    Scene("damBreak", "Dam break, square column H = 0.057 m, through the"
          " impact to 0.6 s (the tutorials' own end)",
          "RMS of the front x/H against the converged Navier-Stokes front"
          " [H]", dam_break_error, None, [
              Method("ULPH", "tutorials/ulphPdFoam/damBreak", "-dx",
                     (0.003, 0.002, 0.0015, 0.001)),
              Method("Riemann WCSPH", "tutorials/riemannSphFoam/damBreak",
                     "-dx", (0.003, 0.002, 0.0015, 0.001)),
              Method("ISPH", "tutorials/isphTlsphFoam/damBreak", "-dx",
                     (0.003, 0.002, 0.0015, 0.001)),
          ], monitors={"accuracyCostSensor": DAM_BREAK_SENSOR},
          reported=("far-wall pressure, y = 0.2 H (p/(rho0 g H))",
                    dam_break_sensor, buchner_note)),
    Scene("elasticGate", "Elastic gate (Antoci et al. 2007), to 0.4 s",
          "RMS of the free end's x(t) against the experiment [m]",
          gate_error, None, [
              Method("Riemann WCSPH + TLSPH",
                     "tutorials/riemannSphFoam/elasticGate", "-dx",
                     (0.0025, 0.00125, 0.000625)),
              Method("ULPH + NOSB-PD", "tutorials/ulphPdFoam/elasticGate",
                     "-dx", (0.0025, 0.00125)),
              Method("ISPH + TLSPH", "tutorials/isphTlsphFoam/elasticGate",
                     "-dx", (0.0025, 0.00125)),
          ]),
    Scene("hydrostaticPlate", "Hydrostatic plate (water 2 m on an"
          " aluminium plate 0.05 m thick), 3 s",
          "|mean mid-span deflection / static value - 1|",
          hydrostatic_error, None, [
              Method("Riemann WCSPH + TLSPH",
                     "tutorials/riemannSphFoam/hydrostaticPlate", "-n",
                     (4, 6, 8), lambda n: 0.05 / n),
              Method("ISPH + TLSPH",
                     "tutorials/isphTlsphFoam/hydrostaticPlate", "-n",
                     (4, 6, 8), lambda n: 0.05 / n),
          ]),
    Scene("oscillatingPlate", "Oscillating plate (Gray et al. 2001), the"
          " tutorial's 3 periods",
          "|period / plate theory - 1|", plate_error, None, [
              Method("TLSPH", "tutorials/isphTlsphFoam/oscillatingPlate",
                     "-dx", (0.002, 0.001)),
              Method("NOSB-PD", "tutorials/isphTlsphFoam/oscillatingPlate",
                     "-dx", (0.002, 0.001), args=["-model", "nosbPd"]),
          ]),
    Scene("clampedBeam", "Clamped beam under a tip load (static)",
          "|tip deflection / beam theory - 1|", beam_error, None, [
              Method("TLSPH", "tutorials/isphTlsphFoam/clampedBeam", "-n",
                     (5, 7, 11, 17), lambda n: 0.01 / n),
              Method("NOSB-PD", "tutorials/isphTlsphFoam/clampedBeam", "-n",
                     (5, 7, 11), lambda n: 0.01 / n,
                     ["-model", "nosbPd"]),
          ]),
]


def slug(text):
    return "".join(c if c.isalnum() else "_" for c in text).strip("_")


def digest_tree(h, root, skip=("validation",)):
    """Add every file under root (but the folders in skip at its top, and
    run output) to the hash h, by relative path and content"""
    for folder, dirs, files in os.walk(root):
        rel = os.path.relpath(folder, root)
        if rel == ".":
            dirs[:] = [d for d in dirs if d not in skip
                       and not d[0].isdigit() and d != "postProcessing"]
        dirs.sort()
        for name in sorted(files):
            if name.startswith("log.") or name.endswith((".foam",
                                                         ".log")):
                continue
            path = os.path.join(folder, name)
            h.update(os.path.relpath(path, root).encode())
            with open(path, "rb") as f:
                h.update(f.read())


def build_digest():
    """The content of this tree's solvers and library (a rebuild with
    other code makes every run new)"""
    h = hashlib.sha256()
    platforms = os.path.join(PROJECT, "platforms")
    for sub in ("bin", "lib"):
        folder = os.path.join(platforms, sub)
        for name in sorted(os.listdir(folder)) if os.path.isdir(folder) \
                else []:
            path = os.path.join(folder, name)
            if os.path.isfile(path):
                with open(path, "rb") as f:
                    h.update(name.encode())
                    h.update(f.read())
    return h.hexdigest()


def run_case(scene, method, value, work, threads, build):
    """One run, made now or reused: (error, cost, note, reported)"""
    tutorial = os.path.join(PROJECT, method.tutorial)
    case = os.path.join(work, scene.name, slug(method.name),
                        "%s%g" % (method.flag.lstrip("-"), value))
    args = [method.flag, "%g" % value] + method.args
    h = hashlib.sha256()
    digest_tree(h, tutorial)
    h.update(repr((args, scene.end, sorted(scene.monitors.items()), threads,
                   build)).encode())
    key = h.hexdigest()
    stamp = os.path.join(case, "inputs.sha256")
    status = os.path.join(case, "Allrun.exit")
    reuse = (os.path.isfile(stamp) and open(stamp).read().strip() == key)
    note = "reused"
    if reuse and os.path.isfile(status):
        code = int(open(status).read().split()[0])
        if code != 0:
            note = "reused; the tutorial's checks missed (Allrun exit %d)" \
                % code
    if not reuse:
        if os.path.isdir(case):
            shutil.rmtree(case)
        shutil.copytree(tutorial, case, ignore=shutil.ignore_patterns(
            "[0-9]*", "postProcessing", "log.*", "*.foam", "processor*"))
        subprocess.run(["./Allclean"], cwd=case, capture_output=True)
        for name, text in scene.monitors.items():
            put_entry(case, "constant/particleProperties",
                      "monitors/" + name, text)
        if scene.end is not None:
            subprocess.run(["foamDictionary", "system/controlDict", "-entry",
                            "endTime", "-set", "%g" % scene.end], cwd=case,
                           capture_output=True, check=True)
        env = dict(os.environ, OMP_NUM_THREADS=str(threads),
                   MESHLESS_PROJECT=PROJECT)
        with open(os.path.join(case, "Allrun.log"), "w") as log:
            code = subprocess.run(["./Allrun"] + args, cwd=case, env=env,
                                  stdout=log, stderr=subprocess.STDOUT
                                  ).returncode
        # The tutorial's validation may miss its own targets (a coarse
        # run, a cut end time): what counts here is that the solver ran
        note = "ran" if code == 0 else \
            "ran; the tutorial's checks missed (Allrun exit %d)" % code
        with open(status, "w") as f:
            f.write("%d\n" % code)
    try:
        cost = run_cost(case)
    except Exception as e:      # no run-cost file: the solver never ran
        return math.nan, None, "no run: %s" % e, ""
    if not cost["completed"]:
        return math.nan, None, "the solver stopped at %g s" \
            % cost["time"], ""
    if not reuse:
        with open(stamp, "w") as f:
            f.write(key + "\n")
    reported = ""
    if scene.reported is not None:
        try:
            reported = scene.reported[1](case)
        except Exception as e:
            reported = "none: %s" % e
    try:
        error = scene.error(case, tutorial)
    except Exception as e:
        return math.nan, cost, "%s; no error: %s" % (note, e), reported
    return error, cost, note, reported


def order(points):
    """Observed orders between successive resolutions: [(value, p)] with
    p = log(e1/e2)/log(s1/s2)"""
    out = []
    for (s1, e1), (s2, e2) in zip(points, points[1:]):
        if e1 > 0 and e2 > 0 and s1 != s2:
            out.append(math.log(e1 / e2) / math.log(s1 / s2))
        else:
            out.append(math.nan)
    return out


def shares(cost, top=4):
    """The largest parts of a run's wall time: 'name 71 %, ...'"""
    parts = [(name, p["share"]) for name, p in cost["parts"].items()
             if name != "time loop (all)" and math.isfinite(p["share"])]
    parts.sort(key=lambda np: -np[1])
    return ", ".join("%s %.0f %%" % (n, 100 * s) for n, s in parts[:top])


def cheapest(results):
    """The report's answer for a scene: the tightest error every method
    reaches (the largest of the methods' best errors), and the cheapest
    run reaching it: (X, method, value, wall) or None"""
    best = {}
    for r in results:
        if r.cost is not None and math.isfinite(r.error):
            best.setdefault(r.method.name, []).append(
                (r.error, r.value, r.cost["wall"], r.method))
    if not best:
        return None
    X = max(min(e for e, _, _, _ in runs) for runs in best.values())
    reach = [(w, m.name, v, m) for runs in best.values()
             for e, v, w, m in runs if e <= X * (1 + 1e-12)]
    w, name, v, m = min(reach, key=lambda r: r[0])
    return X, name, v, w, m


def label(method, value):
    return "%s %g" % (method.flag.lstrip("-"), value)


def report(selected, results, quick, threads, path):
    lines = ["# What accuracy costs, method by method", "",
             "Command: `benchmarks/accuracyCost/Allrun%s` (every run on %d"
             " OpenMP thread%s of this machine; the wall time is the"
             " solver's time loop from its run-cost file)."
             % (" -quick" if quick else "", threads,
                "" if threads == 1 else "s"), "",
             "The parts of the wall time nest (a model's share holds its"
             " effects' and its inner steps'), so the shares do not add"
             " up.", ""]
    left = [s.name for s in SCENES if s not in selected]
    if left:
        lines += ["Not in this report (`-scene` chose the others): %s."
                  % ", ".join(left), ""]
    failed = 0
    for scene in selected:
        rows = results[scene.name]
        lines += ["## %s" % scene.title, "", "Error: %s." % scene.measures,
                  ""]
        answer = cheapest(rows)
        if answer is not None:
            X, name, v, w, m = answer
            n_methods = len({r.method.name for r in rows})
            if n_methods > 1:
                lines += ["**For an error of %.3g, the cheapest method is"
                          " %s at %s, costing %.0f s.**"
                          % (X, name, label(m, v), w), ""]
            else:
                lines += ["**Only %s runs this scene so far: an error of"
                          " %.3g costs %.0f s (%s).**"
                          % (name, X, w, label(m, v)), ""]
        extra = scene.reported is not None
        lines += ["| method | resolution | error | observed order | wall"
                  " time | particles | steps | largest parts of the wall"
                  " time | run |%s" % (" %s (reported) |" % scene.reported[0]
                                       if extra else ""),
                  "|---|---|---|---|---|---|---|---|---|%s"
                  % ("---|" if extra else "")]
        for method in {id(r.method): r.method for r in rows}.values():
            own = [r for r in rows if r.method is method]
            p = [math.nan] + order([(method.spacing(r.value), r.error)
                                    for r in own])
            for k, r in enumerate(own):
                v, e, cost, note = r.value, r.error, r.cost, r.note
                more = " %s |" % r.reported if extra else ""
                if cost is None or not math.isfinite(e):
                    failed += 1
                lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s |"
                             % (method.name, label(method, v),
                                "%.4g" % e if math.isfinite(e) else "none",
                                "%.2f" % p[k] if math.isfinite(p[k]) else "",
                                "%.1f s" % cost["wall"] if cost else "",
                                cost["particles"] if cost else "",
                                cost["steps"] if cost else "",
                                shares(cost) if cost else "", note) + more)
        lines.append("")
        if extra:
            try:
                lines += [scene.reported[2]() + ".", ""]
            except Exception as e:
                lines += ["(the experiment beside it: %s)" % e, ""]
    lines += ["## What an effect costs a scene that does not name it", "",
              "The shares above are of the effects a scene names; one it"
              " does not name is never constructed. Measured by"
              " `benchmarks/unusedEffect/Allrun` (its result.md, copied"
              " here):", ""]
    unused = os.path.join(PROJECT, "benchmarks", "unusedEffect",
                          "result.md")
    if os.path.isfile(unused):
        lines += [line for line in open(unused).read().splitlines()[1:]]
    else:
        lines += ["Not measured yet.", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return failed


def plot(scene, rows, path):
    plt = pyplot()
    if plt is None:
        return
    fig, ax = plt.subplots(figsize=(7, 5))
    for method in {id(r.method): r.method for r in rows}.values():
        own = [(r.cost["wall"], r.error, r.value) for r in rows
               if r.method is method and r.cost is not None
               and math.isfinite(r.error) and r.error > 0]
        if not own:
            continue
        ax.loglog([o[0] for o in own], [o[1] for o in own], "o-",
                  label=method.name)
        for w, e, v in own:
            ax.annotate(label(method, v), (w, e), fontsize=7,
                        xytext=(3, 3), textcoords="offset points")
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel(scene.measures)
    ax.set_title(scene.title, fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def main(argv):
    parser = argparse.ArgumentParser(prog="Allrun", add_help=False,
                                     allow_abbrev=False)
    parser.add_argument("-quick", action="store_true")
    parser.add_argument("-scene", action="append", default=[])
    parser.add_argument("-method", action="append", default=[])
    parser.add_argument("-threads", type=int, default=2)
    parser.add_argument("-work", default=os.path.join(HERE, "runs"))
    parser.add_argument("-report", default=HERE)
    try:
        opts = parser.parse_args(argv)
    except SystemExit:
        print(__doc__)
        return 2
    quick, scenes, methods = opts.quick, opts.scene, opts.method
    threads = opts.threads
    work, out = os.path.abspath(opts.work), os.path.abspath(opts.report)
    known = {s.name for s in SCENES}
    for s in scenes:
        if s not in known:
            print("unknown scene %s: expected one of %s"
                  % (s, ", ".join(sorted(known))))
            return 2
    names = {m.name for s in SCENES for m in s.methods}
    for m in methods:
        if m not in names:
            print("unknown method '%s': expected one of %s"
                  % (m, ", ".join(sorted(names))))
            return 2
    selected = [s for s in SCENES if not scenes or s.name in scenes]
    build = build_digest()
    results = {}
    for scene in selected:
        rows = []
        for method in scene.methods:
            if methods and method.name not in methods:
                continue
            ladder = method.ladder[:2] if quick else method.ladder
            for value in ladder:
                error, cost, note, reported = run_case(
                    scene, method, value, work, threads, build)
                print("%s, %s, %s: error %s, %s (%s)"
                      % (scene.name, method.name, label(method, value),
                         "%.4g" % error, "%.1f s" % cost["wall"] if cost
                         else "no cost", note), flush=True)
                rows.append(Run(method, value, error, cost, note, reported))
        results[scene.name] = rows
        os.makedirs(out, exist_ok=True)
        plot(scene, rows, os.path.join(
            out, "%s%s.png" % (scene.name, "-quick" if quick else "")))
    path = os.path.join(out, "result%s.md" % ("-quick" if quick else ""))
    failed = report(selected, results, quick, threads, path)
    print("wrote %s%s" % (path, "" if not failed else
                          " (%d runs without an error)" % failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
