#!/usr/bin/env python3
"""Check the steady flow of the slot-coater tutorial against closed forms.

1. Mass: the volume flux out of the outlet equals the feed through the
   inlet, and the feed equals the set one, q*span with
   q = webSpeed*wetThickness (relative tolerance 1e-6).
2. Profile under the downstream lip.  Away from the slot corner the flow
   is plane Couette-Poiseuille flow between the moving substrate (y = 0,
   velocity U) and the resting lip (y = h); with eta = y/h,
       u(eta) = U (1 - eta) + A eta (1 - eta).
   a) A from the feed (independent of the solution): the flux per unit
      span is q, so A = 6 (q/h - U/2);
   b) A from the pressure gradient G = dp/dx found under the lip (least
      squares over the downstream half of the lip): A = -G h^2 / (2 nu).
   The computed profile in the outlet column must be within TOL (default
   1 %) of U for both; the transverse velocity must be below TOL U.

usage: checkSlotCoaterFlow.py CASE [TOL]
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
    tol = float(sys.argv[2]) if len(sys.argv) > 2 else 0.01

    par = foamFields.read_parameters(os.path.join(case, "system", "slotCoaterParameters"))
    h, w, Ld = par["gap"], par["slotWidth"], par["downstreamLip"]
    U, t, nu, span = par["webSpeed"], par["wetThickness"], par["nu"], par["span"]
    q = U * t

    time = foamFields.latest_time(case)
    field = lambda name: os.path.join(case, time, name)  # noqa: E731
    C = foamFields.read_internal_field(field("C"))
    Uc = foamFields.read_internal_field(field("U"))
    p = foamFields.read_internal_field(field("p"))
    q_in, q_out = (
        sum(foamFields.read_patch_value(field("phi"), patch,
                                        foamFields.patch_size(case, patch)))
        for patch in ("inlet", "outlet"))

    ok = True
    mass_err = abs(q_in + q_out) / abs(q_in)
    feed_err = abs(-q_in - q * span) / (q * span)
    print("time %s: inlet flux %.6e m^3/s, outlet flux %.6e m^3/s, set feed %.6e m^3/s"
          % (time, q_in, q_out, q * span))
    print("mass imbalance |Qin + Qout|/Qin = %.2e, feed error = %.2e (tolerance 1e-6)"
          % (mass_err, feed_err))
    ok = ok and mass_err < 1e-6 and feed_err < 1e-6

    # Pressure gradient over the downstream half of the lip
    gap_cells = [i for i, c in enumerate(C) if c[1] < h]
    pts = [(C[i][0], p[i]) for i in gap_cells if C[i][0] > w + 0.5 * Ld]
    xm = sum(x for x, _ in pts) / len(pts)
    pm = sum(v for _, v in pts) / len(pts)
    G = sum((x - xm) * (v - pm) for x, v in pts) / sum((x - xm)**2 for x, _ in pts)

    A_feed = 6.0 * (q / h - U / 2.0)
    A_grad = -G * h**2 / (2.0 * nu)
    G_feed = -2.0 * nu * A_feed / h**2
    print("pressure gradient under the downstream lip %.5g m/s^2 (kinematic);"
          " from the feed %.5g (%.2f %%)" % (G, G_feed, 100 * (G - G_feed) / G_feed))

    # Outlet column: the cells of the gap with the largest x
    x_last = max(C[i][0] for i in gap_cells)
    column = sorted((C[i][1], Uc[i][0], Uc[i][1]) for i in gap_cells
                    if abs(C[i][0] - x_last) < 1e-3 * h)
    cross = max(abs(v) for _, _, v in column) / U
    print("outlet column x = %.4g m, %d cells: max |v|/U = %.3e (tolerance %.1e)"
          % (x_last, len(column), cross, tol))
    ok = ok and cross < tol

    for label, A in (("feed", A_feed), ("pressure gradient", A_grad)):
        def exact(y):
            eta = y / h
            return U * (1.0 - eta) + A * eta * (1.0 - eta)
        err = max(abs(u - exact(y)) for y, u, _ in column) / U
        print("  Couette-Poiseuille profile from the %s: max |u - u_CP|/U = %.3e"
              " (tolerance %.1e)" % (label, err, tol))
        ok = ok and err < tol

    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
