"""Rolling tank with an elastic baffle (Idelsohn et al. 2008, the deep
case), shared by the rollingTankBaffle tutorials of every solver (the same
scene).

    from rollingTankBaffle import validate
    sys.exit(validate(here, "riemannSphFoam", 0.001, fluid_ratio=2))

No measured history of the baffle is public (BENCHMARKS.md): the case is
checked for stability over its ten periods of resonant roll, and its tip
history is compared between the solvers. Reads the roll from the case
(tankMotion: oscillatingRotatingMotion's origin, amplitude and omega in
constant/particleProperties) and the tip's position from the
pointDisplacement monitor 'tip' (a run and its restarts), and reports the
tip's deflection in the tank's frame (its position turned back by the
roll, minus its reference position): the largest, and the amplitude (half
the range) and mean over each of the last two periods, with the roll's
period for scale; beside every other solver's tutorial of the scene (its
tip.dat), the amplitude over each period and how far this run lags it.

Writes validation/tip.dat (tip-dx<spacing>.dat for another spacing): t,
the tip's x and y, its deflection in the tank's frame, every 5 ms, which
the other solvers' validations plot beside theirs; validation/result.md
(result-dx<spacing>.md) with the figures, particles per body, steps, solid
sub-steps and wall time; and tip[-dx<spacing>].png.

Checks (the stability of BENCHMARKS: ten periods stable), at every
written time:
  - the run reached endTime;
  - the fluid and the baffle keep their particles;
  - every fluid particle inside the rolled tank (in the tank's frame
    within its walls to 0.5 dx);
  - no fluid particle closer than 0.25 dx to a baffle particle;
  - the fastest fluid particle below 0.1 c0 (weak compressibility holds;
    an incompressible fluid's fastest particle is printed, not checked);
  - the baffle's particle-scale velocity noise below 0.1 sqrt(g h);
  - the coupling's forces equal and opposite (1e-9) at every step.
The energy monitor sees the energies from the tank (frame tank): its
total is the energies less the roll's work, which only the models'
dissipation lowers; it is plotted here (tests/stability bounds it).

With --check, exits 1 when a check is missed.

Usage of a tutorial's validate.py: validate.py <case> [--check]
"""
import math
import os

from foamCloud import read_cloud, times
from foamDict import read_dictionary, lookup
from foamMonitor import (arguments, case_spacing, pyplot, read_monitor,
                         result_suffix, run_cost)
from fsiChecks import (check_rows, end_time, energy_total,
                       momentum_exchange, print_checks, velocity_noise,
                       written_times_checks)
from solverComparison import (best_shift, cost_rows, other_solvers,
                              plot_comparison, read_history, resample,
                              write_history)

LENGTH = 0.608      # tank's inner length [m]
HEIGHT = 0.344      # tank's inner height [m]
DEPTH = 0.1148      # fluid depth asked [m]
SAMPLE = 0.005      # interval of tip.dat [s]


class roll:
    """The tank's roll theta(t) = A sin(omega t) about origin (the case's
    tankMotion, an oscillatingRotatingMotion about z)"""

    def __init__(self, case):
        props = read_dictionary(case, "constant/particleProperties")
        coeffs = lookup(props, "tankMotion/oscillatingRotatingMotionCoeffs")
        self.origin = [float(v) for v in coeffs["origin"]]
        self.amplitude = math.radians(float(coeffs["amplitude"][2]))
        self.omega = float(coeffs["omega"])
        self.period = 2 * math.pi / self.omega

    def angle(self, t):
        return self.amplitude * math.sin(self.omega * t)

    def to_tank(self, t, p):
        """Point p (inertial) in the tank's frame at time t"""
        a = -self.angle(t)
        x, y = p[0] - self.origin[0], p[1] - self.origin[1]
        return (self.origin[0] + math.cos(a) * x - math.sin(a) * y,
                self.origin[1] + math.sin(a) * x + math.cos(a) * y)


def period_figures(ts, ds, period, last=2):
    """(amplitude, mean) of the series over each of the last 'last' whole
    periods (every whole period with None): [(t0, t1, amplitude, mean)]"""
    out = []
    n = int(math.floor(ts[-1] / period + 1e-9))
    for k in range(0 if last is None else n - last, n):
        if k < 0:
            continue
        t0, t1 = k * period, (k + 1) * period
        part = [d for t, d in zip(ts, ds) if t0 <= t <= t1]
        if part:
            out.append((t0, t1, 0.5 * (max(part) - min(part)),
                        sum(part) / len(part)))
    return out


