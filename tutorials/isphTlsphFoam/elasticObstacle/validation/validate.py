#!/usr/bin/python3
"""Elastic obstacle (Walhorn et al. 2005): horizontal displacement of the
obstacle's top-left corner (point A) against the published numerical
solutions (validation/referenceSolutions.dat), etc/python/
elasticObstacle.py shared with the ULPH tutorial: the first peak, value
and time, inside the band the references span; and the stability checks
(fsiChecks). The obstacle 2 mm by default (6 particles through its
thickness), the water twice as coarse (multi-resolution).

Writes validation/result.md (or result-dx<spacing>.md for another
spacing) and pointA[-dx<spacing>].png. With --check, exits 1 when the
first peak is outside the band, the run stopped before it, or a stability
check is missed.

Usage: validate.py <case> [--check]
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT",
                         os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from elasticObstacle import validate  # noqa: E402

SETUP = ("Walhorn et al. 2005 as the ULPH tutorial (column 0.146 x 0.292 m,"
         " tank 0.584 m, obstacle 0.012 x 0.08 m at x = 0.292 m), rho_s"
         " 2500, E 1 MPa, nu 0 (BENCHMARKS.md), plane strain, TLSPH St"
         " Venant-Kirchhoff, implicit; ISPH water twice as coarse with the"
         " dam break tutorial's options but the divergence-free source"
         " alone, no-slip ghost walls, hydrostatic"
         " start, adaptive step maxCo 0.25 (at most 5e-4 s); isphTlsph"
         " coupling iterated (IQN-ILS).")

if __name__ == "__main__":
    sys.exit(validate(here, "isphTlsphFoam", "tutorials/isphTlsphFoam/"
                      "elasticObstacle", 0.002, SETUP, fluid_ratio=2,
                      stability=True, doc=__doc__))
