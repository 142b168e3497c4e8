#!/usr/bin/python3
"""Case test: the ISPH dam break (tutorials/isphTlsphFoam/damBreak) at its
default H/dx = 28.5 (dx = 2 mm) to 0.17 s, before the impact.

- The tutorial's own checks (validate.py --check) pass: the front within
  0.05 H RMS of the Navier-Stokes front without surface tension (0.0477 H
  measured), no particle lost or through a wall, the energy's largest
  rise within 4 % of rho0 g H^3/2 (2.7 %; 1.0 to 2.7 % and a front RMS of
  0.0433 to 0.0489 H over perturbations of h by 1e-13 of itself).
- The run cost has the model's parts and the shifting's.
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import project_dir, run_parts, run_tutorial  # noqa: E402

sys.path.insert(0, os.path.join(project_dir, "etc", "python"))
from foamMonitor import load_runs, run_cost  # noqa: E402

TUTORIAL = "tutorials/isphTlsphFoam/damBreak"


def dam_break(t, work):
    case, code, out = run_tutorial(t, TUTORIAL, work, "default")
    runs = load_runs(os.path.join(case, "validation", "runs"))
    t.check("validated", bool(runs), out[-1500:])
    if not runs:
        return
    run = runs[-1]
    t.check("front within %.4f H < 0.05 H of the Navier-Stokes front"
            % run["rms"], run["rms"] < 0.05)
    t.check("stable to 0.17 s (validate.py's checks)", run["stable"] == 1,
            out[-1500:])
    parts = run_cost(case)["parts"]
    for part in ("water.isph", "water.pressureSolve",
                 "water.particleShifting", "water.wallRepulsion"):
        t.check("run cost has the part %s" % part,
                parts.get(part, {}).get("calls", 0) > 0, str(sorted(parts)))


if __name__ == "__main__":
    sys.exit(run_parts("isphDamBreak", dam_break))