def checks_of(case, motion, fluid, solid, dx, solid_dx, c0, h):
    """[(what, met)]: the stability checks of the module's description"""
    series = times(case)
    t1 = series[-1][0]
    checks = [("ran to endTime %g s (last time %g s)" % (end_time(case), t1),
               abs(t1 - end_time(case)) < 1e-9)]
    state = {"depth": -math.inf, "fastest": 0.0}

    def visit(value, name, fl):
        for p in fl:
            x, y = motion.to_tank(value, p)
            state["depth"] = max(state["depth"], -x, x - LENGTH, -y,
                                 y - HEIGHT)
        U = read_cloud(case, name, fluid).get("U", [])
        state["fastest"] = max([state["fastest"]]
                               + [math.hypot(u[0], u[1]) for u in U])

    checks += written_times_checks(case, series, fluid, solid, dx, visit)
    depth, fastest = state["depth"], state["fastest"]
    checks.append(("every %s particle inside the rolled tank (deepest wall"
                   " penetration %.2f dx < 0.5 dx)" % (fluid, depth / dx),
                   depth < 0.5 * dx))
    if c0 is not None:
        checks.append(("fastest %s particle %.3f m/s < 0.1 c0 = %.2f m/s"
                       % (fluid, fastest, 0.1 * c0), fastest < 0.1 * c0))
    else:
        print("fastest %s particle %.3f m/s (incompressible: no Mach"
              " limit)" % (fluid, fastest))
    noise = velocity_noise(case, solid, solid_dx)
    scale = math.sqrt(9.81 * h)
    checks.append(("the %s's particle-scale velocity noise %.3g m/s < 0.1 x"
                   " %.3g m/s" % (solid, noise, scale), noise < 0.1 * scale))
    balance = momentum_exchange(case, floor=1e-6)
    checks.append(("the %s's force on the %s and the %s's on the %s cancel"
                   " (largest |F_fs + F_sf|/|F_fs| %.1e <= 1e-9)"
                   % (fluid, solid, solid, fluid, balance), balance <= 1e-9))
    return checks


def comparison(here, solver, own, period):
    """Markdown (also printed) comparing the history 'own' (tip.dat just
    written) with every other solver's tutorial of the scene: the
    deflection's amplitude over each whole period, and from the third
    period on the shift (within a quarter period) that best aligns the
    two, with the RMS difference at it and unshifted"""
    rows = read_history(own)
    text = ""
    for other, theirs in other_solvers(here, "rollingTankBaffle", solver):
        mine = period_figures([r[0] for r in rows], [r[3] for r in rows],
                              period, None)
        its = period_figures([r[0] for r in theirs], [r[3] for r in theirs],
                             period, None)
        if not mine or not its:
            continue
        text += ("\n## Beside %s's tutorial (its validation/tip.dat)\n\n"
                 "| period | amplitude, this run | amplitude, %s |\n"
                 "|---|---|---|\n" % (other, other))
        for k, (a, b) in enumerate(zip(mine, its)):
            text += ("| %d (%.3f-%.3f s) | %.4f m | %.4f m |\n"
                     % (k + 1, a[0], a[1], a[2], b[2]))
        shift = best_shift(rows, theirs, 3, 2 * period, period / 4)
        if shift is not None:
            summary = ("From the third period on this run lags %s's by %.0f"
                       " ms, the shift that best aligns the two deflections"
                       " (RMS difference %.1f mm, %.1f mm unshifted)."
                       % ((other,) + tuple(1e3 * v for v in shift)))
            print(summary)
            text += "\n%s\n" % summary
    return text


