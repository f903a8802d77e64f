"""Checks of a consolidation (consolidationResults.py already run): at
every pressure step the cake came to rest with the piston force within
2 % of pressure x area, and the packing density rose from each step to
the next.

usage: checkConsolidation.py runDir
"""
import csv
import os
import sys

FORCE_TOL = 0.02


def main():
    with open(os.path.join(sys.argv[1], 'consolidation.csv')) as f:
        rows = list(csv.DictReader(f))
    ok = len(rows) >= 2
    for r in rows:
        err = float(r['force_error'])
        print('%8.0f Pa: packing density %s, piston force %+.3f %% of'
              ' pressure x area, at rest %s after %s steps'
              % (float(r['pressure_Pa']), r['packing_density'], 100*err,
                 r['at_rest'], r['steps']))
        ok &= abs(err) <= FORCE_TOL and r['at_rest'] == 'yes'
    dens = [float(r['packing_density']) for r in rows]
    rising = all(b > a for a, b in zip(dens, dens[1:]))
    print('packing density rises at every step: %s' % ('yes' if rising else 'no'))
    ok &= rising
    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
