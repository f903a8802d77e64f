#!/usr/bin/env python3
"""Write a tetrahedral mesh of the test channel as a Gmsh 2.2 ASCII file
(for gmshToFoam): the box 100 x 100 x 50 um (walls at y = 0 and y = H)
cut into nx x ny x nz hexahedra, each split into 6 tetrahedra along its
main diagonal (Kuhn split: conforming between neighbours).

usage: makeTetMesh.py out.msh [nx ny nz]
"""
import itertools
import sys

L, H, W = 100e-6, 100e-6, 50e-6


def main():
    out = sys.argv[1]
    nx, ny, nz = (int(a) for a in sys.argv[2:5]) if len(sys.argv) > 4 else (10, 20, 5)

    def node(i, j, k):
        return 1 + i + (nx + 1)*(j + (ny + 1)*k)

    def coord(i, j, k):
        return (L*i/nx, H*j/ny, W*k/nz)

    nodes = [(node(i, j, k), coord(i, j, k))
             for k in range(nz + 1) for j in range(ny + 1) for i in range(nx + 1)]

    def volume6(a, b, c, d):
        pa, pb, pc, pd = (coord(*n) for n in (a, b, c, d))
        u = [pb[m] - pa[m] for m in range(3)]
        v = [pc[m] - pa[m] for m in range(3)]
        w = [pd[m] - pa[m] for m in range(3)]
        return (u[0]*(v[1]*w[2] - v[2]*w[1]) - u[1]*(v[0]*w[2] - v[2]*w[0])
                + u[2]*(v[0]*w[1] - v[1]*w[0]))

    tets = []
    for i, j, k in itertools.product(range(nx), range(ny), range(nz)):
        for perm in itertools.permutations(range(3)):
            corner = [i, j, k]
            path = [tuple(corner)]
            for axis in perm:
                corner[axis] += 1
                path.append(tuple(corner))
            a, b, c, d = path
            if volume6(a, b, c, d) < 0:
                c, d = d, c
            tets.append([node(*a), node(*b), node(*c), node(*d)])

    # Boundary quads split along the diagonal through their lowest corner,
    # as the Kuhn split does.  Physical 1: walls (y = 0, H), 2: sides.
    tris = []

    def quad(c00, c10, c11, c01, phys):
        tris.append((phys, [node(*c00), node(*c10), node(*c11)]))
        tris.append((phys, [node(*c00), node(*c11), node(*c01)]))

    for i, k in itertools.product(range(nx), range(nz)):
        for j in (0, ny):
            quad((i, j, k), (i + 1, j, k), (i + 1, j, k + 1), (i, j, k + 1), 1)
    for j, k in itertools.product(range(ny), range(nz)):
        for i in (0, nx):
            quad((i, j, k), (i, j + 1, k), (i, j + 1, k + 1), (i, j, k + 1), 2)
    for i, j in itertools.product(range(nx), range(ny)):
        for k in (0, nz):
            quad((i, j, k), (i + 1, j, k), (i + 1, j + 1, k), (i, j + 1, k), 2)

    with open(out, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
        f.write('$PhysicalNames\n3\n2 1 "walls"\n2 2 "sides"\n3 3 "fluid"\n$EndPhysicalNames\n')
        f.write("$Nodes\n%d\n" % len(nodes))
        for n, (x, y, z) in nodes:
            f.write("%d %.12g %.12g %.12g\n" % (n, x, y, z))
        f.write("$EndNodes\n$Elements\n%d\n" % (len(tris) + len(tets)))
        e = 0
        for phys, t in tris:
            e += 1
            f.write("%d 2 2 %d %d %d %d %d\n" % (e, phys, phys, *t))
        for t in tets:
            e += 1
            f.write("%d 4 2 3 3 %d %d %d %d\n" % (e, *t))
        f.write("$EndElements\n")


if __name__ == "__main__":
    main()
