"""Write a LIGGGHTS data file (units micro) of a flocculated suspension:
n spheres of one diameter (and, with --fines, n_f smaller ones, in the
flocs at random) grouped into flocs of floc_size spheres each,
the flocs at random places and orientations in a column (periodic in x
and z, walls at the y faces), the same file for the same seed.

Why flocs at t = 0: at the isoelectric point every Brownian encounter
sticks, and Smoluchowski's half-time for the first doubling,
3 mu/(4 k T n0), is about 140 s for 5.8 um spheres at 13 % solids: the
suspension that reaches the filter has flocculated for minutes, which
the simulation's milliseconds cannot reproduce.

Each floc is built by ballistic cluster-cluster aggregation (Jullien &
Kolb 1984; fractal dimension about 1.9): clusters, starting from single
spheres, are merged two at a time, smallest first; one approaches the
other along a random line with a random offset and stops where two of
their spheres first touch (centres exactly the sum of their radii apart).
Spheres of different flocs are at least 5 % of the smaller one's diameter
apart (until the gel below joins them); centres at least a radius plus 5 %
of the largest diameter from the y faces.

With the last argument "gel" the placed flocs then aggregate further,
cluster with cluster, until one network holds every sphere: what the
suspension becomes once its flocs fill space, m^(1 - 3/D) = 0.13 for
flocs of m spheres and fractal dimension D: m = 21 at D = 1.8 (diffusion-
limited), 34 at 1.9 (these flocs); with Smoluchowski's mean size 1 +
t/t_half, after 20 to 33 half-times (above), 47 to 77 minutes after the
pH is set.  The aggregation is diffusion-limited (Meakin 1983; Kolb,
Botet & Jullien 1983): a cluster, chosen with probability proportional
to its mobility m^(-1/D) (Stokes-Einstein with a radius growing as
m^(1/D), D = 1.8), steps a quarter of the smallest diameter in a random
direction
(at the y faces' margin the step's y part is cut short, so the cluster
slides along the wall) and, where one of its spheres first touches a
sphere of another cluster on the way, stops there (in contact) and
joins it.  The x and z periods must be at least 2.5 diameters (one image
of each sphere within a step's reach).

usage: makeFlocs.py out.data n diameter Lx Ly Lz seed floc_size [gel]
       [--fines n_f d_f]   (lengths in um)
"""
import math
import os
import random
import sys

# makeSuspension.py of the twoWay tutorials (also from a copy of this case)
sys.path.insert(0, os.path.join(os.environ.get(
    'COLLOIDFOAM_TUTORIALS',
    os.path.join(os.path.dirname(os.path.abspath(__file__)), '..')), 'twoWay'))
from makeSuspension import fines_option, least_distance, write_data  # noqa: E402


def unit_vector(rng):
    z = rng.uniform(-1, 1)
    t = rng.uniform(0, 2*math.pi)
    s = math.sqrt(1 - z*z)
    return (s*math.cos(t), s*math.sin(t), z)


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0]*b[0] + a[1]*b[1] + a[2]*b[2]


def centred(points):
    c = [sum(p[k] for p in points)/len(points) for k in range(3)]
    return [sub(p, c) for p in points]


def merge(a, b, rng):
    """Cluster b brought to a along a random line until first contact; a
    cluster is (centres, diameters)."""
    (a, da), (b, db) = a, b
    d = max(da + db)
    ra = max(math.sqrt(dot(p, p)) for p in a)
    rb = max(math.sqrt(dot(p, p)) for p in b)
    while True:
        u = unit_vector(rng)
        # two unit vectors normal to u
        e1 = (u[1], -u[0], 0) if abs(u[2]) < 0.9 else (0, u[2], -u[1])
        n1 = math.sqrt(dot(e1, e1))
        e1 = (e1[0]/n1, e1[1]/n1, e1[2]/n1)
        e2 = (u[1]*e1[2] - u[2]*e1[1], u[2]*e1[0] - u[0]*e1[2],
              u[0]*e1[1] - u[1]*e1[0])
        r = (ra + rb + d)*math.sqrt(rng.random())
        t = rng.uniform(0, 2*math.pi)
        start = ra + rb + 2*d
        o = [start*u[k] + r*(math.cos(t)*e1[k] + math.sin(t)*e2[k])
             for k in range(3)]
        # b_j + o - s u touches a_i where |w - s u| = (d_i + d_j)/2,
        # w = b_j + o - a_i
        s_first = None
        for bj, dj in zip(b, db):
            bo = (bj[0] + o[0], bj[1] + o[1], bj[2] + o[2])
            for ai, di in zip(a, da):
                w = sub(bo, ai)
                wu = dot(w, u)
                contact = 0.5*(di + dj)
                disc = wu*wu - dot(w, w) + contact*contact
                if disc >= 0:
                    s = wu - math.sqrt(disc)
                    if s >= 0 and (s_first is None or s < s_first):
                        s_first = s
        if s_first is not None:
            moved = [(bj[0] + o[0] - s_first*u[0], bj[1] + o[1] - s_first*u[1],
                      bj[2] + o[2] - s_first*u[2]) for bj in b]
            return centred(a + moved), da + db


