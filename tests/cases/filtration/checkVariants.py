"""Flocculation shortens the filtration (seed 002: by 51 % in the
experiment, 43 % in its simulation): the flocculated variant's filtration
time is shorter than the stable one's.  Prints the two variants'
porosities, permeabilities and filtration times.

Not asserted: that the flocculated cake is looser (seed 002's 0.601
against 0.43).  The model does not give it beyond the run-to-run spread
of the cake porosity (standard deviation 0.0045 over four suspensions):
at the test size the flocculated cake came out 0.0016 looser with
efd5a35's build and 0.0028 denser with c045673's (a fresh start that now
gives the fluid the first half kick's drag, and the lone particles'
update to rounding), so that comparison only tossed a coin; issue 8 keeps
it open.  The filtration times of the same two builds: 1.8 % and 2.2 %
shorter flocculated.

usage: checkVariants.py stableRunDir flocculatedRunDir
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', '..', 'tutorials', 'filtration'))
from filtrationResults import read_results as results  # noqa: E402


def main():
    s, f = results(sys.argv[1]), results(sys.argv[2])
    for key in ('cake_porosity', 'lowest_layer_porosity', 'permeability_m2',
                'filtration_time_s', 'coordination_number'):
        print('%-24s stable %-12s flocculated %s' % (key, s[key], f[key]))
    shorter = 1 - float(f['filtration_time_s'])/float(s['filtration_time_s'])
    ok = shorter > 0
    print('flocculated filtration %.1f %% shorter than the stable one (must be'
          ' shorter; seed 002: 43-51 %%); cake porosity %+.4f flocculated'
          ' against stable (not asserted: within the run-to-run spread 0.0045)'
          % (100*shorter, float(f['cake_porosity']) - float(s['cake_porosity'])))
    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
