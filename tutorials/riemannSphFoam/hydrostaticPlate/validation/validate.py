#!/usr/bin/python3
"""Validation of the hydrostatic plate (riemannSphFoam, Riemann fluid and
TLSPH solid coupled by riemannTlsph): the plate's mid-span deflection
against plate theory, and the run's stability (etc/python/
hydrostaticPlate.py: the references, measures and checks).

The weakly compressible column rings (its acoustic period 4 H/c0 = 0.12
s, little damped): the deflection is the monitor's time average. The
column's acoustic ringing gains about 2e-3 of rho g H^2 L/2 between 0.5
and 1.4 s and loses it again; it does the same on a rigid plate (E 1000
times larger: 1.6e-3 by 1.5 s), so it is the water's own, not the
coupling's (README).

Usage: validate.py <case> [--check]
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT",
                         os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from hydrostaticPlate import Tutorial, main  # noqa: E402

TUTORIAL = Tutorial(
    solver="riemannSphFoam", method="Riemann fluid + TLSPH solid",
    path="tutorials/riemannSphFoam/hydrostaticPlate",
    fluid="Riemann WCSPH, c0 65 m/s, WKGC 0.9, dissipation in compression,"
          " Wendland C2 h = 1.3 dx_f, side walls of dummy particles",
    coupling="riemannTlsph",
    window="the weakly compressible column rings at 4 H/c0 = 0.12 s")

if __name__ == "__main__":
    main(here, TUTORIAL)
