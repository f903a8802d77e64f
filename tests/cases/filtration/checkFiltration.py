"""Checks of one filtration run (tutorials/filtration, filtrationResults.py
already run on it):
- the filtrate volume grows at every fluid step (flow rate > 0 through the
  outlet), and the filtration ended (99 % of the particles in the cake);
- with --ruth: t/V against V is a straight line from 10 % of the filtrate
  to the end of filtration (Ruth): R^2 >= 0.98 (always printed);
- no particle passed the filter medium (none below y = 0 at any write);
- with a reference run (the same case, serial): the filtrate volume at
  the end time within 1 %.

usage: checkFiltration.py [--ruth] runDir [referenceRunDir]
"""
import glob
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', '..', 'tutorials', 'filtration'))
from filtrationResults import read_results as results  # noqa: E402

R2_MIN = 0.98
PARALLEL_TOL = 0.01


def flow(run):
    """[(time, flow rate)] through the outlet, every fluid step."""
    return [tuple(float(x) for x in line.split()) for line in open(glob.glob(
        os.path.join(run, 'postProcessing', 'filtrate', '*',
                     'surfaceFieldValue.dat'))[0])
            if line.strip() and not line.startswith('#')]


def volume(run):
    """Filtrate volume at the end time [m^3] (trapezoidal)."""
    rows = [(0.0, 0.0)] + flow(run)
    rows[0] = (0.0, rows[1][1])
    return sum(0.5*(rows[k][1] + rows[k - 1][1])*(rows[k][0] - rows[k - 1][0])
               for k in range(1, len(rows)))


def main():
    args = sys.argv[1:]
    ruth = '--ruth' in args
    args = [a for a in args if a != '--ruth']
    run = args[0]
    r = results(run)
    flux = [q for _, q in flow(run)]
    ok = True

    growing = min(flux) > 0
    print('filtrate flow rate: %d steps, smallest %.4g m^3/s (must be > 0)'
          % (len(flux), min(flux)))
    finished = r['filtration_finished'] == 'yes'
    print('filtration ended: %s at %s s' % (r['filtration_finished'],
                                           r['filtration_time_s']))
    r2 = float(r['ruth_r2'])
    print('t/V against V: R^2 %.5f over %s points (at least %.2f)'
          % (r2, r['ruth_points'], R2_MIN))
    below = int(r['particles_below_medium'])
    print('particles below the medium: %d (must be 0)' % below)
    ok = growing and finished and below == 0 and (r2 >= R2_MIN or not ruth)

    if len(args) > 1:
        v, v_ref = volume(run), volume(args[1])
        err = v/v_ref - 1
        print('filtrate volume %.6g m^3, serial %.6g m^3: %+.3f %% (tolerance'
              ' %.0f %%)' % (v, v_ref, 100*err, 100*PARALLEL_TOL))
        ok &= abs(err) <= PARALLEL_TOL

    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
