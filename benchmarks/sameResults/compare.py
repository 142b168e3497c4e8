#!/usr/bin/python3
"""Compare two runs of one case, old and new (benchmarks/sameResults/Allrun).

    compare.py [--name NAME] [--tol 1e-8] [--markdown FILE] OLD_CASE NEW_CASE

Clouds: every written time (the time folders' names must agree), every
body of <time>/lagrangian/ and every field of it, positions included,
read at full precision by etc/python/foamCloud.py of this tree; particles
are matched by their 'id' field (by order when a cloud has none). For each
the largest |new - old| over the particles and components divided by the
largest |old| of that field at that time; positions are divided by the
body's extent instead (the largest side of its bounding box in the old
run at that time), so that a body far from the origin is not favoured.

Monitors: every postProcessing/<name>/<start>/*.dat file, column by column
(columns matched by the header's names, '# time ...', when both sides
have the same ones), the same relative measure over the rows. The
components of a vector (columns named <stem>x, <stem>y[, <stem>z], e.g.
dx dy, plate:onSolidx ...) share one scale, the largest |old| of any of
them: a component that stays near zero (the x-displacement of a beam bent
in y) is measured against the vector it belongs to, not against its own
round-off. Monitor
files are written with fewer digits than the clouds (12 significant
digits, the coupling's forces.dat 6): a column whose difference exceeds
the tolerance but stays within one unit of the last printed digit of
every value is reported as within its print resolution, not failed.

Fields, monitor files and columns present on one side only are listed,
not failed; times, bodies and particles (ids) must agree. Appends the
case's tables to the markdown file, prints one summary line
'<name>: same to <X> (largest relative difference) PASS|FAIL ...' and
exits 0 when everything is within the tolerance, 1 otherwise.
"""
import argparse
import glob
import math
import os
import re
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
project = os.path.dirname(os.path.dirname(here))
sys.path.insert(0, os.path.join(project, "etc", "python"))
from foamCloud import read_cloud, times  # noqa: E402


def fmt(x):
    """A relative difference: exact 0 as 0, else 2 digits"""
    if x is None:
        return "-"
    if x == 0:
        return "0"
    if math.isinf(x) or math.isnan(x):
        return str(x)
    return "%.1e" % x


def max_abs_diff(a, b):
    """Largest |b - a|; NaN in the same places on both sides counts as
    equal, a NaN on one side only as infinite"""
    na, nb = np.isnan(a), np.isnan(b)
    if np.any(na != nb):
        return math.inf
    d = np.abs(b - a)[~na]
    return float(d.max()) if d.size else 0.0


def relative(diff, scale):
    if diff == 0:
        return 0.0
    return diff / scale if scale > 0 else math.inf


class Result:
    """The worst entry, the entries beyond the tolerance and the
    structural failures (times, bodies, particles, rows) of one case"""

    def __init__(self, tol):
        self.tol = tol
        self.worst = 0.0
        self.worst_where = ""
        self.beyond = 0
        self.failures = []
        self.print_limited = []
        self.one_sided = set()

    def record(self, rel, where):
        if rel > self.worst or math.isnan(rel):
            self.worst, self.worst_where = rel, where
        if not rel <= self.tol:
            self.beyond += 1

    def printed(self, rel, where):
        """A monitor column beyond the tolerance but within one unit of
        its last printed digit: noted, not failed"""
        self.print_limited.append((rel, where))

    def failed(self):
        return self.beyond > 0 or bool(self.failures)


def sorted_by_id(cloud):
    """The cloud's fields as arrays in the order of increasing id (ids
    returned too)"""
    n = len(cloud.get("positions", []))
    ids = np.asarray(cloud["id"], dtype=np.int64) if "id" in cloud \
        else np.arange(n)
    order = np.argsort(ids, kind="stable")
    out = {}
    for name, values in cloud.items():
        if name == "id":
            continue
        try:
            a = np.asarray(values, dtype=float)
        except ValueError:
            # A list of its own length per particle (a solid's brokenBonds):
            # tuples, compared exactly
            a = np.empty(len(values), dtype=object)
            a[:] = [tuple(v) if isinstance(v, (list, tuple)) else (v,)
                    for v in values]
        out[name] = a[order] if a.shape[:1] == ids.shape else a
    return ids[order], out


