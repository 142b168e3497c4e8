"""OpenFOAM dictionaries (a case's constant/ and system/ dictionaries, the
solvers' postProcessing/runCost files) read through foamDictionary, which
expands #include, $variables and #eval as the solvers do. Its output
(foamDictionary -expand) is read here into Python dicts: no script reads a
dictionary file by pattern.

    from foamDict import dictionary_entry, read_dictionary
    dictionary_entry(case, "bodies/beam/constitutiveLaw/E")
    dictionary_entry(case, "endTime", "system/controlDict")
    props = read_dictionary(case, "constant/particleProperties")
    lookup(props, "bodies/water/kernel/horizon", "3")
    put_entry(case, "constant/particleProperties", "monitors/energy",
              "{ type energy; }")

Values are as foamDictionary writes them: a single word or number as a
string ("2", "2.1e+11", "taylor"), more than one as a list, a (...) list as
a list, a sub-dictionary as a dict. Numbers have foamDictionary's 6
significant digits.
"""
import os
import subprocess

REQUIRED = object()


def read_dictionary(case, dictionary):
    """The dictionary <case>/<dictionary> (a path relative to the case), its
    FoamFile header left out. Read from the case: foamDictionary takes
    $FOAM_CASE (the tutorials' #includeIfPresent
    "$FOAM_CASE/system/runParameters") from its working directory, so from
    elsewhere it would read the defaults"""
    run = subprocess.run(
        ["foamDictionary", "-expand", dictionary], cwd=case,
        env=dict(os.environ, PWD=os.path.abspath(case)),
        capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError("foamDictionary -expand %s in %s failed:\n%s"
                           % (dictionary, case, run.stdout + run.stderr))
    tokens = _tokens(run.stdout)
    entries, _ = _entries(tokens, 0, None)
    entries.pop("FoamFile", None)
    return entries


def put_entry(case, dictionary, entry, value):
    """Add or set the '/'-scoped entry of a case dictionary (foamDictionary
    -add, then -set, which also replaces a sub-dictionary by a value); the
    sub-dictionaries on its path that the dictionary lacks are added empty
    first. Raises RuntimeError with foamDictionary's output on failure"""
    def run(key, action, text):
        p = subprocess.run(
            ["foamDictionary", dictionary, "-entry", key, action, text],
            cwd=case, env=dict(os.environ, PWD=os.path.abspath(case)),
            capture_output=True, text=True)
        if p.returncode != 0:
            raise RuntimeError("foamDictionary %s -entry %s %s in %s"
                               " failed:\n%s" % (dictionary, key, action,
                                                  case, p.stdout + p.stderr))
    parts = entry.split("/")
    if len(parts) > 1:
        entries = read_dictionary(case, dictionary)
        for k in range(1, len(parts)):
            key = "/".join(parts[:k])
            if lookup(entries, key, None) is None:
                run(key, "-add", "{}")
    for action in ("-add", "-set"):
        run(entry, action, str(value))


def lookup(entries, key, default=REQUIRED):
    """The entry of a '/'-scoped key (bodies/beam/density) in entries of
    read_dictionary; default when it is absent (KeyError without one)"""
    value = entries
    for part in key.split("/"):
        if not isinstance(value, dict) or part not in value:
            if default is REQUIRED:
                raise KeyError(key)
            return default
        value = value[part]
    return value


def dictionary_entry(case, key, dictionary="constant/particleProperties",
                     default=REQUIRED):
    """One entry of a case dictionary (see lookup); without a default a
    missing entry is an error naming the key and the file"""
    try:
        return lookup(read_dictionary(case, dictionary), key, default)
    except KeyError:
        raise KeyError("no entry %s in %s"
                       % (key, os.path.join(case, dictionary)))


def _tokens(text):
    """Words, quoted strings and the punctuation { } ( ) [ ] ; of a
    dictionary's text, comments left out. A word keeps balanced parentheses
    it contains (div(phi,U))."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if c.isspace():
            i += 1
        elif text.startswith("//", i):
            end = text.find("\n", i)
            i = n if end < 0 else end
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            i = n if end < 0 else end + 2
        elif c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            out.append(text[i + 1:j])
            i = j + 1
        elif c in "{}()[];":
            out.append(c)
            i += 1
        else:
            j, depth = i, 0
            while j < n:
                d = text[j]
                if d == "(":
                    depth += 1
                elif d == ")":
                    if depth == 0:
                        break
                    depth -= 1
                elif depth == 0 and (d.isspace() or d in '{};"[]'):
                    break
                j += 1
            out.append(text[i:j])
            i = j
    return out


def _entries(tokens, i, close):
    """The entries from tokens[i] to the token close (None: the end)"""
    entries = {}
    while i < len(tokens) and tokens[i] != close:
        key = tokens[i]
        i += 1
        if i < len(tokens) and tokens[i] == "{":
            entries[key], i = _entries(tokens, i + 1, "}")
            i += 1
            continue
        values = []
        while i < len(tokens) and tokens[i] != ";":
            value, i = _value(tokens, i)
            values.append(value)
        i += 1
        entries[key] = values[0] if len(values) == 1 else values
    return entries, i


def _value(tokens, i):
    """One value from tokens[i]: a word, a list or a dictionary"""
    t = tokens[i]
    if t == "(" or t == "[":
        close = ")" if t == "(" else "]"
        items, i = [], i + 1
        while tokens[i] != close:
            item, i = _value(tokens, i)
            items.append(item)
        return items, i + 1
    if t == "{":
        entries, i = _entries(tokens, i + 1, "}")
        return entries, i + 1
    return t, i + 1
