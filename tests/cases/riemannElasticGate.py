#!/usr/bin/python3
"""Case test: the elastic gate (Antoci et al. 2007) with the Riemann fluid
and the TLSPH solid (tutorials/riemannSphFoam/elasticGate), at its default
resolution (the gate 4 particles thick at 1.25 mm, the water at 2.5 mm),
to 0.4 s:

- validate.py --check: the RMS of the free end's x(t) against the
  experiment below the best published SPH curve's (8.3 mm; 7.0 mm
  measured), the stability checks (no particle lost, water in the tank and
  not in the gate, energy not growing, the gate's particle-scale noise);
- the gate's explicit integrator ('Allrun -explicit', about 36 steps per
  acoustic step of the water) gives the implicit one's free-end curve to
  0.1 s within 0.2 mm (1.2e-3 mm measured).
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import run_parts, run_tutorial, run_validated  # noqa: E402
from foamMonitor import interp, read_monitor  # noqa: E402

TUTORIAL = "tutorials/riemannSphFoam/elasticGate"


def gate(t, work):
    run_validated(t, TUTORIAL, work, "default",
                  what="x RMS below the published curve's and stable")


def explicit(t, work):
    curves = {}
    for name, args in (("implicit", ()), ("explicit", ("-explicit",))):
        case, code, out = run_tutorial(t, TUTORIAL, work, name,
                                       args + ("-end", "0.1"))
        if code != 0:
            return
        curves[name] = read_monitor(case, "freeEnd")
    imp, exp = curves["implicit"], curves["explicit"]
    worst = max(abs(interp(s, exp["time"], exp["dx"])
                    - interp(s, imp["time"], imp["dx"]))
                for s in imp["time"])
    peak = max(imp["dx"])
    t.check("explicit and implicit gates: free-end x within 0.2 mm to"
            " 0.1 s (largest difference %.2e m, x up to %.4f m)"
            % (worst, peak), worst < 2e-4 and peak > 0.03)


if __name__ == "__main__":
    sys.exit(run_parts("riemannElasticGate", gate, explicit))
