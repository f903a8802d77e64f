#!/usr/bin/env python3
"""Serial and 2-rank runs of the slot-coater tutorial at test size
(runSlotCoaterRun.sh) agree: both start from the same initial fill
(DEM/fill.data, packed once, serially, by the tutorial's Allrun), so they
must insert, hold and remove the same numbers of particles (exactly), and
their mean particle velocity must agree within 1 % of its magnitude, per
component (measured: about 1e-5; the feed places the same particles on
any number of ranks).

usage: compareBookkeeping.py SERIALCASE PARALLELCASE
"""
import math
import os
import sys

TOL = 0.01


def summary(case):
    values = open(os.path.join(case, "bookkeeping.txt")).read().split()
    return [int(v) for v in values[:3]], [float(v) for v in values[3:]]


def main():
    (pS, iS, rS), vS = summary(sys.argv[1])
    (pP, iP, rP), vP = summary(sys.argv[2])
    print("serial:   present %d inserted %d removed %d, mean v (%.6g %.6g %.6g) m/s"
          % ((pS, iS, rS) + tuple(vS)))
    print("2 ranks:  present %d inserted %d removed %d, mean v (%.6g %.6g %.6g) m/s"
          % ((pP, iP, rP) + tuple(vP)))
    ok = (iS, pS, rS) == (iP, pP, rP)
    print("inserted, present, removed equal: %s" % ("yes" if ok else "NO"))
    speed = math.sqrt(sum(c*c for c in vS))
    for k, name in enumerate("xyz"):
        err = abs(vP[k] - vS[k])/speed
        print("mean v_%s differs by %.3g %% of |v| (tolerance %g %%)" % (name, 100*err, 100*TOL))
        ok = ok and err <= TOL
    print("serial vs parallel: %s" % ("passed" if ok else "FAILED"))
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
