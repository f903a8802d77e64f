"""Write a LIGGGHTS data file (units micro) of n spheres of one diameter
(and, with --fines, n_f smaller ones) at random, non-overlapping places in
a box, the same file for the same seed: a suspension present from the
start of a two-way run (particles inserted into a closed box during a run
would appear inside the fluid).

periodic: gaps measured across the periodic faces.  walls: centres at
least a radius plus 5 % of a diameter from every face.  column: periodic
in x and z, walls at the y faces.  Two spheres at least 5 % of the
smaller one's diameter apart.  The large spheres are placed first (random
sequential addition), then the fines.

usage: makeSuspension.py out.data n diameter Lx Ly Lz seed periodic|walls|column
       [--fines n_f d_f]   (lengths in um)
"""
import random
import sys


def write_data(out, pts, d, box, title):
    """LIGGGHTS data file (atom_style sphere, one atom type, density 2.5
    pg/um^3: the case sets the real one) of spheres at pts in the box
    [0, box[k]], of diameter d (one number, or one a sphere)."""
    diameters = d if isinstance(d, (list, tuple)) else [d]*len(pts)
    with open(out, 'w') as f:
        f.write('LIGGGHTS data file: %s\n\n' % title)
        f.write('%d atoms\n1 atom types\n\n' % len(pts))
        for k, axis in enumerate('xyz'):
            f.write('0 %g %slo %shi\n' % (box[k], axis, axis))
        f.write('\nAtoms\n\n')
        for i, (p, di) in enumerate(zip(pts, diameters)):
            # id type diameter density x y z
            f.write('%d 1 %.10g 2.5 %.9f %.9f %.9f\n' % (i + 1, di, p[0], p[1], p[2]))


def least_distance(a, b):
    """Least centre distance of spheres of diameters a and b: 5 % of the
    smaller diameter apart (1.05 a between equal spheres, as written)."""
    if a == b:
        return 1.05*a
    return 0.5*(a + b) + 0.05*min(a, b)


def fines_option(args, script):
    """(args without '--fines n_f d_f', n_f, d_f); n_f 0 without it."""
    if '--fines' not in args:
        return args, 0, 0.0
    k = args.index('--fines')
    try:
        n_f, d_f = int(args[k + 1]), float(args[k + 2])
    except (IndexError, ValueError):
        raise SystemExit('%s: --fines needs a count and a diameter [um]'
                         % script)
    if n_f < 0 or not d_f > 0:
        raise SystemExit('%s: --fines %s %s: allowed n_f >= 0, d_f > 0'
                         % (script, args[k + 1], args[k + 2]))
    return args[:k] + args[k + 3:], n_f, d_f


def main():
    args, n_f, d_f = fines_option(sys.argv, 'makeSuspension.py')
    out = args[1]
    n, d = int(args[2]), float(args[3])
    box = [float(x) for x in args[4:7]]
    seed, kind = int(args[7]), args[8]
    if kind not in ('periodic', 'walls', 'column'):
        raise SystemExit('makeSuspension.py: last argument periodic, walls'
                         ' or column')
    if n_f and not d_f < d:
        raise SystemExit('makeSuspension.py: --fines diameter %g um: allowed'
                         ' below the spheres\' %g um' % (d_f, d))
    periodic = [kind == 'periodic' or (kind == 'column' and k != 1)
                for k in range(3)]
    diameters = [d]*n + [d_f]*n_f
    cell = least_distance(d, d)     # the largest least distance

    rng = random.Random(seed)
    nbin = [max(1, int(L//cell)) for L in box]
    bins = {}
    pts = []
    tries = 0
    total = n + n_f
    while len(pts) < total:
        tries += 1
        if tries > 200*total:
            raise SystemExit('makeSuspension.py: cannot place %d spheres'
                             % total)
        di = diameters[len(pts)]
        margin = [0 if periodic[k] else 0.55*di for k in range(3)]
        p = [rng.uniform(margin[k], box[k] - margin[k]) for k in range(3)]
        b = [min(nb - 1, int(p[k]/box[k]*nb)) for k, nb in enumerate(nbin)]
        ok = True
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    key = [b[0] + dx, b[1] + dy, b[2] + dz]
                    for k in range(3):
                        if periodic[k]:
                            key[k] %= nbin[k]
                    for q, dq in bins.get(tuple(key), ()):
                        dd = 0
                        for k in range(3):
                            dk = abs(p[k] - q[k])
                            if periodic[k]:
                                dk = min(dk, box[k] - dk)
                            dd += dk*dk
                        if dd < least_distance(di, dq)**2:
                            ok = False
        if ok:
            pts.append(p)
            bins.setdefault(tuple(b), []).append((p, di))

    title = '%d random spheres (makeSuspension.py)' % n
    if n_f:
        title = ('%d random spheres of %g um and %d of %g um'
                 ' (makeSuspension.py)' % (n, d, n_f, d_f))
    write_data(out, pts, diameters, box, title)

if __name__ == '__main__':
    main()
