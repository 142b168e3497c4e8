#!/usr/bin/python3
"""Elastic gate (Antoci et al. 2007): free-end displacement vs experiment,
RMS of x(t) and y(t), stability checks, validation/result.md and
freeEnd.png (etc/python/elasticGate.py, shared by the solvers' elasticGate
tutorials). The gate 1.25 mm by default (4 particles through its
thickness), the water twice as coarse (multi-resolution).

Usage: validate.py <case> [--check]
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT",
                         os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from elasticGate import validate  # noqa: E402

if __name__ == "__main__":
    sys.exit(validate(here, "isphTlsphFoam", 0.00125, fluid_ratio=2,
                      doc=__doc__))
