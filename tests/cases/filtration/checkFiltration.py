"""Checks of one filtration run (tutorials/filtration, filtrationResults.py
already run on it):
- the filtrate volume grows at every fluid step (flow rate > 0 through the
  outlet), and the filtration ended (99 % of the solids volume in the
  cake: filtration_end yes, not a cake that stopped growing below it);
- with --ruth: t/V against V is a straight line from 10 % of the filtrate
  to the end of filtration (Ruth): R^2 >= 0.98 (always printed);
- no particle passed the filter medium (none below y = 0 at any write);
- with a reference run (the same case, serial; this one on 2 ranks):
  * the same run until round-off grows: the flow rate at every fluid step
    up to 20 us within 1e-9 of the serial one (measured: 1.5e-11, the
    written precision; a parallel error shows at once, e.g. a force or a
    particle missing at a processor boundary);
  * afterwards the two runs part as any two runs of a granular packing do
    (the difference grows from 1e-11 at 40 us to 1e-4 at 100 us and to
    percents of the flow rate as the cake forms), so the filtrate volume
    at the end time is compared with the spread of statistically
    equivalent runs: four serial runs from different random suspensions
    (makeSuspension.py seeds 2718, 1, 2, 3) gave 5.709, 5.755, 5.800 and
    5.691e-13 m^3, a standard deviation of 0.84 %, so 1.2 % for the
    difference of two runs; the tolerance is 3 % (2.5 of it).  Two
    parallel runs measured: -1.03 % and -0.73 %.

usage: checkFiltration.py [--ruth] runDir [referenceRunDir]
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', '..', 'tutorials', 'filtration'))
from filtrationResults import read_results as results  # noqa: E402
from filtrationResults import read_series  # noqa: E402

R2_MIN = 0.98
EARLY_TIME = 2e-5       # [s] the runs are still the same run
EARLY_TOL = 1e-9
PARALLEL_TOL = 0.03


def flow(run):
    """[(time, flow rate)] through the outlet, every fluid step."""
    return [tuple(row[:2]) for row in
            read_series(run, 'filtrate', 'surfaceFieldValue.dat')]


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
    finished = r['filtration_end'] == 'yes'
    print('filtration ended: %s at %s s' % (r['filtration_end'],
                                           r['filtration_time_s']))
    r2 = float(r['ruth_r2'])
    print('t/V against V: R^2 %.5f over %s points (at least %.2f)'
          % (r2, r['ruth_points'], R2_MIN))
    below = int(r['particles_below_medium'])
    print('particles below the medium: %d (must be 0)' % below)
    ok = growing and finished and below == 0 and (r2 >= R2_MIN or not ruth)

    if len(args) > 1:
        early = [(t, q) for t, q in flow(run) if t <= EARLY_TIME]
        early_ref = dict((t, q) for t, q in flow(args[1]) if t <= EARLY_TIME)
        same = len(early) > 10 and all(t in early_ref for t, _ in early)
        worst = max((abs(q/early_ref[t] - 1) for t, q in early if t in early_ref),
                    default=float('inf'))
        print('flow rate up to %g s (%d steps): largest difference from the'
              ' serial run %.3g (at most %g)'
              % (EARLY_TIME, len(early), worst, EARLY_TOL))
        ok &= same and worst <= EARLY_TOL

        v, v_ref = volume(run), volume(args[1])
        err = v/v_ref - 1
        print('filtrate volume %.6g m^3, serial %.6g m^3: %+.3f %% (tolerance'
              ' %.0f %%)' % (v, v_ref, 100*err, 100*PARALLEL_TOL))
        ok &= abs(err) <= PARALLEL_TOL

    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
