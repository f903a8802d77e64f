#!/usr/bin/env python3
"""Move every point of an ASCII polyMesh by a random amount (uniform in
[-a, a] per component, seed 2026), in place: faces become warped and
cells non-convex, which the locator must handle (wall distances to
warped wall faces included).

usage: perturbPoints.py <case> <a [m]>
"""
import random
import re
import sys

case, amplitude = sys.argv[1], float(sys.argv[2])
path = case + "/constant/polyMesh/points"
with open(path) as f:
    text = f.read()
rng = random.Random(2026)
point = re.compile(r"^\(([-+0-9.eE]+) ([-+0-9.eE]+) ([-+0-9.eE]+)\)$", re.M)


def moved(match):
    return "(" + " ".join(
        repr(float(x) + rng.uniform(-amplitude, amplitude))
        for x in match.groups()) + ")"


text, n = point.subn(moved, text)
if n == 0:
    sys.exit(path + ": no points found (ASCII format expected)")
with open(path, "w") as f:
    f.write(text)
print(f"{path}: {n} points moved by up to {amplitude} m per component")
