#!/usr/bin/python3
"""Case test: the ISPH dam break (tutorials/isphTlsphFoam/damBreak) at its
default H/dx = 28.5 (dx = 2 mm) through the impact to 0.6 s (about 15 s).

- The tutorial's own checks (validate.py --check) pass: the front within
  0.05 H RMS of the Navier-Stokes front without surface tension up to
  T = 2.23 (0.0318 H measured), no particle lost or through a wall, the
  energy's largest rise within 4 % of rho0 g H^3/2 (0.48 %).
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
    t.check("stable to 0.6 s (validate.py's checks)", run["stable"] == 1,
            out[-1500:])
    parts = run_cost(case)["parts"]
    for part in ("water.isph", "water.pressureSolve",
                 "water.particleShifting"):
        t.check("run cost has the part %s" % part,
                parts.get(part, {}).get("calls", 0) > 0, str(sorted(parts)))


if __name__ == "__main__":
    sys.exit(run_parts("isphDamBreak", dam_break))
