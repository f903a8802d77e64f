"""Suspensions with fines (--fines n_f d_f of makeSuspension.py and
makeFlocs.py: a second, smaller size, what the filtration case's
fineVolumeFraction asks for), in a column of 58 x 60 x 58 um with 132
spheres of 5.8 um and 1000 of 2.9 um (13 % solids, half the solids volume
in fines, as fineVolumeFraction 0.487 at the tests' size):

- every file: 132 spheres of 5.8 um and 1000 of 2.9 um; no two spheres
  closer than the sum of their radii (to 1e-9), across the periodic x and
  z faces too;
- the random suspension: every pair at least 5 % of the smaller diameter
  beyond contact, every centre at least 0.55 of its own diameter from the
  y faces (the walls);
- the flocs (8 spheres each, the fines among them at random): as many
  clusters of touching spheres (centres within 1e-7 of the sum of their
  radii) as flocs, ceil(1132/8) = 142, and fines in at least 90 % of them
  (by chance a floc of 8 has no fine with probability 0.12^8 = 4e-8;
  fines not mixed in, the first 16 flocs would hold none: 89 %);
- the gel: one cluster holding every sphere, with as many contacts as a
  tree needs (1131);
- a fines' diameter not below the spheres' exits non-zero, naming it, and
  writes no file.

usage: checkFinesSuspension.py tutorials workDir
"""
import os
import subprocess
import sys

import numpy as np

from checkGelSuspension import components, refused, separations

N, D, N_F, D_F = 132, 5.8, 1000, 2.9
BOX, SIZE = (58.0, 60.0, 58.0), 8


def read(path):
    rows = open(path).read().split('Atoms')[1].split('\n')
    a = np.array([[float(v) for v in r.split()[2:7]] for r in rows if r.strip()])
    return a[:, 0], a[:, 2:5]


def main():
    tutorials, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    failures = []

    def check(ok, what):
        print('%s: %s' % ('ok' if ok else 'FAIL', what))
        if not ok:
            failures.append(what)

    common = [str(N), str(D)] + [str(x) for x in BOX] + ['2718']
    fines = ['--fines', str(N_F), str(D_F)]
    runs = {
        'random': [os.path.join(tutorials, 'twoWay', 'makeSuspension.py')]
        + common + ['column'] + fines,
        'flocs': [os.path.join(tutorials, 'filtration', 'makeFlocs.py')]
        + common + [str(SIZE)] + fines,
        'gel': [os.path.join(tutorials, 'filtration', 'makeFlocs.py')]
        + common + [str(SIZE), 'gel'] + fines}
    for mode, args in runs.items():
        out = os.path.join(work, mode + '.data')
        subprocess.run([sys.executable, args[0], out] + args[1:], check=True)
        d, p = read(out)
        r = separations(p, BOX)
        contact = 0.5*(d[:, None] + d[None, :])
        counts = (int((d == D).sum()), int((d == D_F).sum()))
        check(counts == (N, N_F), '%s: %d spheres of %g um and %d of %g um'
              ' (expected %d and %d)' % (mode, counts[0], D, counts[1], D_F,
                                          N, N_F))
        check((r >= contact*(1 - 1e-9)).all(), '%s: no overlap (closest'
              ' %.9f of contact)' % (mode, (r/contact).min()))
        touching = np.abs(r - contact) <= 1e-7*contact
        n, label, contacts = components(touching)
        if mode == 'random':
            least = contact + 0.05*np.minimum(d[:, None], d[None, :])
            check((r >= least*(1 - 1e-9)).all(), 'random: every pair 5 %% of'
                  ' the smaller diameter apart (closest %.6f of that)'
                  % (r/least).min())
            check((p[:, 1] >= 0.55*d - 1e-6).all()
                  and (p[:, 1] <= BOX[1] - 0.55*d + 1e-6).all(),
                  'random: centres 0.55 of their diameter from the y faces')
        elif mode == 'flocs':
            flocs = -(-(N + N_F)//SIZE)
            check(n == flocs, 'flocs: %d clusters (expected %d)' % (n, flocs))
            with_fines = len(set(label[d == D_F]))/n
            check(with_fines >= 0.9, 'flocs: %.0f %% of them hold fines'
                  % (100*with_fines))
        else:
            check(n == 1, 'gel: %d cluster(s) (expected one)' % n)
            check(contacts == N + N_F - 1, 'gel: %d contacts (a tree: %d)'
                  % (contacts, N + N_F - 1))

    ok, said = refused([sys.executable, runs['flocs'][0]], work,
                       common + [str(SIZE), '--fines', str(N_F), str(D)],
                       ['--fines diameter %g' % D])
    check(ok, 'fines not below the spheres: non-zero exit, named (%s), no'
          ' file' % said)

    if failures:
        sys.exit('%d failures' % len(failures))
    print('fines suspension: all checks passed')


if __name__ == '__main__':
    main()
