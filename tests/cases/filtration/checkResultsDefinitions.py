"""Three definitions of filtrationResults.py, on hand-built inputs.

The cake fraction that decides the end of filtration (cake_fraction: the
share of the solids volume whose centres lie below the cake's top plus
one diameter), on arrangements whose volume shares are known in closed
form:

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

The run's contacts (latest_contacts): the DEM dumps its contacts every
write interval; a run whose end time lies between two writes (-endTime
0.4 ms with writes every 24 us) reports those of the last dump before
it, not none; an end time that is a dump's, read back from a time
folder's name to fewer digits, reports that dump's; no dump before the
end, none.

The end of filtration (end_of_filtration) from the cake fraction at each
write: crossing 99 % between writes at 0.98 and 0.995, at the linear
interpolation (two thirds into the interval); a cake that stops growing at
0.9899 (the 0.168 ms write of a flocculated titanium dioxide run, 'no'
before this rule), 'stopped' at the first write of the still fraction;
a pause of one write interval between arriving flocs, not an end (the
cake then reaches 99 %: 'yes' there); still below 0.9 (the start,
before the cake forms), not an end; a fraction that changes by one
small sphere's share between writes, not an end; still rising at the
last write, 'no' at the last write; a single write already at 99 %,
'yes' at it.

usage: checkResultsDefinitions.py tutorials/filtration workDir
"""
import math
import os
import random
import sys

TOL = 1e-12

sys.path.insert(0, os.path.abspath(sys.argv[1]))
from filtrationResults import (cake_fraction, end_of_filtration,  # noqa: E402
                               latest_contacts)

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

# Dumps every 24 us (times as the results key them: step x DEM step,
# rounded to 12 digits), each (coordination number, mean force [N])
dumps = {round(k*120000*2e-10, 12): (5.0 + 0.01*k, 1e-8*k) for k in range(17)}
t, value = latest_contacts(dumps, 0.000400001)
check('end between two dumps: the last one before, time', t, 0.000384)
check('end between two dumps: the last one before, coordination',
      value[0], 5.16)
t, value = latest_contacts(dumps, 0.000384)
check('end at a dump: that dump', t, 0.000384)
t, value = latest_contacts(dumps, 2.4e-5*(1 - 1e-11))
check('end at a dump, its time read to fewer digits', t, 2.4e-5)
t, value = latest_contacts({1e-4: (5.0, 1e-8)}, 5e-5)
check('no dump before the end: none (nan is not nan)',
      float(t == t), 0.0)

# The end of filtration; still: half of one sphere's share of 795
STILL = 0.5/795
writes = [0.0, 2.4e-5, 4.8e-5, 7.2e-5]
t, how = end_of_filtration(list(zip(writes, [0.3, 0.7, 0.98, 0.995])), STILL)
check('99 % crossed between writes: t_f', t, 4.8e-5 + 2.4e-5*2/3)
check('99 % crossed between writes: yes', float(how == 'yes'), 1.0)
fractions = [0.9069, 0.9836, 0.9899, 0.9899, 0.9899]
t, how = end_of_filtration(list(zip([1.2e-4, 1.44e-4, 1.68e-4, 1.92e-4,
                                     2.16e-4], fractions)), STILL)
check('cake stopped at 0.9899: t_f, its first write', t, 1.68e-4)
check('cake stopped at 0.9899: stopped', float(how == 'stopped'), 1.0)
t, how = end_of_filtration(list(zip(writes, [0.95, 0.95, 0.97, 0.995])),
                           STILL)
check('a pause of one interval: yes at 99 %', t, 4.8e-5 + 2.4e-5*0.8)
t, how = end_of_filtration(list(zip(writes, [0.02, 0.02, 0.02, 0.8])), STILL)
check('still at the start: not an end', float(how == 'no'), 1.0)
t, how = end_of_filtration(list(zip(writes, [0.95, 0.95 + 1.0/795,
                                             0.95 + 2.0/795, 0.96])), STILL)
check('one sphere a write: not an end', float(how == 'no'), 1.0)
check('still rising at the end: t_f the last write', t, 7.2e-5)
t, how = end_of_filtration([(1e-4, 0.995)], STILL)
check('a single write at 99 %: t_f', t, 1e-4)
check('a single write at 99 %: yes', float(how == 'yes'), 1.0)

if failed:
    print('results definitions: %d checks FAILED' % len(failed))
    sys.exit(1)
print('results definitions: all checks passed')
