"""The cake fraction that decides the end of filtration
(filtrationResults.cake_fraction: the share of the solids volume whose
centres lie below the cake's top plus one diameter), on hand-built
arrangements whose volume shares are known in closed form:

- one size, 97 of 100 spheres below the top: 0.97 (count and volume the
  same);
- one sphere of 5.8 um above the top, eight of 2.9 um below: the eight
  hold 8 (1.45)^3 = 1 (2.9)^3, so 0.5 (by count it would be 8/9: the
  suspension's last large sphere would not count);
- the same mirrored (the large sphere below, the fines above): 0.5 (by
  count 1/9);
- one of each, the fine above: 8/9 of the volume (by count 1/2);
- a random mixture of 200 spheres of 2.9 and 5.8 um at random heights,
  against the volume share summed here from (4/3) pi r^3;
each within 1e-12.

usage: checkCakeFraction.py tutorials/filtration workDir
"""
import math
import os
import random
import sys

TOL = 1e-12

sys.path.insert(0, os.path.abspath(sys.argv[1]))
from filtrationResults import cake_fraction  # noqa: E402

failed = []


def check(what, got, expected):
    ok = abs(got - expected) <= TOL
    print('%-60s %.15f (expected %.15f) %s'
          % (what, got, expected, 'ok' if ok else 'FAILED'))
    if not ok:
        failed.append(what)


R, r = 2.9, 1.45          # radii [um] of the spheres and of the fines
TOP = 50.0                # the cut [um]

check('one size, 97 of 100 below',
      cake_fraction([10.0]*97 + [60.0]*3, [R]*100, TOP), 0.97)
check('large above, eight fines below',
      cake_fraction([60.0] + [10.0]*8, [R] + [r]*8, TOP), 0.5)
check('large below, eight fines above',
      cake_fraction([10.0] + [60.0]*8, [R] + [r]*8, TOP), 0.5)
check('one of each, the fine above',
      cake_fraction([10.0, 60.0], [R, r], TOP), 8.0/9.0)

rng = random.Random(7)
ys = [rng.uniform(0.0, 100.0) for _ in range(200)]
radii = [rng.choice((R, r)) for _ in range(200)]
volume = [4.0/3.0*math.pi*a**3 for a in radii]
below = sum(v for y, v in zip(ys, volume) if y < TOP)
check('random mixture of 200', cake_fraction(ys, radii, TOP),
      below/sum(volume))

if failed:
    print('cake fraction: %d checks FAILED' % len(failed))
    sys.exit(1)
print('cake fraction: all checks passed')
