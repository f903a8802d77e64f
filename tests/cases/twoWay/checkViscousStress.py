"""Terminal velocity of a neutrally buoyant sphere in plane Poiseuille flow
U_x(y) = 4 Umax y (H - y)/H^2 with Stokes drag and the viscous-stress force
V mu U_x'' = -8 V mu Umax/H^2:
    v_x = U_x(y_p) - (4/9) (d/H)^2 Umax,   v_y = v_z = 0,
within 0.2 % of Umax (the shift itself is 1.8 % of Umax for d/H = 0.2).
The particle sits at a cell centre, where the interpolated U is exact.

usage: checkViscousStress.py caseDir H Umax
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', '..', 'src', 'python'))  # particleCloud
import particleCloud  # noqa: E402

TOL = 0.002


def main():
    case, H, Umax = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    props = open(os.path.join(case, 'constant', 'couplingProperties')).read()
    d = float(re.search(r'diameter\s+([^;\s]+)\s*;', props).group(1))
    data = particleCloud.read(particleCloud.latest(case))
    y = data['position'][0][1]
    v = data['velocity'][0]
    Ux = 4*Umax*y*(H - y)/H**2
    expected = Ux - 4.0/9.0*(d/H)**2*Umax
    err = (v[0] - expected)/Umax
    print('v_x %.8g m/s; U_x(y_p) %.8g m/s; expected with V div(tau) %.8g'
          ' m/s: difference %.2e of Umax (tolerance %.1e); v_y, v_z %.2e,'
          ' %.2e of Umax' % (v[0], Ux, expected, err, TOL, v[1]/Umax, v[2]/Umax))
    ok = abs(err) <= TOL and abs(v[1]) <= TOL*Umax and abs(v[2]) <= TOL*Umax
    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
