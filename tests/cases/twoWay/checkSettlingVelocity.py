"""Terminal velocity of one sphere settling in the two-way solver against
Stokes' law v_s = (rho_p - rho_f) g d^2/(18 mu), with the settings read
from the case (couplingProperties, constant/g).  The velocity is the last
particle file's; it must also have stopped changing (the last two files
within a tenth of the tolerance).

With a reference case (the same run, serial), the velocities must also
agree within 0.1 %.

usage: checkSettlingVelocity.py caseDir tolerance [referenceCaseDir]
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', '..', 'src', 'python'))  # particleCloud
import particleCloud  # noqa: E402


def number(text, key):
    return float(re.search(r'\b%s\s+([^;\s]+)\s*;' % key, text).group(1))


def main():
    case, tol = sys.argv[1], float(sys.argv[2])
    props = open(os.path.join(case, 'constant', 'couplingProperties')).read()
    fluid = props[props.index('fluid'):]
    particles = props[props.index('particles'):]
    rho_f, mu = number(fluid, 'rho'), number(fluid, 'mu')
    d, rho_p = number(particles, 'diameter'), number(particles, 'density')
    g = float(re.search(r'value\s+\(\s*\S+\s+(\S+)',
                        open(os.path.join(case, 'constant', 'g')).read()).group(1))
    v_s = (rho_p - rho_f)*g*d*d/(18*mu)

    files = particleCloud.write_times(case)
    vy = [particleCloud.read(f)['velocity'][0][1] for f in files[-2:]]
    err = vy[-1]/v_s - 1
    drift = abs(vy[-1]/vy[-2] - 1)
    print('terminal velocity %.6g m/s, Stokes %.6g m/s: %+.2f %% (tolerance'
          ' %.1f %%); last change %.2e' % (vy[-1], v_s, 100*err, 100*tol, drift))
    ok = abs(err) <= tol and drift <= 0.1*tol
    if len(sys.argv) > 3:
        ref = particleCloud.read(particleCloud.latest(sys.argv[3]))['velocity'][0][1]
        print('against %s: %.6g m/s (%+.2e relative)'
              % (sys.argv[3], ref, vy[-1]/ref - 1))
        ok &= abs(vy[-1]/ref - 1) <= 1e-3
    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
