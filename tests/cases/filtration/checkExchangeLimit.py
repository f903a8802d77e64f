"""Checks of the exchange limit on the fluid step against two filtrations
(runExchangeLimitTest.sh): the stable variant at test size, one at a fluid
step below the limit the solver printed, one above it.

- The limit brackets where the real cake blows up, within a factor of
  two: the run below is at least half the limit, the run above at most
  twice it.
- Below: the cake holds.  After 0.3 ms (the cake is forming) the net drag
  on the particles points down (with the filtrate) at every fluid step,
  and its largest magnitude is at most 3 times the median (measured 1.3
  from 0.3 to 1 ms at 8e-7 s with particles twice as heavy, 1.00 of
  their limit).
- Above: the cake is blown apart.  After 0.3 ms the net drag reverses
  (points up) at 5 fluid steps or more and bursts to at least 20 times
  its median (measured from 0.3 to 1 ms at 6e-7 s: 47 reversals, 165
  times; at 8e-7 s: 64, 151 times; at 4e-7 s with particles half as
  heavy: 68, 600 times).

usage: checkExchangeLimit.py belowLog aboveLog
"""
import re
import sys

FROM = 3e-4           # [s] the cake is forming
HOLD_RATIO = 3.0
BURST_RATIO = 20.0
MIN_REVERSALS = 5

LIMIT = re.compile(r'^Time-step limit, explicit two-way exchange.*: fluid step '
                   r'<= (\S+) s \(set at fluid fraction \S+\); fluid step '
                   r'(\S+) s is')
NO_LIMIT = re.compile(r'^Time-step limit, explicit two-way exchange.*: none, '
                      r'stable at any fluid step \(fluid step (\S+) s\)')
DRAG = re.compile(r'^Momentum exchange: drag on particles \((\S+) (\S+) (\S+)\)')


def read(log):
    """(limit [s], fluid step [s], [(time, net drag y [N])])"""
    limit = step = None
    drag = []
    time = None
    with open(log) as f:
        for line in f:
            m = LIMIT.match(line)
            n = NO_LIMIT.match(line)
            if m:
                limit, step = float(m.group(1)), float(m.group(2))
            elif n:
                limit, step = float('inf'), float(n.group(1))
            elif line.startswith('Time = '):
                time = float(line.split()[2])
            else:
                m = DRAG.match(line)
                if m and time is not None:
                    drag.append((time, float(m.group(2))))
    if limit is None or not drag:
        sys.exit('%s: no exchange limit or no drag printed' % log)
    return limit, step, drag


def statistics(drag):
    """(fluid steps with the drag up, max |drag| / median |drag|) after FROM"""
    y = [f for t, f in drag if t >= FROM]
    if len(y) < 100:
        sys.exit('only %d fluid steps after %g s' % (len(y), FROM))
    mags = sorted(abs(f) for f in y)
    median = mags[len(mags)//2]
    return sum(1 for f in y if f > 0), mags[-1]/median, len(y)


def main(below_log, above_log):
    failures = []
    limit, below_step, below = read(below_log)
    above_limit, above_step, above = read(above_log)
    print('limit %.4g s; fluid steps %.3g s (%.2f of it), %.3g s (%.2f of it)'
          % (limit, below_step, below_step/limit, above_step, above_step/limit))
    if above_limit != float('inf'):
        # freeFluidFraction 0.8 leaves no free layer that limits the step
        failures.append('the run above printed a finite limit %g' % above_limit)
    if not limit/2 <= below_step < limit:
        failures.append('the run below is not within half the limit below it')
    if not limit < above_step <= 2*limit:
        failures.append('the run above is not within twice the limit above it')

    up, ratio, n = statistics(below)
    print('below: %d of %d fluid steps with the drag up, max/median %.2f'
          % (up, n, ratio))
    if up > 0 or ratio > HOLD_RATIO:
        failures.append('below the limit the cake did not hold')

    up, ratio, n = statistics(above)
    print('above: %d of %d fluid steps with the drag up, max/median %.1f'
          % (up, n, ratio))
    if up < MIN_REVERSALS or ratio < BURST_RATIO:
        failures.append('above the limit the cake was not blown apart')

    for f in failures:
        print('FAIL: ' + f)
    if failures:
        sys.exit(1)
    print('PASS')


if __name__ == '__main__':
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
