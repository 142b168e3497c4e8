#!/usr/bin/python3
"""Dam break on an elastic plate (Liao et al. 2015): the plate tip's
history, stability checks, validation/result.md, tip.dat and tip.png
(etc/python/liaoPlate.py, shared by the solvers' liaoPlate tutorials). The
plate 1 mm by default (4 particles through its thickness), the water four
times as coarse (multi-resolution).

Usage: validate.py <case> [--check]
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT",
                         os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from liaoPlate import validate  # noqa: E402

if __name__ == "__main__":
    sys.exit(validate(here, "isphTlsphFoam", 0.001, fluid_ratio=4,
                      doc=__doc__))
