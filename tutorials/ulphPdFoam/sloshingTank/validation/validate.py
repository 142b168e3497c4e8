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

SETUP = ("c0 = 40 m/s, alpha = 0.1, Gaussian h = 1.2 dx, horizon 3h, density "
         "filter every 20 steps, no-slip ghost walls")

if __name__ == "__main__":
    case, check = arguments()
    sys.exit(validate(case, check, "ulphPdFoam",
                      "tutorials/ulphPdFoam/sloshingTank", SETUP, here))
