#!/usr/bin/env python3
"""Surge front of the VOF dam break (interFoam) at every written time.

The front is the largest x where the water fraction alpha.water crosses 0.5,
over all rows of the uniform grid (the alpha = 0.5 contour's foremost point),
interpolated linearly between cell centres. The grid is the one block of
system/blockMeshDict: nx x ny cells of size H/n, cell i at column i % nx and
row i // nx (system/resolution).

    front.py CASE OUT

writes OUT: T = t sqrt(g/H) and x/H, one line per written time.
"""

import math
import os
import re
import sys

H = 0.057
G = 9.81


def read_resolution(case):
    with open(os.path.join(case, "system", "resolution")) as f:
        text = f.read()
    values = dict(re.findall(r"(\w+)\s+([0-9]+)\s*;", text))
    return int(values["n"]), int(values["nx"]), int(values["ny"])


def read_alpha(path, size):
    """The internal field of a volScalarField, ascii or binary."""
    with open(path, "rb") as f:
        data = f.read()
    binary = re.search(rb"format\s+binary\s*;", data) is not None
    arch = re.search(rb'arch\s+"([^"]*)"', data)
    if binary and arch and (b"LSB" not in arch.group(1)
                            or b"scalar=64" not in arch.group(1)):
        sys.exit("front.py: %s is %s: expected LSB;scalar=64"
                 % (path, arch.group(1).decode()))
    m = re.search(rb"internalField\s+uniform\s+([^;]+);", data)
    if m:
        return [float(m.group(1))]*size
    m = re.search(rb"internalField\s+nonuniform\s+List<scalar>\s+(\d+)\s*\(",
                  data)
    if not m:
        sys.exit("front.py: no internalField in " + path)
    n = int(m.group(1))
    if n != size:
        sys.exit("front.py: %s holds %d cells, the grid %d" % (path, n, size))
    start = m.end()
    if binary:
        import struct
        return list(struct.unpack_from("<%dd" % n, data, start))
    return [float(v) for v in data[start:].split(b")")[0].split()]


def front(alpha, n, nx, ny):
    dx = H/n
    best = 0.0
    for j in range(ny):
        row = alpha[j*nx:(j + 1)*nx]
        last = -1
        for i in range(nx - 1, -1, -1):
            if row[i] >= 0.5:
                last = i
                break
        if last < 0:
            continue
        x = (last + 0.5)*dx
        if last + 1 < nx:
            a, b = row[last], row[last + 1]
            x += (a - 0.5)/(a - b)*dx
        else:
            x = nx*dx
        best = max(best, x)
    return best


def main():
    if len(sys.argv) != 3:
        sys.exit("Usage: front.py CASE OUT")
    case, out = sys.argv[1:]
    n, nx, ny = read_resolution(case)
    times = []
    for name in os.listdir(case):
        try:
            t = float(name)
        except ValueError:
            continue
        if os.path.isfile(os.path.join(case, name, "alpha.water")):
            times.append((t, name))
    times.sort()
    with open(out, "w") as f:
        f.write("# T = t sqrt(g/H)   x/H (alpha.water = 0.5, foremost point)\n")
        for t, name in times:
            alpha = read_alpha(os.path.join(case, name, "alpha.water"), nx*ny)
            f.write("%.5f %.5f\n" % (t*math.sqrt(G/H), front(alpha, n, nx, ny)/H))


if __name__ == "__main__":
    main()
