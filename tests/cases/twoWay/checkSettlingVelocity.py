"""Terminal velocity of spheres settling in the two-way solver against
Stokes' law v_s = (rho_p - rho_f) g d^2/(18 mu), with the settings read
from the case (couplingProperties, constant/g) and each sphere's own
diameter (the cloud's d: spheres of different sizes in one run,
particles/diameterRange).  Several spheres also move in each other's flow:
placed far apart (a far field of (3/4)(a_j/r) v_j in unbounded liquid,
Batchelor 1976; less in the closed box, whose walls carry the return
flow), within the tolerance.  The velocity is the last particle file's;
it must also have stopped changing (the last two files within a tenth of
the tolerance).

With a reference case (the same run, serial), the velocities must also
agree within 0.1 %.  With --diameters, the spheres' diameters (by id) must
be these: the Stokes velocities are of the sizes the DEM script set, not
only of those the solver wrote.

usage: checkSettlingVelocity.py caseDir tolerance [referenceCaseDir]
       [--diameters d1,d2,...]   (diameters in m)
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
    args = sys.argv[1:]
    expected = None
    if '--diameters' in args:
        k = args.index('--diameters')
        expected = [float(x) for x in args[k + 1].split(',')]
        args = args[:k] + args[k + 2:]
    case, tol = args[0], float(args[1])
    props = open(os.path.join(case, 'constant', 'couplingProperties')).read()
    fluid = props[props.index('fluid'):]
    particles = props[props.index('particles'):]
    rho_f, mu = number(fluid, 'rho'), number(fluid, 'mu')
    rho_p = number(particles, 'density')
    g = float(re.search(r'value\s+\(\s*\S+\s+(\S+)',
                        open(os.path.join(case, 'constant', 'g')).read()).group(1))

    files = particleCloud.write_times(case)
    clouds = [particleCloud.read(f) for f in files[-2:]]
    ok = True
    if expected is not None:
        got = [2*a for a in clouds[-1]['radius']]
        same = len(got) == len(expected) and all(
            abs(g/e - 1) <= 1e-9 for g, e in zip(got, expected))
        print('diameters %s m (expected %s)' % (got, expected))
        ok &= same
    for i, a in enumerate(clouds[-1]['radius']):
        v_s = (rho_p - rho_f)*g*(2*a)**2/(18*mu)
        vy = [cloud['velocity'][i][1] for cloud in clouds]
        err = vy[-1]/v_s - 1
        drift = abs(vy[-1]/vy[-2] - 1)
        print('sphere of d = %.4g m: terminal velocity %.6g m/s, Stokes %.6g'
              ' m/s: %+.2f %% (tolerance %.1f %%); last change %.2e'
              % (2*a, vy[-1], v_s, 100*err, 100*tol, drift))
        ok &= abs(err) <= tol and drift <= 0.1*tol
    if len(args) > 2:
        ref = particleCloud.read(particleCloud.latest(args[2]))['velocity']
        for i, v in enumerate(clouds[-1]['velocity']):
            print('against %s: %.6g m/s (%+.2e relative)'
                  % (args[2], ref[i][1], v[1]/ref[i][1] - 1))
            ok &= abs(v[1]/ref[i][1] - 1) <= 1e-3
    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