def floc(diameters, rng):
    """(centres, diameters) of a floc of spheres of these diameters."""
    clusters = [([(0.0, 0.0, 0.0)], [di]) for di in diameters]
    while len(clusters) > 1:
        clusters.sort(key=lambda c: len(c[0]))
        a, b = clusters[0], clusters[1]
        clusters = clusters[2:] + [merge(a, b, rng)]
    return clusters[0]

def separation(a, b, box):
    """a - b, x and z by the nearest periodic image."""
    w = [a[k] - b[k] for k in range(3)]
    for k in (0, 2):
        w[k] -= box[k]*round(w[k]/box[k])
    return w


class Bins:
    """Indices of points in cells at least `cell` wide, periodic in x and
    z: every point within `cell` of p is in the 27 cells around p's."""

    def __init__(self, box, cell):
        self.box = box
        self.n = [max(1, int(L//cell)) for L in box]
        self.cells = {}

    def key(self, p):
        return tuple(min(nb - 1, int(p[k]/self.box[k]*nb))
                     for k, nb in enumerate(self.n))

    def add(self, i, p):
        self.cells.setdefault(self.key(p), set()).add(i)

    def remove(self, i, p):
        self.cells[self.key(p)].discard(i)

    def near(self, p):
        b = self.key(p)
        seen = set()
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    kk = ((b[0] + dx) % self.n[0], b[1] + dy,
                          (b[2] + dz) % self.n[2])
                    if kk not in seen:
                        seen.add(kk)
                        yield from self.cells.get(kk, ())


# Fractal dimension of diffusion-limited cluster-cluster aggregates: the
# gel's clusters' mobility m^(-1/D)
DLCA_DIMENSION = 1.8


def aggregate(pts, diameters, flocs, box, margin, rng):
    """Join the clusters (lists of indices into pts, periodic in x and z)
    by diffusion-limited cluster-cluster aggregation until one is left;
    pts is changed in place.  Returns the number of moves."""
    step = 0.25*min(diameters)
    reach = max(diameters) + step   # centre distance within which a step
                                    # can bring two spheres into contact
    for k in (0, 2):
        if box[k] < 2*reach:
            raise SystemExit('makeFlocs.py: gel: the period %s = %g um is'
                             ' below 2.5 diameters (%g um)'
                             % ('xyz'[k], box[k], 2*reach))
    pos = [list(p) for p in pts]
    owner = {}
    members = {}
    for c, fl in enumerate(flocs):
        members[c] = list(fl)
        for i in fl:
            owner[i] = c
    bins = Bins(box, reach)
    for i, p in enumerate(pos):
        bins.add(i, p)

    moves = 0
    limit = 100*len(pts)       # moves; the tests' size takes 0.6 a sphere
                               # (486 for 795)
    while len(members) > 1:
        moves += 1
        if moves > limit:
            raise SystemExit('makeFlocs.py: %d clusters left after %d moves:'
                             ' no gel' % (len(members), limit))
        ids = list(members)
        c = rng.choices(ids, [len(members[k])**(-1/DLCA_DIMENSION)
                              for k in ids])[0]
        u = unit_vector(rng)
        # the step; its y part cut at the y margin (the cluster slides)
        move = [step*u[k] for k in range(3)]
        if move[1] > 0:
            move[1] = min(move[1], max(0.0, min(box[1] - margin - pos[i][1]
                                                for i in members[c])))
        elif move[1] < 0:
            move[1] = max(move[1], min(0.0, max(margin - pos[i][1]
                                                for i in members[c])))
        s_max = math.sqrt(dot(move, move))
        if s_max == 0:                   # straight into the wall
            continue
        u = [x/s_max for x in move]
        s_first, partner = s_max, None
        for i in members[c]:
            b = pos[i]
            for j in bins.near(b):
                if owner[j] == c:
                    continue
                w = separation(b, pos[j], box)
                wu = dot(w, u)
                contact = 0.5*(diameters[i] + diameters[j])
                disc = wu*wu - dot(w, w) + contact*contact
                if disc >= 0:
                    s = -wu - math.sqrt(disc)
                    if -1e-9*contact <= s < s_first:
                        s_first, partner = max(s, 0.0), j
        for i in members[c]:
            bins.remove(i, pos[i])
            for k in range(3):
                pos[i][k] += s_first*u[k]
            for k in (0, 2):
                pos[i][k] %= box[k]
                if pos[i][k] >= box[k]:      # -1e-17 % L is L
                    pos[i][k] = 0.0
            bins.add(i, pos[i])
        if partner is not None:
            other = owner[partner]
            for i in members[c]:
                owner[i] = other
            members[other] += members.pop(c)
    pts[:] = [tuple(p) for p in pos]
    return moves


def rotated(points, rng):
    """points turned by a random rotation (uniform quaternion)."""
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    q = (math.sqrt(1 - u1)*math.sin(2*math.pi*u2),
         math.sqrt(1 - u1)*math.cos(2*math.pi*u2),
         math.sqrt(u1)*math.sin(2*math.pi*u3),
         math.sqrt(u1)*math.cos(2*math.pi*u3))
    x, y, z, w = q
    m = ((1 - 2*(y*y + z*z), 2*(x*y - z*w), 2*(x*z + y*w)),
         (2*(x*y + z*w), 1 - 2*(x*x + z*z), 2*(y*z - x*w)),
         (2*(x*z - y*w), 2*(y*z + x*w), 1 - 2*(x*x + y*y)))
    return [tuple(dot(row, p) for row in m) for p in points]


def main():
    args, n_f, d_f = fines_option(sys.argv, 'makeFlocs.py')
    out = args[1]
    n, d = int(args[2]), float(args[3])
    box = [float(x) for x in args[4:7]]
    seed, size = int(args[7]), int(args[8])
    gelled = len(args) > 9 and args[9] == 'gel'
    if len(args) > 10 or (len(args) == 10 and not gelled):
        raise SystemExit('makeFlocs.py: unknown argument %s; usage: '
                         'makeFlocs.py out.data n diameter Lx Ly Lz seed '
                         'floc_size [gel] [--fines n_f d_f]'
                         % ' '.join(args[9:]))
    if size < 1:
        raise SystemExit('makeFlocs.py: floc size %d: at least 1' % size)
    if n_f and not d_f < d:
        raise SystemExit('makeFlocs.py: --fines diameter %g um: allowed'
                         ' below the spheres\' %g um' % (d_f, d))
    rng = random.Random(seed)
    # the spheres' diameters in the order the flocs take them: the fines
    # among the large spheres at random
    diameters = [d]*n + [d_f]*n_f
    if n_f:
        rng.shuffle(diameters)
    n += n_f
    margin = 0.55*d
    bins = Bins(box, least_distance(d, d))
    pts = []
    placed_diameters = []

    def free(p, dp):
        return all(dot(w, w) >= least_distance(dp, placed_diameters[j])**2
                   for j, w in ((j, separation(p, pts[j], box))
                                for j in bins.near(p)))

    sizes = [size]*(n//size) + ([n % size] if n % size else [])
    for m in sizes:
        body, body_diameters = floc(diameters[len(pts):len(pts) + m], rng)
        for tries in range(20000):
            shape = rotated(body, rng)
            lo = min(p[1] for p in shape)
            hi = max(p[1] for p in shape)
            if hi - lo > box[1] - 2*margin:
                raise SystemExit('makeFlocs.py: a floc of %d spheres is taller'
                                 ' than the column' % m)
            c = (rng.uniform(0, box[0]),
                 rng.uniform(margin - lo, box[1] - margin - hi),
                 rng.uniform(0, box[2]))
            placed = [((p[0] + c[0]) % box[0], p[1] + c[1],
                       (p[2] + c[2]) % box[2]) for p in shape]
            if all(free(p, dp) for p, dp in zip(placed, body_diameters)):
                for p, dp in zip(placed, body_diameters):
                    bins.add(len(pts), p)
                    pts.append(p)
                    placed_diameters.append(dp)
                break
        else:
            raise SystemExit('makeFlocs.py: cannot place floc %d of %d (%d'
                             ' spheres): fewer or smaller flocs, or a larger'
                             ' box' % (len(pts)//size + 1, len(sizes), m))

    if gelled:
        flocs = [list(range(k, k + m)) for k, m in
                 zip([sum(sizes[:j]) for j in range(len(sizes))], sizes)]
        moves = aggregate(pts, placed_diameters, flocs, box, margin, rng)
        title = ('%d spheres in one network: %d flocs joined by diffusion-'
                 'limited aggregation in %d moves (makeFlocs.py)'
                 % (n, len(sizes), moves))
    else:
        title = '%d spheres in %d flocs (makeFlocs.py)' % (n, len(sizes))
    if n_f:
        title += ', %d of them fines of %g um' % (n_f, d_f)
    write_data(out, pts, placed_diameters, box, title)

if __name__ == '__main__':
    main()
