#!/usr/bin/env python3
"""The hand-built arrangement of runArrangementTest.sh as LIGGGHTS
create_atoms lines (um), in the order of checkArrangement.GROUPS."""
import math

A = 1.002       # centre distance of a touching pair [um] (gap 2 nm)
LOOSE = 1.010   # of a bonded, not touching pair (gap 10 nm)

GROUPS = [
    ("chain5", [(48.0 + k*A, 50.0, 25.0) for k in range(5)]),
    ("ring6", [(20.0 + A*math.cos(k*math.pi/3), 70.0 + A*math.sin(k*math.pi/3), 25.0)
               for k in range(6)]),
    ("pair", [(20.0, 30.0, 25.0), (20.0 + A, 30.0, 25.0)]),
    ("pairAcrossRanks", [(50.0 - A/2, 30.0, 25.0), (50.0 + A/2, 30.0, 25.0)]),
    ("chain3AcrossPeriodic", [(70.0, 70.0, 50.0 - A/2), (70.0, 70.0, A/2),
                              (70.0, 70.0, 1.5*A)]),
    ("loosePair", [(30.0, 50.0, 10.0), (30.0 + LOOSE, 50.0, 10.0)]),
    ("isolated", [(80.0, 20.0, 25.0)]),
    ("onWall", [(60.0, 0.5025, 25.0)]),
]

if __name__ == "__main__":
    for _, centres in GROUPS:
        for x, y, z in centres:
            print("create_atoms 1 single %.12g %.12g %.12g units box" % (x, y, z))
