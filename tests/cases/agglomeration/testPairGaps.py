#!/usr/bin/env python3
"""The close pairs of a cloud (src/python/pairGaps.py, which the study's
report uses for the pairs held apart near contact) against the pairs of
all N^2/2 checked one by one:

  1. 1500 spheres of radius 0.10-0.20 um at random in 10 x 6 x 2 um^3
     (20 % by volume, overlaps counted), z periodic with span 2 um (the
     minimum image in z: the only image within the bound when the span is
     at least two cells): the same pairs below each bound of 5, 20 and
     100 nm, each once, gaps equal to within 1e-15 m.
  2. Built by hand (radius 0.15 um, span 1.25 um): a pair across the
     periodic face 10 nm apart; a pair 49 nm apart inside the box with the
     bound 50 nm; a pair 51 nm apart (not found); three spheres in a row
     10 nm apart (2 pairs, the end spheres 320 nm apart not found); a
     pair 10 nm apart with one sphere given one span up (z beyond the
     span: taken modulo the span); a pair across the face 39 nm apart
     with the lower sphere 0.33 um from the face (beyond two radii,
     within 2 radii + the bound); a pair 10 nm apart across the face with
     one sphere given below z = 0 (-0.05 um, as LIGGGHTS' atoms drift out
     of the box between neighbour-list builds).
  3. A span shorter than two cells is refused (a pair would meet itself
     through two images).

usage: testPairGaps.py colloidFoamDir"""
import os
import sys

import numpy as np


def brute(pos, r, span, max_gap):
    found = {}
    for i in range(len(r)):
        d = pos[i + 1:] - pos[i]
        d[:, 2] -= span*np.round(d[:, 2]/span)
        gap = np.linalg.norm(d, axis=1) - r[i] - r[i + 1:]
        for k in np.nonzero(gap < max_gap)[0]:
            found[(i, i + 1 + k)] = gap[k]
    return found


def main():
    sys.path.insert(0, os.path.join(sys.argv[1], "src", "python"))
    import pairGaps
    ok = True

    rng = np.random.default_rng(12)
    n, span = 1500, 2e-6
    pos = rng.uniform([0, 0, 0], [10e-6, 6e-6, span], size=(n, 3))
    r = rng.uniform(0.1e-6, 0.2e-6, size=n)
    for bound in (5e-9, 20e-9, 100e-9):
        i, j, gap = pairGaps.close_pairs(pos, r, span, bound)
        expect = brute(pos, r, span, bound)
        got = {(a, b): g for a, b, g in zip(i, j, gap)}
        across = sum(1 for a, b in expect
                     if abs(pos[a, 2] - pos[b, 2]) > span/2)
        same = len(i) == len(got) == len(expect) and set(got) == set(expect) and \
            all(abs(got[k] - expect[k]) < 1e-15 for k in expect) and \
            list(gap) == sorted(gap)
        print("random cloud, bound %g nm: %d pairs (%d across the periodic face), "
              "brute force %d: %s" % (bound*1e9, len(got), across, len(expect),
                                      "ok" if same else "FAIL"))
        ok = ok and same and across > 0

    R, span, u = 0.15e-6, 1.25e-6, 1e-6
    pos = np.array([[1*u, 1*u, 0.16*u], [1*u, 1*u, span - 0.15*u],     # across: 10 nm
                    [3*u, 1*u, 0.5*u], [3*u + 2*R + 49e-9, 1*u, 0.5*u],  # 49 nm
                    [5*u, 1*u, 0.5*u], [5*u, 1*u + 2*R + 51e-9, 0.5*u],  # 51 nm
                    [7*u, 2*u, 0.6*u], [7*u + 2*R + 10e-9, 2*u, 0.6*u],
                    [7*u + 4*R + 20e-9, 2*u, 0.6*u],                    # a row
                    [9*u, 1*u, span + 0.1*u], [9*u, 1*u, 0.41*u],       # z beyond the span
                    [11*u, 1*u, 0.33*u], [11*u, 1*u, span - 0.009*u],   # across: 39 nm
                    [13*u, 1*u, -0.05*u], [13*u, 1*u, span - 0.36*u]])  # z below 0: 10 nm
    i, j, gap = pairGaps.close_pairs(pos, [R]*len(pos), span, 50e-9)
    got = {(a, b): g for a, b, g in zip(i, j, gap)}
    expect = {(0, 1): 10e-9, (6, 7): 10e-9, (7, 8): 10e-9, (2, 3): 49e-9, (9, 10): 10e-9,
              (11, 12): 39e-9, (13, 14): 10e-9}
    good = len(i) == len(got) and set(got) == set(expect) and \
        all(abs(got[k] - expect[k]) < 1e-15 for k in expect)
    print("built by hand: %s: %s" % (sorted((k, "%.4g nm" % (g*1e9)) for k, g in got.items()),
                                     "ok" if good else "FAIL (expected %s)" % expect))
    ok = ok and good

    try:
        pairGaps.close_pairs(pos, [R]*len(pos), 0.6e-6, 50e-9)
        print("span 0.6 um (less than two cells of 0.35 um): accepted: FAIL")
        ok = False
    except ValueError as e:
        print("span 0.6 um refused: %s: ok" % e)

    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
