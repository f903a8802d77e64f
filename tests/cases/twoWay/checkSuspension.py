"""Settling suspension at test size: the mean vertical velocity of the
particles in the middle of the column (1.5 to 4.5 mm) at the last write;
with a reference case (the same run, serial), within 0.1 % of it.  Also:
the particles settle (mean velocity downward) and none is lost.

usage: checkSuspension.py caseDir [referenceCaseDir]
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', '..', 'src', 'python'))  # particleCloud
import particleCloud  # noqa: E402


def mean_velocity(case):
    data = particleCloud.read(particleCloud.latest(case))
    vy = [v[1] for x, v in zip(data['position'], data['velocity'])
          if 1.5e-3 < x[1] < 4.5e-3]
    return sum(vy)/len(vy), len(data['position'])


def main():
    v, n = mean_velocity(sys.argv[1])
    print('mean settling velocity %.6g m/s, %d particles' % (v, n))
    ok = v < 0 and n == 4584
    if len(sys.argv) > 2:
        ref, _ = mean_velocity(sys.argv[2])
        print('against %s: %.6g m/s (%+.2e relative)'
              % (sys.argv[2], ref, v/ref - 1))
        ok &= abs(v/ref - 1) <= 1e-3
    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
