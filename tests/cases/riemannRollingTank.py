#!/usr/bin/python3
"""Case test: the rolling tank with an elastic baffle (Idelsohn et al.
2008) with the Riemann fluid and the TLSPH solid
(tutorials/riemannSphFoam/rollingTankBaffle), at its default resolution
(the baffle 4 particles thick at 1 mm, the oil at 2 mm), through the first
half period of the roll to 0.5 s:

- validate.py --check: the stability checks (no particle lost, the oil
  inside the rolled tank and out of the baffle, the fastest oil particle
  below 0.1 c0, the baffle's particle-scale noise, the coupling's forces
  equal and opposite);
- the baffle's foot follows the tank (the motion constraint): the
  baffle's lowest particle, in the notch, sits where the roll takes its
  reference position, to 1e-8 m (the roll read back with 6 digits), at
  every written time;
- the oil, lagging the tank as it rolls counterclockwise, bends the
  baffle's tip to -x in the tank's frame by 0.5 s (-53 mm measured);
- solverComparison.best_shift, with which the validation says how far a
  run lags another solver's tutorial: a sine read 50 ms late is found 50
  ms behind, the aligned RMS difference zero (1e-12) and the unshifted
  one that of the two sines (2 sin(omega 0.025 s)/sqrt(2)); a history
  that ends before the comparison starts gives None.
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(here)),
                                "etc", "python"))
from caseTest import run_parts, run_validated  # noqa: E402
from foamCloud import read_cloud, times  # noqa: E402
from rollingTankBaffle import roll  # noqa: E402
from solverComparison import best_shift, resample  # noqa: E402

TUTORIAL = "tutorials/riemannSphFoam/rollingTankBaffle"


def tank_checks(t, tutorial, work):
    """Run tutorial's default to 0.5 s and check it (the module's
    description); returns the case, or None when the run failed"""
    case = run_validated(t, tutorial, work, "default", ("-end", "0.5"))
    if case is None:
        return None

    motion = roll(case)
    worst, n = 0.0, 0
    for value, name in times(case):
        cloud = read_cloud(case, name, "baffle")
        if "X0" not in cloud:
            continue        # the seeded time: positions are X0
        X0, x = cloud["X0"], cloud["positions"]
        foot = min(range(len(X0)), key=lambda i: (X0[i][1], X0[i][0]))
        px, py = motion.to_tank(value, x[foot])
        worst = max(worst, math.hypot(px - X0[foot][0], py - X0[foot][1]))
        n += 1
    t.check("the baffle's foot follows the roll (largest distance from its"
            " place in the tank %.1e m <= 1e-8 m over %d times)" % (worst, n),
            n > 0 and worst <= 1e-8)

    tip = [r.split() for r in open(os.path.join(case, "validation",
                                                "tip.dat"))
           if not r.startswith("#")]
    deflection = float(tip[-1][3])
    t.check("the tip bent to -x in the tank's frame by 0.5 s (%.4f m)"
            % deflection, deflection < -0.01)
    return case


def tank(t, work):
    tank_checks(t, TUTORIAL, work)


def shift(t, work):
    omega, step = 2 * math.pi / 1.211, 0.005
    ts = [k * step for k in range(2423)]
    late = resample(step, ts, [math.sin(omega * (v - 0.05)) for v in ts])
    ref = resample(step, ts, [math.sin(omega * v) for v in ts])
    got = best_shift(late, ref, 1, 2.422, 1.211 / 4)
    expected = math.sqrt(2) * math.sin(omega * 0.025)
    t.check("best_shift: a sine read 50 ms late lags by %.4f s, RMS %.1e"
            " aligned, %.6f unshifted (%.6f)" % (got + (expected,)),
            abs(got[0] - 0.05) < 1e-9 and got[1] < 1e-12
            and abs(got[2] - expected) < 1e-3 * expected)
    t.check("best_shift: a history that ends before the comparison starts"
            " gives None", best_shift(late[:400], ref, 1, 2.422, 0.3) is None)


if __name__ == "__main__":
    sys.exit(run_parts("riemannRollingTank", shift, tank))
