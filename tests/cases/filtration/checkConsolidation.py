"""Checks of a consolidation (consolidationResults.py already run): at
every pressure step the cake came to rest with the piston force within
2 % of pressure x area, and the packing density rose from each step to
the next.  Given a second run (the same cake consolidated serially, this
one on 2 ranks): the packing density at every pressure within 0.001 of
it, a third of the difference that the loading rate makes (README,
Consolidation: 0.003 between 0.2 and 0.05 m/s) and a tenth of the
smallest step between pressures.

usage: checkConsolidation.py runDir [serialRunDir]
"""
import csv
import os
import sys

FORCE_TOL = 0.02
SERIAL_TOL = 0.001


def read(run):
    with open(os.path.join(run, 'consolidation.csv')) as f:
        return list(csv.DictReader(f))


def main():
    rows = read(sys.argv[1])
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
    if len(sys.argv) > 2:
        serial = read(sys.argv[2])
        same = len(serial) == len(rows)
        for r, s in zip(rows, serial):
            diff = float(r['packing_density']) - float(s['packing_density'])
            print('%8.0f Pa: packing density %s, serial %s: %+.5f'
                  % (float(r['pressure_Pa']), r['packing_density'],
                     s['packing_density'], diff))
            same &= (r['pressure_Pa'] == s['pressure_Pa']
                     and abs(diff) <= SERIAL_TOL)
        print('as the serial consolidation within %g: %s'
              % (SERIAL_TOL, 'yes' if same else 'no'))
        ok &= same
    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
