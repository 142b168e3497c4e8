#!/usr/bin/python3
"""Free fall under gravity: compare the particles with the exact solution.

The symplectic Euler scheme with a fixed step dt from rest gives after n steps
    y_n = y_0 + g dt^2 n (n + 1) / 2
exactly (to round-off); the continuous solution is y_0 + g t^2 / 2, which
the scheme approaches at first order in dt (the difference is g dt t / 2).
Reads the ascii clouds of the first and last times (full precision with
writePrecision 17), prints both errors, and exits 1 when the error against
the discrete solution exceeds 1e-9 m.

Usage: validate.py <case>
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
project = os.environ.get("MESHLESS_PROJECT",
                         os.path.join(here, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from foamCloud import read_cloud, times  # noqa: E402


def main(case):
    g = -9.81
    dt = 0.001
    t_end, last = times(case)[-1]
    n = round(t_end / dt)
    first = read_cloud(case, times(case)[0][1], "drop")
    final = read_cloud(case, last, "drop")
    y0 = dict(zip(first["id"], first["positions"]))
    y1 = dict(zip(final["id"], final["positions"]))
    discrete = g * dt * dt * n * (n + 1) / 2
    continuous = g * t_end * t_end / 2
    err_d = max(abs(y1[i][1] - y0[i][1] - discrete) for i in y0)
    err_c = max(abs(y1[i][1] - y0[i][1] - continuous) for i in y0)
    err_x = max(abs(y1[i][0] - y0[i][0]) for i in y0)
    print("free fall to t = %g s (%d steps of %g s), %d particles"
          % (t_end, n, dt, len(y0)))
    print("  drop: exact discrete %.10f m, simulated error %.3e m"
          % (discrete, err_d))
    print("  vs continuous g t^2/2 = %.10f m: difference %.3e m"
          " (first order: g dt t / 2 = %.3e m)"
          % (continuous, err_c, abs(g * dt * t_end / 2)))
    print("  horizontal drift %.3e m" % err_x)
    ok = len(y1) == len(y0) and err_d < 1e-9 and err_x < 1e-12
    print("free fall: %s" % ("PASS" if ok else "FAIL"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
