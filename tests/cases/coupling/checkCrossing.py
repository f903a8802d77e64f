#!/usr/bin/env python3
"""Checks of the 2-rank run against its serial twin (see
runParallelTest.sh): the particle crossed x = 55 um, was never outside the
fluid, needed at most 3 global searches, and ended with the serial run's
velocity within 1e-6 relative.

usage: checkCrossing.py serialCase parallelCase
"""
import math
import re
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', '..', 'src', 'python'))  # particleCloud
import particleCloud  # noqa: E402

X_CROSSED = 55e-6
MAX_GLOBAL_SEARCHES = 3
TOL = 1e-6


def main():
    serial, parallel = sys.argv[1], sys.argv[2]
    ok = True

    log = open(parallel + "/log.colloidDEMFoam").read()
    steps = re.findall(r"Coupling: (\d+) particles, (\d+) outside the fluid, (\d+) global searches", log)
    if not steps:
        sys.exit("checkCrossing: no coupling lines in the parallel log")
    outside = sum(int(s[1]) for s in steps)
    searches = sum(int(s[2]) for s in steps)
    print("coupling steps %d, particle-steps outside the fluid %d, global searches %d"
          % (len(steps), outside, searches))
    if outside != 0 or any(int(s[0]) != 1 for s in steps):
        print("FAIL: particle lost or outside the fluid"); ok = False
    if searches > MAX_GLOBAL_SEARCHES:
        print("FAIL: more than %d global searches" % MAX_GLOBAL_SEARCHES); ok = False

    dp = particleCloud.read(particleCloud.latest(parallel))
    ds = particleCloud.read(particleCloud.latest(serial))
    x = dp["position"][0][0]
    print("final x = %.6g m (processor boundary at 5e-05 m)" % x)
    if x < X_CROSSED:
        print("FAIL: particle did not cross the processor boundary"); ok = False

    vp, vs = dp["velocity"][0], ds["velocity"][0]
    speed = math.sqrt(sum(c*c for c in vs))
    diff = math.sqrt(sum((a - b)**2 for a, b in zip(vp, vs)))/speed
    print("parallel v = (%.10g %.10g %.10g)" % tuple(vp))
    print("serial   v = (%.10g %.10g %.10g)" % tuple(vs))
    print("relative difference %.3g" % diff)
    if diff > TOL:
        print("FAIL: serial and parallel velocities differ by more than %g" % TOL); ok = False

    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
