#!/usr/bin/python3
"""Case test: still water on a plate, the ISPH fluid and a TLSPH solid
coupled by isphTlsph (isphTlsphFoam).

The scene of riemannTlsphHydrostatic (water 0.2 x 0.1 m on a plate
0.2 x 0.02 m clamped at both ends that is the tank's bottom, free-slip
ghost walls left, right and under the plate, the implicit integrator)
with the ISPH fluid of the still water tutorial (corrected gradient,
pairwise walls, CG), 0.5 s:

- Rigid plate (E = 1e12 Pa), twice as fine as the water, at water
  spacings dx = 5 and 2.5 mm (H/dx = 20, 40): the mean force on the plate
  over 0.1-0.5 s against the water's weight rho g H W, within 5 % and
  3 %, and its error at least 1.5 times smaller at the finer spacing
  (measured -4.3 %, -2.5 % and, at 1.25 mm, -1.5 %; with the plate as
  fine as the water -4.9 %, -2.7 %, -1.8 %). Half a spacing of it is the
  ISPH column's own (the free-surface condition p = 0 sits on the surface
  particles, half a spacing below the water's edge), the rest tends to
  the exchange's lattice sums, 0.92 % low (isphEquations::
  interfaceReaction and its unit test). Per step the fluid's force on the plate
  and the plate's on the fluid cancel to 1e-9 of their size; the log
  names the coupling; no particle lost, none of the water inside the
  plate.
- Elastic plate (E = 1e8 Pa, the implicit integrator at the fluid's
  step) at dx = 5 mm: runs to 0.5 s, the same balance (the load within
  6 %: -5.2 % measured, the rigid plate's -4.3 % and the deflected
  plate's lattice), no particle lost,
  no water inside the plate, and the mid-span deflection at the end
  against clamped-clamped plate theory (plane strain, the weight of the
  water and of the plate, with shear, over the span between the clamped
  regions) within 10 % (+3.3 % measured; the load is the rigid plate's).
- Bad input: a weakly compressible fluid (riemannWcsph) refused, naming
  isph and the couplings to use instead; solidAcceleration other than
  none or step refused, naming the keyword; a solid's contact 'walls'
  naming a body that is not a ghost wall refused, naming the entry.

And the tutorial isphTlsphFoam/hydrostaticPlate, coarse and short
(Allrun -n 4 -end 0.5: 4 plate particles through the thickness, the water
at 25 mm; 2 m of water on 0.05 m of aluminium, a mass ratio of 15), with
the coupling's sub-iterations (interfaceQuasiNewton): its validation's
stability checks met, the mean mid-span deflection over the last two
thirds within 5 % of plate theory with shear, the forces balanced every
step, every step converged (none at maxIterations) in at most 4
iterations on average. The same scene without the sub-iterations (the
staggered exchange) blows up, with the blow-up's diagnosis: the added-mass
instability the iterations remove.
"""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import (copy_case, run, run_parts, run_steps,  # noqa: E402
                      run_tutorial, set_entry)
from foamCloud import read_cloud, times  # noqa: E402
from fsiChecks import plate_force_checks  # noqa: E402

H, W, G, RHO = 0.1, 0.2, 9.81, 1000.0
PLATE_T, PLATE_RHO, NU = 0.02, 2000.0, 0.3
PROPS = "constant/particleProperties"


def make_case(work, name, dx, E):
    """The scene with the ISPH water, water and walls at dx, the plate at
    dx/2, Young's modulus E"""
    case = copy_case(os.path.join(here, "isphTlsphHydrostatic"),
                     os.path.join(work, name))
    for body, spacing in (("water", dx), ("tank", dx), ("plate", dx / 2)):
        set_entry(case, "system/seedParticlesDict", "bodies/%s/spacing" % body,
                  spacing)
    set_entry(case, PROPS, "bodies/plate/constitutiveLaw/E", E)
    return case


def common_checks(t, case, dx, prefix):
    t_end, last = times(case)[-1]
    t.check_close(prefix + "ran to 0.5 s", t_end, 0.5, 1e-9)
    water = read_cloud(case, last, "water")["positions"]
    plate = read_cloud(case, last, "plate")["positions"]
    n_w = round(W / dx) * round(H / dx)
    n_p = round(W / dx * 2) * round(PLATE_T / dx * 2)
    t.check_equal(prefix + "no fluid particle lost", len(water), n_w)
    t.check_equal(prefix + "no plate particle lost", len(plate), n_p)
    top = max(x[1] for x in plate)
    lowest = min(x[1] for x in water)
    t.check(prefix + "no fluid particle inside the plate (lowest %.5f m,"
            " plate's top row %.5f m)" % (lowest, top), lowest > top)
    return plate


def rigid(t, work):
    errors = []
    for dx, rtol in ((0.005, 0.05), (0.0025, 0.03)):
        prefix = "rigid, dx %g: " % dx
        case = make_case(work, "rigid%g" % dx, dx, 1e12)
        ok, out = run_steps(t, case, ("blockMesh", "seedParticles",
                                      "isphTlsphFoam"), prefix)
        if not ok:
            return
        forces = plate_force_checks(t, case, out, "isphTlsph", 50,
                                    -RHO * G * H * W, rtol)
        late = [r[2] for r in forces if r[0] >= 0.1]
        errors.append(sum(late) / len(late) / (-RHO * G * H * W) - 1)
        common_checks(t, case, dx, prefix)
    t.check("load error %.2f %% at dx 5 mm, %.2f %% at 2.5 mm: at least 1.5"
            " times smaller (first order)" % (100 * errors[0],
                                              100 * errors[1]),
            abs(errors[1]) * 1.5 <= abs(errors[0]))


