#!/usr/bin/python3
"""Validation of the hydrostatic plate (isphTlsphFoam, ISPH fluid and
TLSPH solid coupled by isphTlsph, each step iterated): the plate's mid-
span deflection against plate theory, and the run's stability
(etc/python/hydrostaticPlate.py: the references, measures and checks).

The loaded plate rings at about 0.017 s and settles within 0.1 s; the
deflection is the monitor's time average over the window all the same.

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
    solver="isphTlsphFoam", method="ISPH fluid + TLSPH solid",
    path="tutorials/isphTlsphFoam/hydrostaticPlate",
    fluid="ISPH (projection, BoomerAMG), cubic spline h = 1.2 dx_f, side"
          " walls of ghost particles, step at most 1e-3 s",
    coupling="isphTlsph, iterated (IQN-ILS, tolerance 1e-4)",
    window="the loaded plate rings at about 0.017 s and settles within"
           " 0.1 s")

if __name__ == "__main__":
    main(here, TUTORIAL)
