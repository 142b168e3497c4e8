#!/usr/bin/python3
"""Case test: the interFoam reference of the dam break
(benchmarks/damBreakVof).

front.py, which turns the VOF solution into the surge front the damBreak
tutorial is compared with, is checked on made-up fields whose front is
known (ascii and binary, a straight edge and a tongue ahead of the column,
a cell of the last column), result.py's reading of the run names, and on
a short coarse interFoam run of the case
(n = 19 cells per H, to t = 0.04 s): the front starts at the column's edge
x = H, does not go back and has moved on by t = 0.04 s as far as the
finer runs say (x/H = 1.299 at T = 0.525 for n = 57, 85 and 114, to
0.002; within 0.03 here).
"""
import os
import shutil
import struct
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "lib"))
from caseTest import project_dir, run, run_parts, set_entry  # noqa: E402
from foamMonitor import read_rows  # noqa: E402

BENCH = os.path.join(project_dir, "benchmarks", "damBreakVof")
H = 0.057


def write_case(case, n, alpha, binary):
    """A case with system/resolution and alpha.water at t = 0.01"""
    nx, ny = 4 * n, 2 * n
    os.makedirs(os.path.join(case, "system"))
    os.makedirs(os.path.join(case, "0.01"))
    open(os.path.join(case, "system", "resolution"), "w").write(
        "n %d;\nnx %d;\nny %d;\n" % (n, nx, ny))
    head = ("FoamFile\n{\n    version 2.0;\n    format %s;\n"
            "    class volScalarField;\n    object alpha.water;\n}\n"
            "dimensions [0 0 0 0 0 0 0];\n\n"
            "internalField nonuniform List<scalar> \n%d\n("
            % ("binary" if binary else "ascii", nx * ny))
    with open(os.path.join(case, "0.01", "alpha.water"), "wb") as f:
        f.write(head.encode())
        if binary:
            f.write(struct.pack("<%dd" % len(alpha), *alpha))
        else:
            f.write(("\n" + "\n".join("%.17g" % a for a in alpha)
                     + "\n").encode())
        f.write(b")\n;\n\nboundaryField\n{\n}\n")


def front_of(work, name, n, alpha, binary):
    case = os.path.join(work, name)
    write_case(case, n, alpha, binary)
    out = os.path.join(work, name + ".dat")
    code, log = run([sys.executable, os.path.join(BENCH, "front.py"), case,
                     out], work)
    if code != 0:
        return None, log
    rows = read_rows(out)
    return rows[0][1], log


def check_made_up(t, work):
    n = 10
    nx, ny = 4 * n, 2 * n
    dx = H / n
    # Column of 15 cells, rows 0-4, its last cell half full: the 0.5
    # crossing lies at that cell's centre, 14.5 dx
    alpha = [0.0] * (nx * ny)
    for j in range(5):
        for i in range(14):
            alpha[j * nx + i] = 1.0
        alpha[j * nx + 14] = 0.5
    for binary in (False, True):
        x, log = front_of(work, "edge%d" % binary, n, alpha, binary)
        t.check("%s: half-full last cell, front at its centre (%s, 14.5 dx)"
                % ("binary" if binary else "ascii",
                   "%.6f dx" % (x * H / dx) if x is not None else log),
                x is not None and abs(x * H / dx - 14.5) < 1e-4)
    # A tongue in row 0 ahead of the column to cell 24 (alpha 0.9), then
    # 0.3: crossing at 24.5 + 0.4/0.6 dx
    tongue = list(alpha)
    for i in range(14, 25):
        tongue[i] = 0.9
    tongue[25] = 0.3
    x, log = front_of(work, "tongue", n, tongue, True)
    # (front.py writes x/H to 5 decimals: 1e-4 dx here)
    expected = 24.5 + 0.4 / 0.6
    t.check("the foremost row counts: tongue to %.4f dx (%s)"
            % (expected, "%.6f dx" % (x * H / dx) if x is not None else log),
            x is not None and abs(x * H / dx - expected) < 1e-4)
    # Water in the last column: the front is the wall, 4H
    wall = list(alpha)
    wall[nx - 1] = 1.0
    x, log = front_of(work, "wall", n, wall, False)
    t.check("water in the last column: front at the wall, 4H (%s)"
            % ("%.6f H" % x if x is not None else log),
            x is not None and abs(x - 4.0) < 1e-9)


def check_run(t, work):
    case = os.path.join(work, "coarse")
    shutil.copytree(os.path.join(BENCH, "case"), case)
    shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))
    open(os.path.join(case, "system", "resolution"), "w").write(
        "n 19;\nnx 76;\nny 38;\n")
    set_entry(case, "system/controlDict", "endTime", 0.04)
    for app in ("blockMesh", "setFields", "interFoam"):
        code, log = run([app], case)
        open(os.path.join(case, "log." + app), "w").write(log)
        t.check("%s runs" % app, code == 0, log[-2000:])
        if code != 0:
            return
    out = os.path.join(work, "coarse.dat")
    code, log = run([sys.executable, os.path.join(BENCH, "front.py"), case,
                     out], work)
    t.check("front.py reads the run", code == 0, log)
    if code != 0:
        return
    rows = read_rows(out)
    t.check("fronts at t = 0 and every 2.5 ms to 0.04 s (%d)" % len(rows),
            len(rows) == 17)
    t.check("the front starts at the column's edge (x/H = %.4f)"
            % rows[0][1], abs(rows[0][1] - 1.0) < 1e-9)
    back = min(b[1] - a[1] for a, b in zip(rows, rows[1:]))
    t.check("the front never goes back (smallest step %+.4f H)" % back,
            back >= -1e-9)
    T, x = rows[-1]
    t.check("at T = %.3f the front is at x/H = %.3f (finer runs: 1.299 "
            "+- 0.03)" % (T, x),
            abs(T - 0.525) < 1e-3 and abs(x - 1.299) < 0.03)


def check_variants(t, work):
    """result.py's reading of the front files' names"""
    sys.path.insert(0, BENCH)
    from result import key, variant
    for name, expected in [
            ("front-n114.dat", ("", 114, "0.072", "1e-6")),
            ("front-n57-sigma0.dat", ("-sigma0", 57, "0", "1e-6")),
            ("front-n57-sigma7.2e-2-nu1E-4.dat",
             ("-sigma7.2e-2-nu1E-4", 57, "7.2e-2", "1E-4"))]:
        suffix, n = key(name)
        got = (suffix, n) + variant(suffix)
        t.check_equal("result.py reads %s" % name, got, expected)


def check_interfoam_run(t, work):
    if shutil.which("interFoam") is None:
        t.check("interFoam on the PATH (etc/bashrc)", False)
    else:
        check_run(t, work)

if __name__ == "__main__":
    sys.exit(run_parts("damBreakVof", check_variants, check_made_up,
                       check_interfoam_run))
