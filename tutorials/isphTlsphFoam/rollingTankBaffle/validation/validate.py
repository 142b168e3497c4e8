#!/usr/bin/python3
"""Rolling tank with an elastic baffle (Idelsohn et al. 2008): the
baffle tip's deflection in the tank's frame, stability checks over ten
periods, validation/result.md, tip.dat and tip.png
(etc/python/rollingTankBaffle.py, shared by the solvers'
rollingTankBaffle tutorials). The baffle 1 mm by default (4 particles
through its thickness), the oil twice as coarse (multi-resolution).

Usage: validate.py <case> [--check]
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT",
                         os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from rollingTankBaffle import validate  # noqa: E402

if __name__ == "__main__":
    sys.exit(validate(here, "isphTlsphFoam", 0.001, fluid_ratio=2,
                      doc=__doc__))
