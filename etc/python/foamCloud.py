"""Reading meshlessFoam's lagrangian clouds at full precision, for tutorial
validation scripts and tests (ParaView's reader converts to float32).

    import sys; sys.path.insert(0, os.path.join(MESHLESS_PROJECT, "etc/python"))
    from foamCloud import times, read_cloud

read_cloud(case, time, body) returns {"id": [...], "positions": [[x,y,z],..],
<field>: [...]} for the files of <case>/<time>/lagrangian/<body>/ (but
OpenFOAM's barycentric 'coordinates'; positions from the exact 'position'
field when there is one), ascii or
binary (writeFormat binary: the arch of the file's header gives the sizes
of labels and scalars); read_field and read_positions one file of it;
speed_history a body's RMS and largest speed at each written time.
"""
import math
import os
import re
import struct

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def times(case):
    """Time folders of a case as (value, name), sorted by value."""
    out = []
    for d in os.listdir(case):
        if not os.path.isdir(os.path.join(case, d)):
            continue
        try:
            out.append((float(d), d))
        except ValueError:
            pass
    return sorted(out)


def _body(text):
    """The list part of an OpenFOAM file: after the header block."""
    end = text.index("}", text.index("FoamFile")) + 1
    return text[end:]


_COMPONENTS = {"scalarField": 1, "labelField": 1, "vectorField": 3,
               "symmTensorField": 6, "tensorField": 9}


class _Layout:
    """The packing of a binary file, from its header's arch: the byte
    order and the struct code and size of a label and of a scalar"""

    def __init__(self, head):
        arch = re.search(r'arch\s+"([^"]*)"', head)
        arch = arch.group(1) if arch else "LSB;label=32;scalar=64"
        self.order = "<" if arch.startswith("LSB") else ">"
        bits = dict(re.findall(r"(label|scalar)=(\d+)", arch))
        self.label, self.label_size = {"32": ("i", 4), "64": ("q", 8)}[
            bits.get("label", "32")]
        self.scalar, self.scalar_size = {"32": ("f", 4), "64": ("d", 8)}[
            bits.get("scalar", "64")]


def _read_binary(path, raw):
    """A binary list file (IOField of labels, scalars or vectors): the
    count, '(' and the packed values"""
    head = raw[:raw.index(b"}", raw.index(b"FoamFile")) + 1].decode()
    cls = re.search(r"class\s+([^;\s]+);", head).group(1)
    layout = _Layout(head)
    if cls == "labelFieldField":
        return _read_binary_label_lists(path, raw, head, layout)
    if cls == "labelFieldCompactField":
        return _read_binary_compact_label_lists(path, raw, head, layout)
    if cls == "Cloud<passiveParticle>":
        return _read_binary_cloud(path, raw, head, layout)
    if cls not in _COMPONENTS:
        raise ValueError("%s: binary %s not supported" % (path, cls))
    order = layout.order
    code = layout.label if cls == "labelField" else layout.scalar
    # the count starts the first line after the header's comment lines;
    # binary lists are always N(bytes) (OpenFOAM writes N{value} only in
    # ascii), an empty one just 0
    m = re.compile(rb"\n\s*(\d+)\s*(\(|\n|$)").search(raw, len(head))
    if m is None:
        raise ValueError("no list in " + path)
    n, k = int(m.group(1)), _COMPONENTS[cls]
    if n == 0:
        return []
    if m.group(2) != b"(":
        raise ValueError("%s: expected '(' after the count %d" % (path, n))
    values = struct.unpack_from(order + code * (n * k), raw, m.end())
    if k == 1:
        return list(values)
    return [list(values[i * k:(i + 1) * k]) for i in range(n)]


def _read_binary_label_lists(path, raw, head, layout):
    """A binary labelFieldField (per particle a list of labels): the count,
    '(' and per entry its length and, when not empty, its packed labels"""
    order, code, size = layout.order, layout.label, layout.label_size
    m = re.compile(rb"\n\s*(\d+)\s*(\(|\n|$)").search(raw, len(head))
    if m is None:
        raise ValueError("no list in " + path)
    n = int(m.group(1))
    if n == 0:
        return []
    pos, out = m.end(), []
    number = re.compile(rb"\s*(\d+)\s*")
    for _ in range(n):
        k = number.match(raw, pos)
        if k is None:
            raise ValueError("%s: entry %d has no length" % (path, len(out)))
        length, pos = int(k.group(1)), k.end()
        if length:
            if raw[pos:pos + 1] != b"(":
                raise ValueError("%s: expected '(' in entry %d"
                                 % (path, len(out)))
            out.append(list(struct.unpack_from(order + code * length, raw,
                                               pos + 1)))
            pos += 1 + size * length + 1
        else:
            out.append([])
    return out


