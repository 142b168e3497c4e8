#!/usr/bin/python3
"""Case test: the Riemann WCSPH Taylor-Green vortex (tutorials/
riemannSphFoam/taylorGreen) at dx = 1/50 to t = 1 on relaxed particles,
with each kernel correction.

- The tutorial's own checks (validate.py --check) pass with its default
  scheme (RKGC, normalised Laplacian): the kinetic energy's decay rate
  within 1 % of 16 pi^2/Re (+0.43 % measured) and the energy within 2 %
  of the exact decay throughout (0.94 %): no burst.
- The ordering the measurements show (README), run by run with
  -correction: RKGC's decay-rate error below KGC's (0.43 % against
  0.70 %), and KGC's below a third of none's (4.6 %).
- With the published Morris Laplacian the decay is too slow by more than
  2 % (-2.7 % measured): its 3 % bias at h = 1.3 dx, which the normalised
  Laplacian removes.
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import project_dir, run_parts, run_tutorial  # noqa: E402

sys.path.insert(0, os.path.join(project_dir, "etc", "python"))
from foamMonitor import load_runs  # noqa: E402

TUTORIAL = "tutorials/riemannSphFoam/taylorGreen"


def figures(case):
    runs = load_runs(os.path.join(case, "validation", "runs"))
    return runs[-1] if runs else None


def corrections(t, work):
    found = {}
    for name, args in (("RKGC", ()),
                       ("KGC", ("-correction", "KGC")),
                       ("none", ("-correction", "none")),
                       ("RKGC-morris", ("-laplacian", "morris"))):
        case, code, out = run_tutorial(t, TUTORIAL, work, name, args,
                                       check=False)
        run = figures(case)
        t.check("%s: ran to t = 1 and was validated" % name,
                code == 0 and run is not None, out[-1500:])
        if run is None:
            continue
        found[name] = run
        if name == "RKGC":
            t.check("default scheme: decay-rate error %+.2f %% within 1 %%,"
                    " energy within %.2f %% < 2 %% of the exact decay"
                    % (100 * run["rateError"], 100 * run["departure"]),
                    abs(run["rateError"]) < 0.01 and run["departure"] < 0.02)
    if len(found) < 4:
        return
    r, k, n, m = (abs(found[c]["rateError"]) for c in
                  ("RKGC", "KGC", "none", "RKGC-morris"))
    t.check("decay-rate error: RKGC %.2f %% < KGC %.2f %% < none/3 %.2f %%"
            % (100 * r, 100 * k, 100 * n / 3), r < k < n / 3)
    t.check("Morris Laplacian: decay-rate error %.2f %% above 2 %%"
            % (100 * m), m > 0.02)


if __name__ == "__main__":
    sys.exit(run_parts("riemannTaylorGreen", corrections))
