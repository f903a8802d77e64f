"""The flocculated suspension as one network (makeFlocs.py ... gel), at
the tests' size (795 spheres of 5.8 um in 58 x 185.6 x 58 um, flocs of 8),
checked against the same seed's flocs (makeFlocs.py without gel):

- the flocs' file: as many separate clusters of touching spheres (centres
  within 1e-7 d of one diameter) as flocs, ceil(795/8) = 100;
- the gel's file: one cluster holding all 795 spheres, with as many
  contacts as a tree needs (794: each join adds one contact);
- both: no two spheres closer than one diameter (to 1e-9 d), across the
  periodic x and z faces too, and every centre at least 0.55 d from the
  y faces (the walls);
- the aggregation moves each floc rigidly: every distance between two
  spheres of one floc is the same in both files (to 1e-6 d);
- a bad last argument ("gel " misspelt) exits non-zero, names it and the
  usage, and writes no file.

usage: checkGelSuspension.py makeFlocs.py workDir
"""
import os
import subprocess
import sys

import numpy as np

N, D, BOX, SIZE = 795, 5.8, (58.0, 185.6, 58.0), 8


def read(path):
    text = open(path).read()
    rows = text.split('Atoms')[1].split('\n')
    return np.array([[float(v) for v in r.split()[4:7]]
                     for r in rows if r.strip()])


def separations(p, box=BOX):
    """Centre distances of the spheres at p, x and z periodic (box)."""
    w = p[:, None, :] - p[None, :, :]
    for k in (0, 2):
        w[:, :, k] -= box[k]*np.round(w[:, :, k]/box[k])
    r = np.sqrt((w**2).sum(-1))
    np.fill_diagonal(r, np.inf)
    return r


def clusters(r):
    count, label, contacts = components(r < D*(1 + 1e-7))
    return count, np.bincount(label).max(), contacts


def components(touching):
    """(count, label of each sphere, contacts) of the clusters of the
    matrix touching."""
    label = -np.ones(len(touching), int)
    count = 0
    for s in range(len(touching)):
        if label[s] >= 0:
            continue
        label[s] = count
        stack = [s]
        while stack:
            i = stack.pop()
            for j in np.nonzero(touching[i] & (label < 0))[0]:
                label[j] = count
                stack.append(j)
        count += 1
    return count, label, int(touching.sum())//2


def refused(command, work, args, words):
    """(whether command, writing work/bad.data with args, exits non-zero,
    says every one of words and writes no file; what it said)."""
    bad = os.path.join(work, 'bad.data')
    run = subprocess.run(command + [bad] + args, capture_output=True,
                         text=True)
    said = run.stderr.strip()
    return (run.returncode != 0 and all(w in said for w in words)
            and not os.path.exists(bad)), said


def main():
    script, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    failures = []

    def check(ok, what):
        print('%s: %s' % ('ok' if ok else 'FAIL', what))
        if not ok:
            failures.append(what)

    files = {}
    for mode in ('flocs', 'gel'):
        out = os.path.join(work, mode + '.data')
        args = [sys.executable, script, out, str(N), str(D)] + \
            [str(x) for x in BOX] + ['2718', str(SIZE)] + \
            (['gel'] if mode == 'gel' else [])
        subprocess.run(args, check=True)
        files[mode] = read(out)
    flocs = -(-N//SIZE)
    for mode, p in files.items():
        r = separations(p)
        n, largest, contacts = clusters(r)
        print('%s: %d spheres, %d clusters, largest %d, %d contacts, '
              'closest %.10f d, y from %.3f to %.3f um'
              % (mode, len(p), n, largest, contacts, r.min()/D,
                 p[:, 1].min(), p[:, 1].max()))
        check(len(p) == N, '%s: %d spheres (expected %d)' % (mode, len(p), N))
        check(r.min() >= D*(1 - 1e-9), '%s: no overlap' % mode)
        check(p[:, 1].min() >= 0.55*D - 1e-6
              and p[:, 1].max() <= BOX[1] - 0.55*D + 1e-6,
              '%s: centres 0.55 d from the y faces' % mode)
        if mode == 'flocs':
            check(n == flocs, 'flocs: %d clusters (expected %d)' % (n, flocs))
        else:
            check(n == 1 and largest == N, 'gel: one cluster of all spheres')
            check(contacts == N - 1, 'gel: %d contacts (a tree: %d)'
                  % (contacts, N - 1))
    worst = 0.0
    for start in range(0, N, SIZE):
        a = separations(files['flocs'][start:start + SIZE])
        b = separations(files['gel'][start:start + SIZE])
        finite = np.isfinite(a)
        worst = max(worst, np.abs(a[finite] - b[finite]).max(initial=0.0))
    check(worst <= 1e-6*D, 'gel: flocs moved rigidly (largest change of an '
          'internal distance %.2e d)' % (worst/D))

    ok, said = refused([sys.executable, script], work,
                       [str(N), str(D)] + [str(x) for x in BOX]
                       + ['2718', str(SIZE), 'gell'], ['gell', 'usage'])
    check(ok, 'bad argument: non-zero exit, named with the usage (%s), no'
          ' file' % said)

    if failures:
        sys.exit('%d failures' % len(failures))
    print('gel suspension: all checks passed')


if __name__ == '__main__':
    main()
