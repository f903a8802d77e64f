#!/usr/bin/env python3
"""Serial and 2-rank runs of the slot-coater tutorial at test size
(runSlotCoaterRun.sh) agree: the same number of particles inserted (the
fill and the feed are fixed by the solids fraction), the particles present
at the end within 1 %, and the mean particle velocity within 1 % of its
magnitude, per component.  The random initial fill is drawn per rank, so
the runs are statistically, not bit-for-bit, the same: the few particles
removed near the outlet in 3 us (single digits) are printed, not compared.

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
    ok = iS == iP
    print("inserted equal: %s" % ("yes" if ok else "NO"))
    dPresent = abs(pP - pS)/pS
    print("present differ by %.3g %% (tolerance %g %%)" % (100*dPresent, 100*TOL))
    ok = ok and dPresent <= TOL
    speed = math.sqrt(sum(c*c for c in vS))
    for k, name in enumerate("xyz"):
        err = abs(vP[k] - vS[k])/speed
        print("mean v_%s differs by %.3g %% of |v| (tolerance %g %%)" % (name, 100*err, 100*TOL))
        ok = ok and err <= TOL
    print("serial vs parallel: %s" % ("passed" if ok else "FAILED"))
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
