"""Permeability of the fixed bed's interior in the filtration case against
the packed-bed case's (same bed): k = mu q L/dp, dp the difference of the
cell-layer means of p between the layers centred at y = 0.625 and 1.625 mm,
q the filtrate flux through the outlet over the cross-section (filtration)
or the fixed inflow (packed bed).  Tolerance 3 %.

Also, in the filtration case (one cell across, steady): every cell's
superficial velocity eps U_y equals the outlet's -q within 1e-3 relative,
from the medium through the bed to the inlet (the cell velocities carry
their faces' fluxes; with linear face pressures they alternated in sign
from cell to cell at up to 280 times q).

usage: checkDarcy.py filtrationCase packedBedCase Us
"""
import glob
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', 'fluidCommon'))
import foamFields  # noqa: E402

MU, RHO = 1e-3, 1000.0
Y_LO, Y_HI = 0.625e-3, 1.625e-3
WIDTH = 1e-3
TOL = 0.03


def layer_pressure_drop(case):
    """rho (mean p at Y_LO - mean p at Y_HI) [Pa]."""
    t = foamFields.latest_time(case)
    p = foamFields.read_internal_field(os.path.join(case, t, 'p'))
    cy = [c[1] for c in
          foamFields.read_internal_field(os.path.join(case, t, 'C'))]

    def mean_at(y):
        near = [v for v, c in zip(p, cy) if abs(c - y) < 1e-9]
        if not near:
            raise SystemExit('checkDarcy.py: no cell layer at y = %g in %s'
                             % (y, case))
        return sum(near)/len(near)
    return RHO*abs(mean_at(Y_LO) - mean_at(Y_HI))


def main():
    filt, bed, us = sys.argv[1], sys.argv[2], float(sys.argv[3])
    rows = [[float(x) for x in line.split()] for line in open(glob.glob(
        os.path.join(filt, 'postProcessing', 'filtrate', '*',
                     'surfaceFieldValue.dat'))[0])
            if line.strip() and not line.startswith('#')]
    q = rows[-1][1]/WIDTH**2
    q_before = rows[-101][1]/WIDTH**2     # 1 ms earlier: steady?
    length = Y_HI - Y_LO
    k_filt = MU*q*length/layer_pressure_drop(filt)
    k_bed = MU*us*length/layer_pressure_drop(bed)
    err = k_filt/k_bed - 1
    print('filtration case: q %.6g m/s (1 ms before: %.6g), k %.6g m^2'
          % (q, q_before, k_filt))
    print('packed-bed case: Us %.6g m/s, k %.6g m^2' % (us, k_bed))
    print('permeability difference %+.2f %% (tolerance %.0f %%)'
          % (100*err, 100*TOL))
    t = foamFields.latest_time(filt)
    u = foamFields.read_internal_field(os.path.join(filt, t, 'U'))
    eps = foamFields.read_internal_field(os.path.join(filt, t, 'voidfraction'))
    cells = max(abs(e*v[1]/q + 1) for e, v in zip(eps, u))
    print('cell superficial velocities eps U_y against -q: at most %.2e'
          ' relative (tolerance 1e-3)' % cells)
    steady = abs(q/q_before - 1) < 1e-3
    if not steady:
        print('the filtration case is not steady yet')
    ok = abs(err) <= TOL and steady and cells <= 1e-3
    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
