#!/usr/bin/env python3
"""Compare a computed plane-gap velocity profile with the closed form.

Steady, laminar, fully developed flow of a Newtonian liquid between a fixed
wall (y = 0) and a wall sliding at Uwall (y = H), driven by the kinematic
pressure drop dp over the length L (G = dp/L):

    u(y) = Uwall*y/H + G/(2 nu) * y*(H - y)

(Couette part + Poiseuille part; Uwall = 0 is plane Poiseuille flow.)
The error measure is max over cells |u_cell - u(y_cell)| / max|u|, which
must stay below the tolerance (default 1 %).  The transverse velocity must
vanish to the same tolerance.

usage: checkGapProfile.py CASE [TOLERANCE]
"""

import os
import sys

# Read the shared reader from the source tree without writing a bytecode
# cache into it
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "fluidCommon"))
import foamFields  # noqa: E402


def main():
    case = sys.argv[1]
    tolerance = float(sys.argv[2]) if len(sys.argv) > 2 else 0.01

    par = foamFields.read_parameters(os.path.join(case, "system", "gapParameters"))
    H, L, nu, Uwall, dp = par["H"], par["L"], par["nu"], par["Uwall"], par["dp"]
    G = dp / L

    time = foamFields.latest_time(case)
    U = foamFields.read_internal_field(os.path.join(case, time, "U"))
    C = foamFields.read_internal_field(os.path.join(case, time, "C"))
    if len(U) != len(C) or not U:
        print("FAIL: U (%d) and C (%d) do not match" % (len(U), len(C)))
        return 1

    def exact(y):
        return Uwall * y / H + G / (2.0 * nu) * y * (H - y)

    uScale = max(abs(exact(c[1])) for c in C)
    uScale = max(uScale, abs(Uwall))
    errAxial = max(abs(u[0] - exact(c[1])) for u, c in zip(U, C)) / uScale
    errCross = max(max(abs(u[1]), abs(u[2])) for u in U) / uScale

    print("time %s, %d cells, H = %g m, Uwall = %g m/s, G = %g m/s^2"
          % (time, len(C), H, Uwall, G))
    print("max |u - u_exact| / max|u| = %.3e (tolerance %.1e)" % (errAxial, tolerance))
    print("max |v|, |w| / max|u|      = %.3e (tolerance %.1e)" % (errCross, tolerance))
    if errAxial > tolerance or errCross > tolerance:
        print("FAIL")
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
