#!/usr/bin/python3
"""Sloshing tank: free-surface elevation at FS1 (0.05 m from the left wall)
against the linear modal solution, over the first two periods
(etc/python/sloshingValidation.py: the reference, the measures and their
target).

Writes validation/result[-dx<spacing>].md and elevation[...].png.
With --check, exits 1 when the phase target is missed.

Usage: validate.py <case> [--check]
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT",
                         os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from foamMonitor import arguments  # noqa: E402
from sloshingValidation import validate  # noqa: E402

SETUP = ("projection ISPH, cubic spline h = 1.2 dx, the Poisson equation "
         "by BiCGStab to 1e-8 with the walls' own rows (Lind et al. 2012), "
         "the divergence-free source alone, wall contact 1 dx, the "
         "sum form of the gradient near the surface, Fickian shifting 0.1, "
         "mu = 1e-3 Pa s, maxCo 0.1, no-slip ghost walls")

if __name__ == "__main__":
    case, check = arguments()
    sys.exit(validate(case, check, "isphTlsphFoam",
                      "tutorials/isphTlsphFoam/sloshingTank", SETUP, here))
