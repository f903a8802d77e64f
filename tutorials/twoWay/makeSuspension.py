"""Write a LIGGGHTS data file (units micro) of n spheres of one diameter
at random, non-overlapping places in a box, the same file for the same
seed: a suspension present from the start of a two-way run (particles
inserted into a closed box during a run would appear inside the fluid).

periodic: gaps measured across the periodic faces.  walls: centres at
least a radius plus 5 % of a diameter from every face.  column: periodic
in x and z, walls at the y faces.

usage: makeSuspension.py out.data n diameter Lx Ly Lz seed periodic|walls|column
       (lengths in um)
"""
import random
import sys


def write_data(out, pts, d, box, title):
    """LIGGGHTS data file (atom_style sphere, one atom type, density 2.5
    pg/um^3: the case sets the real one) of spheres of diameter d at pts
    in the box [0, box[k]]."""
    with open(out, 'w') as f:
        f.write('LIGGGHTS data file: %s\n\n' % title)
        f.write('%d atoms\n1 atom types\n\n' % len(pts))
        for k, axis in enumerate('xyz'):
            f.write('0 %g %slo %shi\n' % (box[k], axis, axis))
        f.write('\nAtoms\n\n')
        for i, p in enumerate(pts):
            # id type diameter density x y z
            f.write('%d 1 %g 2.5 %.9f %.9f %.9f\n' % (i + 1, d, p[0], p[1], p[2]))


def main():
    out = sys.argv[1]
    n, d = int(sys.argv[2]), float(sys.argv[3])
    box = [float(x) for x in sys.argv[4:7]]
    seed, kind = int(sys.argv[7]), sys.argv[8]
    if kind not in ('periodic', 'walls', 'column'):
        raise SystemExit('makeSuspension.py: last argument periodic, walls'
                         ' or column')
    periodic = [kind == 'periodic' or (kind == 'column' and k != 1)
                for k in range(3)]
    margin = [0 if periodic[k] else 0.55*d for k in range(3)]
    gap2 = (1.05*d)**2

    rng = random.Random(seed)
    nbin = [max(1, int(L//(1.05*d))) for L in box]
    bins = {}
    pts = []
    tries = 0
    while len(pts) < n:
        tries += 1
        if tries > 200*n:
            raise SystemExit('makeSuspension.py: cannot place %d spheres' % n)
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
                    for q in bins.get(tuple(key), ()):
                        dd = 0
                        for k in range(3):
                            dk = abs(p[k] - q[k])
                            if periodic[k]:
                                dk = min(dk, box[k] - dk)
                            dd += dk*dk
                        if dd < gap2:
                            ok = False
        if ok:
            pts.append(p)
            bins.setdefault(tuple(b), []).append(p)

    write_data(out, pts, d, box, '%d random spheres (makeSuspension.py)' % n)

if __name__ == '__main__':
    main()