def compare_clouds(old, new, result):
    """{(body, field): {time: relative difference or a note}} and the
    list of times"""
    told = {name for _, name in times(old)}
    tnew = {name for _, name in times(new)}
    if told != tnew:
        result.failures.append(
            "written times differ: only old %s, only new %s"
            % (sorted(told - tnew, key=float) or "none",
               sorted(tnew - told, key=float) or "none"))
    common = sorted(told & tnew, key=float)
    table = {}
    for t in common:
        def bodies(case):
            d = os.path.join(case, t, "lagrangian")
            return set(os.listdir(d)) if os.path.isdir(d) else set()
        bold, bnew = bodies(old), bodies(new)
        for b in sorted(bold ^ bnew):
            result.failures.append("time %s: body %s only in %s"
                                   % (t, b, "old" if b in bold else "new"))
        for b in sorted(bold & bnew):
            iold, cold = sorted_by_id(read_cloud(old, t, b))
            inew, cnew = sorted_by_id(read_cloud(new, t, b))
            if iold.shape != inew.shape or np.any(iold != inew):
                common_ids = np.intersect1d(iold, inew)
                result.failures.append(
                    "time %s, body %s: particles differ (%d old, %d new,"
                    " %d ids in common)" % (t, b, iold.size, inew.size,
                                            common_ids.size))
                keep_o = np.isin(iold, common_ids)
                keep_n = np.isin(inew, common_ids)
                cold = {k: v[keep_o] if v.shape[:1] == iold.shape else v
                        for k, v in cold.items()}
                cnew = {k: v[keep_n] if v.shape[:1] == inew.shape else v
                        for k, v in cnew.items()}
            for f in sorted(set(cold) | set(cnew)):
                row = table.setdefault((b, f), {})
                if f not in cnew or f not in cold:
                    side = "old" if f in cold else "new"
                    row[t] = "only " + side
                    result.one_sided.add("%s/%s (%s)" % (b, f, side))
                    continue
                a, c = cold[f], cnew[f]
                if a.shape != c.shape:
                    row[t] = "shape %s vs %s" % (a.shape, c.shape)
                    result.failures.append("time %s, %s/%s: shape %s old,"
                                           " %s new" % (t, b, f, a.shape,
                                                        c.shape))
                    continue
                if a.dtype == object or c.dtype == object:
                    differ = int(sum(x != y for x, y in zip(a, c)))
                    rel = 0.0 if differ == 0 else math.inf
                    row[t] = rel
                    result.record(rel, "%s/%s at t = %s (lists of %d"
                                  " particles differ)" % (b, f, t, differ))
                    continue
                if f == "positions" and a.size:
                    scale = float(np.max(a.max(axis=0) - a.min(axis=0)))
                    if scale == 0:
                        scale = float(np.abs(a).max())
                else:
                    scale = float(np.abs(a).max()) if a.size else 0.0
                rel = relative(max_abs_diff(a, c), scale)
                row[t] = rel
                result.record(rel, "%s/%s at t = %s" % (b, f, t))
    return table, common


def significant_digits(token):
    """Significant digits of a number as written ('1.25e-05': 3)"""
    mantissa = re.split(r"[eE]", token.lstrip("+-"))[0].replace(".", "")
    return len(mantissa.lstrip("0"))


def read_dat(path):
    """(column names, values [rows x columns], significant digits the file
    is written with: the most of any number in it)"""
    names, rows, digits = None, [], 1
    for line in open(path):
        if line.startswith("#"):
            if re.match(r"#\s*time\b", line):
                names = line.lstrip("#").strip("\n").strip()
            continue
        tokens = line.split()
        if not tokens:
            continue
        rows.append([float(v) for v in tokens])
        digits = max([digits] + [significant_digits(v) for v in tokens])
    width = max((len(r) for r in rows), default=0)
    if any(len(r) != width for r in rows):
        raise ValueError("%s: rows of different lengths" % path)
    if names is not None:
        # Tab-separated names; a 'name(x y z)' stands for three columns
        cols = []
        for n in names.split("\t"):
            n = n.strip()
            m = re.match(r"(.*)\((\w+(?: \w+)+)\)$", n)
            if m:
                cols += ["%s%s" % (m.group(1), c) for c in m.group(2).split()]
            elif n:
                cols.append(n)
        if len(cols) != width:
            cols = names.split()
        names = cols if len(cols) == width else None
    if names is None:
        names = ["column %d" % (k + 1) for k in range(width)]
    return names, np.array(rows, dtype=float).reshape(-1, width), digits


def last_digit(values, digits):
    """One unit of the last significant digit of each value, written with
    that many digits (0 for 0)"""
    a = np.abs(values)
    out = np.zeros_like(a)
    nz = a > 0
    out[nz] = 10.0 ** (np.floor(np.log10(a[nz])) - digits + 1)
    return out