def validate(here, solver, default_dx, fluid_ratio=1, fluid="oil",
             doc=None):
    """Validate the case named on the command line: 'here' is the
    tutorial's validation folder, 'solver' names the curve, default_dx is
    the baffle's spacing of the tutorial's default run and fluid_ratio the
    fluid's spacing over the baffle's. Returns the exit code (1 with
    --check when a check is missed)."""
    case, check = arguments(doc or __doc__)
    motion = roll(case)
    sim = read_monitor(case, "tip")    # a run and its restarts
    ts, xs, ys = sim["time"], sim["x"], sim["y"]
    X0 = (xs[0] - sim["dx"][0], ys[0] - sim["dy"][0])
    ds = [motion.to_tank(t, (x, y))[0] - X0[0]
          for t, x, y in zip(ts, xs, ys)]
    dx = case_spacing(case, default_dx)
    suffix = result_suffix(dx, default_dx)
    cost = run_cost(case)
    # A weakly compressible fluid's sound speed; None for an incompressible
    # one (ISPH), which has no Mach number to check
    c0 = lookup(read_dictionary(case, "constant/particleProperties"),
                "bodies/%s/soundSpeed" % fluid, None)
    c0 = None if c0 is None else float(c0)

    own = os.path.join(here, "tip%s.dat" % suffix)
    write_history(own, ["rollingTankBaffle tip (%g, %g) m, %s, baffle"
                        " spacing %g m, %s %g m" % (X0 + (solver, dx, fluid,
                                                         fluid_ratio * dx)),
                        "t [s]  x [m]  y [m]  deflection in the tank's"
                        " frame [m]"],
                  resample(SAMPLE, ts, xs, ys, ds))

    k = max(range(len(ds)), key=lambda i: abs(ds[i]))
    periods = period_figures(ts, ds, motion.period)
    lines = ["largest deflection of the tip in the tank's frame %.4f m at"
             " %.3f s" % (ds[k], ts[k])]
    for t0, t1, amp, mean in periods:
        lines.append("deflection over %.3f-%.3f s: amplitude %.4f m, mean"
                     " %.4f m" % (t0, t1, amp, mean))
    for line in lines:
        print(line)

    checks = checks_of(case, motion, fluid, "baffle", fluid_ratio * dx, dx,
                       c0, DEPTH)
    print_checks(checks)

    with open(os.path.join(here, "result%s.md" % suffix), "w") as f:
        f.write("# rollingTankBaffle (%s): rolling tank with an elastic"
                " baffle\n\n" % solver)
        f.write("Baffle spacing %g m (%d particles through its 0.004 m), %s"
                " %g m, roll %.1f deg with T = %.4f s, run to %.3f s (%.1f"
                " periods). No measured history is public: the figures are"
                " for comparing solvers and resolutions, the checks are the"
                " targets.\n\n"
                % (dx, round(0.004 / dx), fluid, fluid_ratio * dx,
                   math.degrees(motion.amplitude), motion.period, ts[-1],
                   ts[-1] / motion.period))
        f.write("| quantity | value |\n|---|---|\n")
        f.write("| largest tip deflection (tank frame) | %.4f m at %.3f s"
                " |\n" % (ds[k], ts[k]))
        for t0, t1, amp, mean in periods:
            f.write("| deflection over %.3f-%.3f s | amplitude %.4f m, mean"
                    " %.4f m |\n" % (t0, t1, amp, mean))
        for what, value in cost_rows(cost, fluid):
            f.write("| %s | %s |\n" % (what, value))
        f.write("\n| check | |\n|---|---|\n")
        f.write("".join(row + "\n" for row in check_rows(checks)))
        f.write(comparison(here, solver, own, motion.period))

    plt = pyplot()
    if plt is not None:
        figure, (ax, ae) = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True)
        ax.plot(ts, ds, "-", lw=1.5, label="%s, dx = %g m (this run)"
                % (solver, dx))
        plot_comparison(ax, here, "rollingTankBaffle", solver, own, 3)
        scale = max(abs(d) for d in ds) or 1.0
        ax.plot(ts, [scale * motion.angle(t) / motion.amplitude for t in ts],
                ":", color="grey", lw=1, label="roll (scaled)")
        ax.set_ylabel("tip deflection, tank frame [m]")
        ax.set_title("Idelsohn et al. 2008 rolling tank, baffle tip")
        ax.grid(True)
        ax.legend(fontsize=8)
        energy = energy_total(case)
        te = read_monitor(case, "energy")["time"]
        ae.plot(te[:len(energy)], energy, "-", lw=1)
        ae.set_xlabel("t [s]")
        ae.set_ylabel("total energy less the roll's work [J/m]")
        ae.grid(True)
        figure.tight_layout()
        figure.savefig(os.path.join(here, "tip%s.png" % suffix), dpi=100)

    met = all(good for _, good in checks)
    return 1 if check and not met else 0
