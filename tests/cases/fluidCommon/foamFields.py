"""Read OpenFOAM ASCII field files and simple 'key value;' parameter files.

Plain Python (standard library only) so that the case checkers need nothing
beyond python3.  Only what the checkers use: the internal field of a
volScalarField or volVectorField (uniform or nonuniform), one patch's
'value' entry, and flat dictionaries of numeric parameters.
"""

import os
import re


def read_parameters(path):
    """Return {key: float} for every 'key number;' line of a flat dictionary."""
    values = {}
    pattern = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_]*)\s+([-+0-9.eE]+)\s*;")
    with open(path) as f:
        for line in f:
            match = pattern.match(line)
            if match:
                values[match.group(1)] = float(match.group(2))
    return values


def latest_time(case):
    """Name of the latest numeric time folder of a case (not '0')."""
    times = []
    for name in os.listdir(case):
        try:
            times.append((float(name), name))
        except ValueError:
            continue
    times.sort()
    if not times or times[-1][0] == 0:
        raise RuntimeError("no solution time folder in " + case)
    return times[-1][1]


def _parse_values(text, start):
    """Parse a uniform or nonuniform list starting at text[start:]."""
    rest = text[start:].lstrip()
    if rest.startswith("uniform"):
        body = rest[len("uniform"):].lstrip()
        if body.startswith("("):
            return [tuple(float(x) for x in body[1:body.index(")")].split())]
        return [float(body[:body.index(";")])]
    if not rest.startswith("nonuniform"):
        raise RuntimeError("cannot parse field values: " + rest[:40])
    match = re.match(r"nonuniform\s+List<(\w+)>\s*(\d+)\s*\(", rest)
    if not match:
        raise RuntimeError("cannot parse list header: " + rest[:60])
    kind, count = match.group(1), int(match.group(2))
    body = rest[match.end():]
    if kind == "scalar":
        tokens = body[:body.index(")")].split()
        if len(tokens) != count:
            raise RuntimeError("expected %d scalars, found %d" % (count, len(tokens)))
        return [float(t) for t in tokens]
    vectors = re.findall(r"\(\s*([^()]+?)\s*\)", body[:body.index("\n)")])
    if len(vectors) != count:
        raise RuntimeError("expected %d vectors, found %d" % (count, len(vectors)))
    return [tuple(float(x) for x in v.split()) for v in vectors]


def read_internal_field(path):
    """Values of the internalField: a list of floats or of 3-tuples."""
    with open(path) as f:
        text = f.read()
    start = text.index("internalField") + len("internalField")
    return _parse_values(text, start)


def patch_size(case, patch):
    """Number of faces of a patch, from constant/polyMesh/boundary."""
    with open(os.path.join(case, "constant", "polyMesh", "boundary")) as f:
        text = f.read()
    match = re.compile(r"\n\s*" + re.escape(patch) + r"\s*\n\s*\{([^}]*)\}").search(text)
    if not match:
        raise RuntimeError("patch %s not in the mesh of %s" % (patch, case))
    return int(re.search(r"nFaces\s+(\d+)", match.group(1)).group(1))


def read_patch_value(path, patch, size=None):
    """The 'value' entry of one patch of a field file (list, as above);
    a uniform value is repeated size times when size is given."""
    with open(path) as f:
        text = f.read()
    boundary = text.index("boundaryField")
    match = re.compile(r"\n\s*" + re.escape(patch) + r"\s*\n\s*\{").search(text, boundary)
    if not match:
        raise RuntimeError("patch %s not found in %s" % (patch, path))
    end = text.index("}", match.end())
    value = re.compile(r"\bvalue\b").search(text, match.end(), end)
    if not value:
        raise RuntimeError("patch %s of %s has no value entry" % (patch, path))
    values = _parse_values(text, value.end())
    if size is not None and len(values) == 1:
        values = values*size
    return values