def compare_monitors(old, new, result):
    """Rows (file, column, rows old/new, relative, note)"""
    def files(case):
        base = os.path.join(case, "postProcessing")
        return {os.path.relpath(p, base)
                for p in glob.glob(os.path.join(base, "*", "*", "*.dat"))}
    fold, fnew = files(old), files(new)
    rows = []
    for f in sorted(fold | fnew):
        if f not in fnew or f not in fold:
            side = "old" if f in fold else "new"
            rows.append((f, "", "", None, "only in " + side))
            result.one_sided.add("%s (%s)" % (f, side))
            continue
        nold, vold, dold = read_dat(os.path.join(old, "postProcessing", f))
        nnew, vnew, dnew = read_dat(os.path.join(new, "postProcessing", f))
        digits = min(dold, dnew)
        count = "%d / %d" % (len(vold), len(vnew))
        if len(vold) != len(vnew):
            rows.append((f, "", count, None, "different number of rows"))
            result.failures.append("%s: %s rows" % (f, count))
            continue
        def vector_scale(name):
            """Largest |old| of the vector column name belongs to"""
            if name[-1:] not in ("x", "y", "z"):
                return None
            stem = name[:-1]
            group = [k for k, n in enumerate(nold)
                     if n[:-1] == stem and n[-1:] in ("x", "y", "z")]
            if len(group) < 2:
                return None
            return float(np.abs(vold[:, group]).max()) if len(vold) else 0.0

        for k, c in enumerate(nold):
            if c not in nnew:
                rows.append((f, c, count, None, "only in old"))
                result.one_sided.add("%s %s (old)" % (f, c))
                continue
            j = nnew.index(c)
            a, b = vold[:, k], vnew[:, j]
            scale = vector_scale(c)
            if scale is None:
                scale = float(np.abs(a).max()) if a.size else 0.0
            rel = relative(max_abs_diff(a, b), scale)
            note = ""
            worst_row = int(np.argmax(np.abs(b - a))) if a.size else 0
            where = "monitor %s, column %s at t = %g" \
                % (f, c, vold[worst_row, 0]) if a.size else "monitor " + f
            unit = np.maximum(last_digit(a, digits), last_digit(b, digits))
            if rel > result.tol and not math.isinf(rel) \
                    and np.all(np.abs(b - a) <= 1.000001 * unit):
                note = "within the print resolution (%d digits)" % digits
                result.printed(rel, where)
            else:
                result.record(rel, where)
            rows.append((f, c, count, rel, note))
        for c in nnew:
            if c not in nold:
                rows.append((f, c, count, None, "only in new"))
                result.one_sided.add("%s %s (new)" % (f, c))
    return rows


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("old")
    p.add_argument("new")
    p.add_argument("--name", default="case")
    p.add_argument("--tol", type=float, default=1e-8)
    p.add_argument("--markdown", help="append the tables to this file")
    args = p.parse_args()

    result = Result(args.tol)
    table, common = compare_clouds(args.old, args.new, result)
    monitors = compare_monitors(args.old, args.new, result)

    if result.failed():
        why = []
        if result.beyond:
            why.append("worst %s; %d entries above %g"
                       % (result.worst_where, result.beyond, args.tol))
        why += result.failures[:2]
        if len(result.failures) > 2:
            why.append("%d more" % (len(result.failures) - 2))
        verdict = "FAIL: " + "; ".join(why)
    else:
        verdict = "PASS"
    summary = "%s: same to %s (largest relative difference) %s" % (
        args.name, fmt(result.worst), verdict)
    if result.one_sided:
        summary += "; on one side only (not compared): " + ", ".join(
            sorted(result.one_sided))
    if result.print_limited:
        rel, where = max(result.print_limited)
        summary += ("; %d monitor column(s) differ within their print"
                    " resolution only (largest %s: %s)"
                    % (len(result.print_limited), fmt(rel), where))

    if args.markdown:
        with open(args.markdown, "a") as md:
            md.write("## %s\n\n%s\n\n" % (args.name, summary))
            md.write("Clouds: largest |new - old| / largest |old| of the field"
                     " (positions: / the body's extent, the largest side of"
                     " its bounding box) per written time; -: not written"
                     " at that time.\n\n")
            if common:
                md.write("| body | field | " + " | ".join(
                    "t = %s" % t for t in common) + " |\n")
                md.write("|---|---|" + "---|" * len(common) + "\n")
                for (b, f), row in sorted(table.items()):
                    md.write("| %s | %s | %s |\n" % (b, f, " | ".join(
                        fmt(row[t]) if isinstance(row.get(t), float)
                        else row.get(t, "-") for t in common)))
            else:
                md.write("No written time on both sides.\n")
            md.write("\n")
            if monitors:
                md.write("| monitor file | column | rows old / new |"
                         " relative difference | |\n|---|---|---|---|---|\n")
                for f, c, n, rel, note in monitors:
                    md.write("| %s | %s | %s | %s | %s |\n"
                             % (f, c, n, fmt(rel), note))
            else:
                md.write("No monitor files.\n")
            md.write("\n")
            for failure in result.failures:
                md.write("- FAIL: %s\n" % failure)
            if result.failures:
                md.write("\n")
    print(summary)
    return 1 if result.failed() else 0


if __name__ == "__main__":
    sys.exit(main())
