#!/usr/bin/env python3
"""Check DEM wall STL files that together cover a box's whole boundary.

References are the box's exact values (corners from boxParameters, times
the DEM length scale s):
  - total triangle area   = 2 (Lx Ly + Ly Lz + Lz Lx) s^2
  - enclosed volume by the divergence theorem,
        V = sum over triangles of a . (b x c) / 6,
    = Lx Ly Lz s^3; positive only if every triangle winds outwards
  - every facet normal is the unit normal of its winding and equals the
    outward normal of the box side the triangle lies on (out of the fluid)
  - optionally, the number of triangles (2 per quadrilateral face);
  - optionally, refined triangles (writeDEMWalls -maxEdge): no edge longer
    than MAXEDGE, and in each file a longest edge above MAXEDGE/2 (no
    more refinement than needed).
Relative tolerance 1e-7 (the files carry 10 significant digits).

usage: checkStlBox.py STLDIR BOXPARAMETERS SCALE [NTRIANGLES [MAXEDGE]]
       (NTRIANGLES -1: any number)
"""

import glob
import os
import sys

# Read the shared reader from the source tree without writing a bytecode
# cache into it
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "fluidCommon"))
import foamFields  # noqa: E402

TOLERANCE = 1e-7


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def norm(a):
    return dot(a, a) ** 0.5


def read_stl(path):
    """List of (stated normal, (a, b, c)) from an ASCII STL file."""
    facets = []
    normal, verts = None, []
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "facet":
                normal = tuple(float(x) for x in words[2:5])
                verts = []
            elif words[0] == "vertex":
                verts.append(tuple(float(x) for x in words[1:4]))
            elif words[0] == "endfacet":
                if len(verts) != 3:
                    raise RuntimeError("%s: facet with %d vertices" % (path, len(verts)))
                facets.append((normal, tuple(verts)))
    return facets


def main():
    stl_dir, params, scale = sys.argv[1], sys.argv[2], float(sys.argv[3])
    n_expected = int(sys.argv[4]) if len(sys.argv) > 4 else -1
    max_edge = float(sys.argv[5]) if len(sys.argv) > 5 else None

    box = foamFields.read_parameters(params)
    lo = tuple(scale * box[k] for k in ("x0", "y0", "z0"))
    hi = tuple(scale * box[k] for k in ("x1", "y1", "z1"))
    L = sub(hi, lo)
    area_exact = 2.0 * (L[0] * L[1] + L[1] * L[2] + L[2] * L[0])
    volume_exact = L[0] * L[1] * L[2]
    length = max(L)

    files = sorted(glob.glob(os.path.join(stl_dir, "*.stl")))
    facets = []
    longest_per_file = []
    for path in files:
        these = read_stl(path)
        facets.extend(these)
        longest_per_file.append(max(
            norm(sub(t[(e + 1) % 3], t[e])) for _, t in these for e in range(3)))

    area, volume, bad_normals, bad_sides = 0.0, 0.0, 0, 0
    for stated, (a, b, c) in facets:
        twice = cross(sub(b, a), sub(c, a))
        area += 0.5 * norm(twice)
        volume += dot(a, cross(b, c)) / 6.0
        unit = tuple(x / norm(twice) for x in twice)
        if norm(sub(unit, stated)) > 1e-6:
            bad_normals += 1
        # The box side this triangle lies on, and its outward normal
        outward = None
        for i in range(3):
            for bound, sign in ((lo[i], -1.0), (hi[i], 1.0)):
                if all(abs(p[i] - bound) < TOLERANCE * length for p in (a, b, c)):
                    outward = tuple(sign if j == i else 0.0 for j in range(3))
        if outward is None or dot(unit, outward) < 1.0 - 1e-9:
            bad_sides += 1

    area_err = abs(area - area_exact) / area_exact
    volume_err = abs(volume - volume_exact) / volume_exact
    print("%d files, %d triangles%s" % (len(files), len(facets),
          "" if n_expected < 0 else " (expected %d)" % n_expected))
    print("area   %.10g, exact %.10g, relative error %.2e" % (area, area_exact, area_err))
    print("volume %.10g, exact %.10g, relative error %.2e" % (volume, volume_exact, volume_err))
    print("facets whose stated normal differs from the winding: %d" % bad_normals)
    print("facets not on a box side or not facing out of the fluid: %d" % bad_sides)

    refined_ok = True
    if max_edge is not None:
        longest = max(longest_per_file)
        shortest_longest = min(longest_per_file)
        refined_ok = (longest <= max_edge * (1 + TOLERANCE)
                      and shortest_longest > 0.5 * max_edge)
        print("longest edge %.10g (at most %g), shortest longest edge of a file"
              " %.10g (above %g)" % (longest, max_edge, shortest_longest, 0.5 * max_edge))

    ok = (refined_ok and facets and area_err < TOLERANCE and volume_err < TOLERANCE
          and bad_normals == 0 and bad_sides == 0
          and (n_expected < 0 or n_expected == len(facets)))
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