def plate_theory_deflection():
    """Mid-span deflection of a plate clamped at both ends (plane strain,
    E' = E/(1 - nu^2)) under the uniform load q of the water's weight and
    its own, with Timoshenko shear (k = 5/6): w = q L^4/(384 E' I) +
    q L^2/(8 k G A), L = 0.18 m the span between the clamped ends'
    regions (x < 0.01 m, x > 0.19 m)"""
    E, L = 1e8, 0.18
    q = RHO * G * H + PLATE_RHO * G * PLATE_T
    Ep = E / (1 - NU * NU)
    inertia = PLATE_T ** 3 / 12
    shear = E / (2 * (1 + NU)) * 5 / 6 * PLATE_T
    return q * L ** 4 / (384 * Ep * inertia) + q * L * L / (8 * shear)


def elastic(t, work):
    dx = 0.005
    case = make_case(work, "elastic", dx, 1e8)
    ok, out = run_steps(t, case, ("blockMesh", "seedParticles",
                                  "isphTlsphFoam"), "elastic: ")
    if not ok:
        return
    plate_force_checks(t, case, out, "isphTlsph", 50, -RHO * G * H * W, 0.06)
    plate = common_checks(t, case, dx, "elastic: ")
    start = read_cloud(case, "0", "plate")["positions"]
    mid = min(range(len(start)), key=lambda k: abs(start[k][0] - W / 2)
              + abs(start[k][1] + PLATE_T / 2))
    w = start[mid][1] - plate[mid][1]
    theory = plate_theory_deflection()
    t.check_close("elastic: mid-span deflection %.3e m vs plate theory %.3e m"
                  % (w, theory), w, theory, 0.10)

    set_entry(case, PROPS, "coupling/solidAcceleration", "instant")
    code, log = run(["isphTlsphFoam"], case)
    t.check("solidAcceleration instant refused, naming the keyword",
            code != 0 and "solidAcceleration" in log and "step" in log,
            log[-1500:])
    set_entry(case, PROPS, "coupling/solidAcceleration", "none")

    # A solid's contact 'walls' must name ghost walls
    set_entry(case, PROPS, "bodies/plate/walls", "(water)")
    code, log = run(["isphTlsphFoam"], case)
    t.check("a solid's contact with a fluid ('walls (water)') refused,"
            " naming the entry, the body and a ghostWall", code != 0
            and "'walls'" in log and "water" in log and "ghostWall" in log,
            log[-1500:])
    set_entry(case, PROPS, "bodies/plate/walls", "(tank)")
    code, log = run(["isphTlsphFoam"], case)
    t.check("'walls (tank)' taken (the run starts and ends)", code == 0,
            log[-1500:])
    set_entry(case, PROPS, "bodies/plate/walls", "()")

    set_entry(case, PROPS, "bodies/water/model", "riemannWcsph")
    set_entry(case, PROPS, "bodies/water/soundSpeed", 20)
    set_entry(case, PROPS, "bodies/water/kernelCorrection", "none")
    code, log = run(["isphTlsphFoam"], case)
    t.check("a weakly compressible fluid refused, naming isph and"
            " riemannTlsph", code != 0 and "isph" in log
            and "riemannTlsph" in log, log[-1500:])


def tutorial(t, work):
    plate_l, column = 1.0, 2.0
    case, code, out = run_tutorial(
        t, "tutorials/isphTlsphFoam/hydrostaticPlate", work, "tutorial",
        ("-n", "4", "-end", "0.5"), check=False)
    m = re.search(r"mean deflection ([0-9.e+-]+) m, ([-+0-9.]+) %", out)
    t.check("tutorial validated", m is not None, out[-1500:])
    if m:
        err = float(m.group(2))
        t.check("tutorial: mean deflection %s m, %+.2f %% of plate theory "
                "with shear, within 5 %%" % (m.group(1), err), abs(err) < 5)
    missed = [line for line in out.splitlines() if line.endswith("MISSED")]
    t.check("tutorial: stability checks met", not missed and m is not None,
            "\n".join(missed))
    if not os.path.isfile(os.path.join(case, "log.isphTlsphFoam")):
        return
    with open(os.path.join(case, "log.isphTlsphFoam")) as f:
        log = f.read()
    plate_force_checks(t, case, log, "isphTlsph", 400,
                       -RHO * G * column * plate_l, 0.05)
    s = re.search(r"coupling isphTlsph: ([0-9.e+-]+) iterations per step on"
                  r" average, at most (\d+), (\d+) steps stopped", log)
    t.check("tutorial: the log gives the iterations", s is not None)
    if s:
        t.check("tutorial: %s iterations per step on average (at most %s),"
                " at most 4" % (s.group(1), s.group(2)),
                float(s.group(1)) <= 4)
        t.check("tutorial: every step converged (%s at maxIterations)"
                % s.group(3), s.group(3) == "0")

    # The staggered exchange: the added-mass instability
    props = "constant/particleProperties"
    code, _ = run(["foamDictionary", props, "-entry", "coupling/iterations",
                   "-remove"], case)
    t.check("staggered: iterations removed", code == 0)
    set_entry(case, "system/controlDict", "startFrom", "startTime")
    code, log = run(["isphTlsphFoam"], case)
    t.check("staggered: the same scene blows up, with a diagnosis",
            code != 0 and "Blow-up" in log, log[-1500:])


if __name__ == "__main__":
    sys.exit(run_parts("isphTlsphHydrostatic", rigid, elastic, tutorial))
