#!/usr/bin/python3
"""Case test: still water on an elastic plate, ULPH fluid + NOSB-PD solid
coupled by ulphPd (ulphPdFoam).

Water 0.2 x 0.1 m (dx = 5 mm, c0 = 20 m/s, hydrostatic start) on a plate
0.2 x 0.02 m (E = 100 MPa, clamped at both ends) that is the tank's bottom;
ghost walls left, right and under the plate. 0.5 s. Checks:
- the fluid's force on the plate, averaged over 0.1-0.5 s (the weakly
  compressible water and the plate ring about it), is rho g H W within 3 %;
- momentum exchange: per step the fluid's force on the plate and the
  plate's force on the fluid (summed from the fluid's side over its own
  neighbour lists) cancel to 1e-9 of their size;
- the log names the coupling; the run cost (postProcessing/runCost) has
  the coupling's solid sub-steps per fluid step, the most and the mean of
  those the coupling wrote for each step (forces.dat), more than one at
  every step;
- stability: no NaN (the solver would stop), no particle lost, no fluid
  particle below the plate's top, total energy (fluid kinetic + potential,
  plate kinetic + strain + potential) not growing above its start value
  by more than 1e-3 of the column's potential energy rho g H^2 W/2.
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import copy_case, run_parts, run_steps  # noqa: E402
from foamCloud import read_cloud, times  # noqa: E402
from foamMonitor import run_cost  # noqa: E402
from fsiChecks import energy_total, plate_force_checks  # noqa: E402

H, W, DX, G, RHO = 0.1, 0.2, 0.005, 9.81, 1000.0


def hydrostatic(t, work):
    case = copy_case(os.path.join(here, "ulphPdHydrostatic"),
                     os.path.join(work, "case"))
    ok, out = run_steps(t, case)
    if not ok:
        return
    forces = plate_force_checks(t, case, out, "ulphPd", 1000,
                                -RHO * G * H * W)
    sub = [r[7] for r in forces]
    t.check("solid sub-steps > 1 (E = 100 MPa is stiffer than the"
            " water's c0)", min(sub) > 1)
    cost = run_cost(case)
    coupling = cost["subSteps"].get("coupling")
    t.check("run cost reports the coupling's solid sub-steps per fluid"
            " step: %s, the most and the mean of forces.dat's (%d, %.4g)"
            % (coupling, max(sub), sum(sub) / len(sub)),
            coupling is not None and coupling["most"] == max(sub)
            and abs(coupling["mean"] - sum(sub) / len(sub))
            <= 1e-5 * coupling["mean"]
            and cost["steps"] == len(forces))

    t_end, last = times(case)[-1]
    t.check_close("ran to 0.5 s", t_end, 0.5, 1e-9)
    water = read_cloud(case, last, "water")["positions"]
    plate = read_cloud(case, last, "plate")["positions"]
    t.check_equal("no fluid particle lost", len(water), 40 * 20)
    t.check_equal("no plate particle lost", len(plate), 40 * 4)
    lowest = min(x[1] for x in water)
    t.check("no fluid particle inside the plate (lowest at %.4f m)"
            % lowest, lowest > 0)

    total = energy_total(case)
    scale = 0.5 * RHO * G * H * H * W
    growth = max(total) - total[0]
    t.check("total energy not growing (%.2e J <= %.2e J)"
            % (growth, 1e-3 * scale), growth <= 1e-3 * scale)


if __name__ == "__main__":
    sys.exit(run_parts("ulphPdHydrostatic", hydrostatic))
