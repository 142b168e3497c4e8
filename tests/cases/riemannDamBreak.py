#!/usr/bin/python3
"""Case test: the Riemann WCSPH dam break (tutorials/riemannSphFoam/
damBreak) at H/dx = 28.5 (dx = 2 mm) to 0.6 s, with each kernel
correction.

- The tutorial's own checks (validate.py --check) pass with its default
  scheme (WKGC, compression limiter): through the impact to 0.6 s, no
  particle lost or through a wall, the energy's rises within 1.5 %.
- The front against the Navier-Stokes reference (interFoam without surface
  tension) within 0.03 H RMS at this coarse spacing (0.0157 H measured;
  the tutorial's target 0.05 H holds at H/dx = 57, where it is 0.007 H).
- The ordering the measurements show (README), run by run with
  -correction: the corrected pressure gradients bring the front closer to
  the reference than none (WKGC, RKGC below none); none is the most
  nearly energy-conserving (largest rise below WKGC's), and the weighting
  of WKGC keeps the rise of the reverse pairing (RKGC) in bounds (WKGC's
  largest rise below half of RKGC's); every correction reaches 0.6 s
  without losing a particle.
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import project_dir, run_parts, run_tutorial  # noqa: E402

sys.path.insert(0, os.path.join(project_dir, "etc", "python"))
from foamMonitor import load_runs  # noqa: E402

TUTORIAL = "tutorials/riemannSphFoam/damBreak"


def figures(case):
    runs = load_runs(os.path.join(case, "validation", "runs"))
    return runs[-1] if runs else None


def corrections(t, work):
    found = {}
    for correction in ("WKGC", "RKGC", "none"):
        case, code, out = run_tutorial(
            t, TUTORIAL, work, correction,
            ("-dx", "0.002", "-correction", correction), check=False)
        run = figures(case)
        t.check("%s: ran and was validated" % correction, run is not None,
                out[-1500:])
        if run is None:
            continue
        found[correction] = run
        t.check("%s: reached 0.6 s, no particle lost or through a wall"
                % correction, "ran to endTime 0.6 s" in out
                and "MISSED: the water keeps" not in out
                and "MISSED: deepest wall" not in out, out[-1500:])
        if correction == "WKGC":
            t.check("default scheme: validate.py --check passes", code == 0,
                    out[-1500:])
            t.check("default scheme: front within %.4f H < 0.03 H of the"
                    " Navier-Stokes front" % run["rms"], run["rms"] < 0.03)
    if len(found) < 3:
        return
    w, r, n = found["WKGC"], found["RKGC"], found["none"]
    t.check("front: WKGC %.4f H and RKGC %.4f H closer than none %.4f H"
            % (w["rms"], r["rms"], n["rms"]),
            w["rms"] < n["rms"] and r["rms"] < n["rms"])
    t.check("energy: largest rise of none %.4f < WKGC %.4f < RKGC/2 %.4f"
            " J/m" % (n["energyRise"], w["energyRise"], r["energyRise"] / 2),
            n["energyRise"] < w["energyRise"] < r["energyRise"] / 2)


if __name__ == "__main__":
    sys.exit(run_parts("riemannDamBreak", corrections))
