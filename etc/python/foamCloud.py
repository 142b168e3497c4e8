"""Reading meshlessFoam's lagrangian clouds at full precision, for tutorial
validation scripts and tests (ParaView's reader converts to float32).

    import sys; sys.path.insert(0, os.path.join(MESHLESS_PROJECT, "etc/python"))
    from foamCloud import times, read_cloud

read_cloud(case, time, body) returns {"id": [...], "positions": [[x,y,z],..],
<field>: [...]} for the ascii files of <case>/<time>/lagrangian/<body>/.
"""
import os
import re

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


def read_list(path):
    """An ascii list file: scalars, labels, or vectors/tensors as lists.
    Handles the uniform form N{value}. Positions lines '(x y z) celli' give
    [x, y, z]."""
    text = _body(open(path).read())
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
    """Every ascii file of a cloud, by name."""
    d = os.path.join(case, time, "lagrangian", body)
    out = {}
    for name in sorted(os.listdir(d)):
        out[name] = read_list(os.path.join(d, name))
    if "id" in out:
        out["id"] = [int(v) for v in out["id"]]
    return out


def read_positions(case, time, body):
    """Positions of a cloud ([x, y, z] each): always ascii, whatever the
    case's writeFormat."""
    return read_list(os.path.join(case, time, "lagrangian", body, "positions"))
