#!/usr/bin/env python3
"""The settling runs on different meshes of the same channel (hex, tet,
polyhedral) must give the same particle velocity: each component of every
run within 1 % of the first (hex) run's (the y component relative to
itself, x and z relative to |v|).

usage: compareRuns.py hexCase otherCase...
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', '..', 'src', 'python'))  # particleCloud
import particleCloud  # noqa: E402

TOL = 0.01


def velocity(case):
    return particleCloud.read(particleCloud.latest(case))["velocity"][0]


def main():
    ref = velocity(sys.argv[1])
    speed = math.sqrt(sum(c*c for c in ref))
    print("%-40s v = (%.8g %.8g %.8g) m/s" % ((sys.argv[1],) + tuple(ref)))
    ok = True
    for case in sys.argv[2:]:
        v = velocity(case)
        errX = abs(v[0] - ref[0])/speed
        errY = abs(v[1] - ref[1])/abs(ref[1])
        errZ = abs(v[2] - ref[2])/speed
        print("%-40s v = (%.8g %.8g %.8g) m/s" % ((case,) + tuple(v)))
        print("    differences: x %.3g %% of |v|, y %.3g %%, z %.3g %% of |v|"
              % (100*errX, 100*errY, 100*errZ))
        ok = ok and max(errX, errY, errZ) < TOL
    print("PASS" if ok else "FAIL (tolerance 1 %)")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
