#!/usr/bin/env python3
"""Random spheres for the shear-collision test (runShearTest.sh): N centres
uniformly in the band y0 < y < y1 of the box [0, Lx] x [0, Lz] (periodic in
x and z), no two closer than 2R + minGap, as LIGGGHTS create_atoms lines
(um).  A fixed seed: the same particles every run.

usage: makeShearParticles.py N R y0 y1 Lx Lz minGap > file"""
import math
import random
import sys


def main():
    n = int(sys.argv[1])
    R, y0, y1, Lx, Lz, gap = (float(v) for v in sys.argv[2:8])
    rng = random.Random(20261202)
    dmin = 2*R + gap
    cell = dmin
    grid = {}
    placed = []

    def key(p):
        return (int(p[0]//cell), int(p[1]//cell), int(p[2]//cell))

    nx, nz = int(Lx//cell), int(Lz//cell)
    tries = 0
    while len(placed) < n:
        tries += 1
        if tries > 200*n:
            sys.exit("makeShearParticles: cannot place %d spheres (placed %d)" % (n, len(placed)))
        p = (rng.uniform(0, Lx), rng.uniform(y0, y1), rng.uniform(0, Lz))
        k = key(p)
        ok = True
        for a in (-1, 0, 1):
            for b in (-1, 0, 1):
                for c in (-1, 0, 1):
                    for q in grid.get(((k[0] + a) % nx, k[1] + b, (k[2] + c) % nz), []):
                        dx = abs(p[0] - q[0]); dx = min(dx, Lx - dx)
                        dz = abs(p[2] - q[2]); dz = min(dz, Lz - dz)
                        if dx*dx + (p[1] - q[1])**2 + dz*dz < dmin*dmin:
                            ok = False
        if ok:
            placed.append(p)
            grid.setdefault((k[0] % nx, k[1], k[2] % nz), []).append(p)
    for x, y, z in placed:
        print("create_atoms 1 single %.9f %.9f %.9f units box" % (x, y, z))


if __name__ == "__main__":
    main()