def _read_binary_compact_label_lists(path, raw, head, layout):
    """A binary labelFieldCompactField (what OpenFOAM's utilities write for
    a labelFieldField in binary): the offsets list, then the values list"""
    order, code, size = layout.order, layout.label, layout.label_size
    lists, pos = [], len(head)
    count = re.compile(rb"\s*(?://[^\n]*\n\s*)*(\d+)\s*")
    for _ in range(2):
        m = count.match(raw, pos)
        if m is None:
            raise ValueError("%s: expected a list's size" % path)
        n, pos = int(m.group(1)), m.end()
        if n and raw[pos:pos + 1] == b"(":
            lists.append(list(struct.unpack_from(order + code * n, raw,
                                                 pos + 1)))
            pos += 1 + size * n + 1
        else:
            lists.append([])
    offsets, values = lists
    return [values[offsets[k]:offsets[k + 1]]
            for k in range(len(offsets) - 1)]


def _read_binary_cloud(path, raw, head, layout):
    """A binary positions or coordinates file of a cloud, as OpenFOAM's
    particle writes it: per particle '(' and its packed record ')':
    positions (x y z) and the cell; coordinates (a b c d) and the cell, tet
    face and tet point. Returns the points, [x, y, z] or [a, b, c, d]"""
    obj = re.search(r"object\s+(\w+);", head).group(1)
    ns, nl = (4, 3) if obj == "coordinates" else (3, 1)
    record = layout.order + layout.scalar * ns + layout.label * nl
    size = ns * layout.scalar_size + nl * layout.label_size
    m = re.compile(rb"\n\s*(\d+)\s*\(").search(raw, len(head))
    if m is None:
        raise ValueError("no list in " + path)
    n, pos, out = int(m.group(1)), m.end(), []
    for _ in range(n):
        pos = raw.index(b"(", pos) + 1
        out.append(list(struct.unpack_from(record, raw, pos)[:ns]))
        pos += size + 1
    return out


def read_list(path):
    """A list file: scalars, labels, or vectors/tensors as lists, ascii or
    binary. Handles the uniform form N{value}. Positions lines
    '(x y z) celli' give [x, y, z]; a labelFieldField (a list of labels
    per particle, e.g. brokenBonds) lists of numbers."""
    raw = open(path, "rb").read()
    if re.search(rb"format\s+binary\s*;", raw[:2000]):
        return _read_binary(path, raw)
    text = _body(raw.decode())
    text = re.sub(r"//.*", "", text)
    m = re.match(r"\s*(\d+)\s*\{\s*(\([^()]*\)|" + _NUMBER + r")\s*\}", text)
    if m:      # uniform list N{value}
        v = m.group(2)
        if v.startswith("("):
            return [[float(c) for c in v[1:-1].split()]] * int(m.group(1))
        return [float(v)] * int(m.group(1))
    m = re.search(r"(\d+)\s*\(", text)
    if not m:
        raise ValueError("no list in " + path)
    n = int(m.group(1))
    rest = text[m.end():]
    vectors = re.findall(r"\(([^()]*)\)", rest)
    if vectors:
        out = [[float(v) for v in vec.split()] for vec in vectors[:n]]
    else:
        out = [float(v) for v in re.findall(_NUMBER, rest)[:n]]
    if len(out) != n:
        raise ValueError("%s: %d entries, expected %d" % (path, len(out), n))
    return out


def read_cloud(case, time, body):
    """Every file of a cloud, by name."""
    d = os.path.join(case, time, "lagrangian", body)
    names = sorted(os.listdir(d))
    out = {}
    for name in names:
        # OpenFOAM's barycentric coordinates are not read; positions are
        # the exact 'position' field when there is one (see read_positions)
        if name == "coordinates" or (name == "positions"
                                     and "position" in names):
            continue
        out[name] = read_list(os.path.join(d, name))
    if "position" in out:
        out["positions"] = out.pop("position")
    if "id" in out:
        out["id"] = [int(v) for v in out["id"]]
    return out


def read_field(case, time, body, name):
    """One field of a cloud (read_list of its file)."""
    return read_list(os.path.join(case, time, "lagrangian", body, name))


def read_positions(case, time, body):
    """Positions of a cloud ([x, y, z] each): the exact 'position' field
    when written (it is what decomposePar and reconstructPar carry
    unchanged), otherwise the positions file."""
    if os.path.exists(os.path.join(case, time, "lagrangian", body,
                                   "position")):
        return read_field(case, time, body, "position")
    return read_field(case, time, body, "positions")


def speed_history(case, body):
    """(time, RMS speed, largest speed) of a body at every written time
    after the first, in the plane"""
    out = []
    for value, name in times(case)[1:]:
        U = read_field(case, name, body, "U")
        speeds = [math.hypot(u[0], u[1]) for u in U]
        rms = math.sqrt(sum(s * s for s in speeds) / len(speeds))
        out.append((value, rms, max(speeds)))
    return out
