#!/usr/bin/env python3
"""The slot-coater tutorial's initial fill and feed in its spanwise-periodic
DEM box (issue 12, points 0 and 3), at test size (the serial fixture of
case.slotCoater):

  - the DEM box of the run is periodic in z (boundary f f p);
  - no two particles closer than fillMinimumGap, their periodic images
    across the z faces included (every pair, brute force: an independent
    check of what the solver's start-up reports);
  - no particle closer than fillMinimumGap to a wall of the gap or of the
    slot (substrate, lip undersides, slot walls, upstream wall);
  - the periodic face is no wall for the fill: the particle centres within
    r + fillMinimumGap/2 of z = 0 or z = span (a reflecting or excluding
    face leaves that band empty) number what a uniform fill puts there,
    within 4 binomial standard deviations;
  - the feed's particles (the coupling's feed, minimumGap fillMinimumGap):
    the solver's log reports for each insertion their smallest gap to any
    particle ("Inserted particles: smallest gap", the start-up overlap
    check run on them), at least fillMinimumGap, or none closer than a
    radius.

usage: checkSlotCoaterFill.py case"""
import math
import os
import re
import sys

# The slot-coater tests' reader of the DEM variables Allrun writes
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "slotCoater"))
from checkBookkeeping import liggghtsVariables  # noqa: E402


def dataAtoms(path):
    """Box and (diameter, x, y, z) of each atom of a LIGGGHTS data file
    (atom_style sphere: id type diameter density x y z)."""
    lines = open(path).read().splitlines()
    box = {}
    for line in lines[:20]:
        m = re.match(r"\s*(\S+)\s+(\S+)\s+([xyz])lo\s+[xyz]hi", line)
        if m:
            box[m.group(3)] = (float(m.group(1)), float(m.group(2)))
    start = next(i for i, l in enumerate(lines) if l.startswith("Atoms"))
    atoms = []
    for line in lines[start + 2:]:
        if not line.strip():
            break
        v = line.split()
        atoms.append((float(v[2]), float(v[4]), float(v[5]), float(v[6])))
    return box, atoms


def main():
    case = sys.argv[1]
    ok = True

    def check(good, text):
        nonlocal ok
        ok = ok and good
        print("%-72s %s" % (text, "ok" if good else "FAILED"))

    log = open(os.path.join(case, "log.liggghts")).read()
    check(re.search(r"^boundary f f p\s*$", log, re.M) is not None,
          "the DEM box of the run is periodic in z (log.liggghts)")

    p = liggghtsVariables(os.path.join(case, "DEM", "slotCoater.liggghts"))
    box, atoms = dataAtoms(os.path.join(case, "DEM", "fill.data"))
    span = box["z"][1] - box["z"][0]
    check(abs(span - p["span"]) <= 1e-9*p["span"],
          "box period in z %.6g um = span %.6g um" % (span, p["span"]))
    gapMin = p["fillMinimumGap"]
    tol = 1e-9*gapMin      # round-off of LIGGGHTS' own check (um)

    # Every pair, with the periodic image in z that is closest
    smallest = math.inf
    n = len(atoms)
    for i in range(n):
        di, xi, yi, zi = atoms[i]
        for j in range(i + 1, n):
            dj, xj, yj, zj = atoms[j]
            dz = abs(zi - zj)
            dz = min(dz, span - dz)
            dx = xi - xj
            dy = yi - yj
            d2 = dx*dx + dy*dy + dz*dz
            reach = 0.5*(di + dj) + gapMin
            if d2 < (reach + 1.0)**2:
                smallest = min(smallest, math.sqrt(d2) - 0.5*(di + dj))
    check(n > 1000 and smallest >= gapMin - tol,
          "%d particles: smallest gap %.6g um >= fillMinimumGap %.6g um"
          % (n, smallest, gapMin))

    # Walls: each particle is in the gap (below the lips) or in the slot
    wallGap = math.inf
    for d, x, y, z in atoms:
        r = 0.5*d
        gaps = [y - r, x - p["xLo"] - r]                  # substrate, upstream wall
        if y > p["gap"]:
            gaps += [x - r, p["slotWidth"] - x - r]       # slot walls
        elif x < 0 or x > p["slotWidth"]:
            gaps.append(p["gap"] - y - r)                  # lip undersides
        else:
            # Below the slot: the nearer lip corner
            for cx in (0.0, p["slotWidth"]):
                if y + r > p["gap"] - gapMin:
                    gaps.append(math.hypot(x - cx, y - p["gap"]) - r)
        wallGap = min(wallGap, min(gaps))
    check(wallGap >= gapMin - tol,
          "smallest particle-wall gap %.6g um >= fillMinimumGap" % wallGap)

    # The band at the periodic face: a uniform fill puts the fraction
    # 2 w/span of the centres there (w = r + gap/2, the grown radius)
    w = 0.5*atoms[0][0] + 0.5*gapMin
    inBand = sum(1 for a in atoms
                 if a[3] - box["z"][0] < w or box["z"][1] - a[3] < w)
    q = 2*w/span
    expected = q*n
    sigma = math.sqrt(n*q*(1 - q))
    check(abs(inBand - expected) <= 4*sigma,
          "centres within %.3g um of the periodic face: %d, uniform %.0f +- %.0f"
          % (w, inBand, expected, sigma))

    solverLog = open(os.path.join(case, "log.colloidDEMFoam")).read()
    reports = re.findall(r"^Inserted particles: (.*)$", solverLog, re.M)
    gaps = [float(m.group(1))*1e6 for m in
            (re.match(r"smallest gap (\S+) m", r) for r in reports) if m]
    far = sum(1 for r in reports if r.startswith("no two closer than"))
    # The solver measures them after the coupling step they were placed
    # in (deltaT of system/controlDict): a pair may have closed by the
    # largest shear of the flow, 4 U/h (the substrate under the upstream
    # lip), times their centre distance, times that step
    deltaT = float(re.search(r"^deltaT\s+(\S+);",
                             open(os.path.join(case, "system", "controlDict")).read(),
                             re.M).group(1))*1e6     # us
    closing = 4*p["webSpeed"]/p["gap"]*(atoms[0][0] + gapMin)*deltaT
    check(bool(reports) and len(gaps) + far == len(reports)
          and min(gaps + [gapMin]) >= gapMin - tol - closing,
          "feed: %d insertion(s), smallest gap %.6g um >= fillMinimumGap - %.2g um"
          " (shear in a coupling step)" % (len(reports), min(gaps) if gaps else -1.0, closing))

    if not ok:
        raise SystemExit("FAIL")
    print("PASS")


if __name__ == "__main__":
    main()
