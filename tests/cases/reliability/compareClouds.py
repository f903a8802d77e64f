#!/usr/bin/env python3
"""Two write times of the same run (uninterrupted and resumed) must hold
the same particles (by id) at the same positions and velocities.

Reference: the uninterrupted run.  The resumed run repeats the same
arithmetic except for the order of some sums (neighbour lists and the
atoms' order are rebuilt at the resume), so
  - at least 95 % of the particles must be identical to every written
    digit (position and velocity): round-off differences stay below the
    written precision except where a stiff contact amplifies them (slot-
    coater test, 1.8 us after the resume: 99.85 % serial, 99.5 % on 2
    ranks);
  - none may be further than 1e-3 of a diameter from its position in the
    reference (such an amplified round-off difference: 3e-5 d for two
    particles touching each other and the moving substrate, 1.8 us after
    the resume in the slot-coater test).
A missing piece of state fails the first: without the last step's force
658 of 1981 particles were identical; with a release step of the feed
one step early, a particle's position differed by 5e-3 d.

With a velocity tolerance (two-way runs): the fluid resumes from its
written fields (15 digits), so velocities differ from the uninterrupted
run's in their last digits; then every particle's velocity must be within
that fraction of the reference's largest velocity component (and its
position within 1e-3 d) instead of 95 % identical to every digit.

usage: compareClouds.py referenceTimeDir resumedTimeDir [velocityTolerance]
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', '..', 'src', 'python'))
import particleCloud  # noqa: E402

IDENTICAL_FRACTION = 0.95
POSITION_TOL = 1e-3   # of the diameter


def main():
    ref = particleCloud.read(sys.argv[1])
    res = particleCloud.read(sys.argv[2])
    ok = True

    same_ids = ref['id'] == res['id']
    print('particles: reference %d, resumed %d, same ids: %s'
          % (len(ref['id']), len(res['id']), same_ids))
    if not same_ids or not ref['id']:
        print('FAIL: not the same particles')
        sys.exit(1)

    d = 2*max(ref['radius'])
    pairs = list(zip(ref['position'], res['position'],
                     ref['velocity'], res['velocity']))
    identical = sum(1 for p, q, u, w in pairs if p == q and u == w)
    fraction = identical/len(pairs)
    dx = max(max(abs(a - b) for a, b in zip(p, q)) for p, q, _, _ in pairs)
    dv = max(max(abs(a - b) for a, b in zip(u, w)) for _, _, u, w in pairs)
    print('identical to every written digit: %d of %d (%.2f %%; at least'
          ' %g %%)' % (identical, len(pairs), 100*fraction,
                       100*IDENTICAL_FRACTION))
    print('largest position difference %.3g m = %.3g d (at most %g d);'
          ' largest velocity difference %.3g m/s'
          % (dx, dx/d, POSITION_TOL, dv))
    if len(sys.argv) > 3:
        vmax = max(max(abs(a) for a in u) for _, _, u, _ in pairs)
        tol = float(sys.argv[3])
        print('largest velocity difference %.3g m/s, largest velocity'
              ' component %.3g m/s (at most %g of it)' % (dv, vmax, tol))
        if dv > tol*vmax:
            print('FAIL: velocities differ')
            ok = False
    elif fraction < IDENTICAL_FRACTION:
        print('FAIL: the resumed run is not the same run')
        ok = False
    if dx > POSITION_TOL*d:
        print('FAIL: positions differ')
        ok = False
    print('PASS' if ok else 'FAIL')
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
