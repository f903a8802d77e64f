"""The flocculated cake is looser than the stable one (seed 002: flocs
deposit into an open structure): its mean porosity is higher.  Prints the
two variants' porosities, permeabilities and filtration times.

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
    ok = float(f['cake_porosity']) > float(s['cake_porosity'])
    print('flocculated cake porosity above the stable one: %s'
          % ('yes' if ok else 'no'))
    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
