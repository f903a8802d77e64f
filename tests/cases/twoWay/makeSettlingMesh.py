"""Write system/blockMeshDict of the settling box: a cube of side 64 mm
around (32, 32, 32) mm, with a central block of 8 x 8 x 8 (or nInner^3)
uniform cells of size delta and, outside it, cells growing geometrically
to the walls (so the walls are far, 320 particle diameters, at a few
thousand cells).

usage: makeSettlingMesh.py caseDir delta[m] [nInner]
"""
import os
import sys

L = 64e-3       # box side [m]
N_IN = 8        # uniform cells across the centre (default)
N_OUT = 6         # graded cells on each side


def main():
    case, delta = sys.argv[1], float(sys.argv[2])
    n_in = int(sys.argv[3]) if len(sys.argv) > 3 else N_IN
    inner = n_in*delta
    outer = 0.5*(L - inner)
    if outer <= N_OUT*delta:
        raise SystemExit('makeSettlingMesh.py: %d centre cells of %g m leave'
                         ' %g m to each wall, not more than %d cells of that'
                         ' size: fewer or smaller centre cells'
                         % (n_in, delta, outer, N_OUT))
    # first outer cell = delta: solve delta (r^n - 1)/(r - 1) = outer for r
    lo, hi = 1.0 + 1e-9, 10.0
    for _ in range(200):
        r = 0.5*(lo + hi)
        if delta*(r**N_OUT - 1)/(r - 1) < outer:
            lo = r
        else:
            hi = r
    ratio = r**(N_OUT - 1)       # last/first cell of a section
    f_out = outer/L
    grading = ('((%.10g %d %.10g) (%.10g %d 1) (%.10g %d %.10g))'
               % (f_out, N_OUT, 1/ratio, inner/L, n_in, f_out, N_OUT, ratio))
    n = n_in + 2*N_OUT
    text = """FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }

// Written by makeSettlingMesh.py: closed box of %(L)g m, centre cells of
// %(delta)g m (growth ratio %(r).4f outside)
convertToMeters 1;

vertices
(
    (0 0 0) (%(L)g 0 0) (%(L)g %(L)g 0) (0 %(L)g 0)
    (0 0 %(L)g) (%(L)g 0 %(L)g) (%(L)g %(L)g %(L)g) (0 %(L)g %(L)g)
);

blocks
(
    hex (0 1 2 3 4 5 6 7) (%(n)d %(n)d %(n)d)
    simpleGrading (%(g)s %(g)s %(g)s)
);

boundary
(
    walls
    {
        type wall;
        faces
        (
            (0 1 5 4) (3 7 6 2) (0 4 7 3) (1 2 6 5) (0 3 2 1) (4 5 6 7)
        );
    }
);
""" % dict(L=L, delta=delta, r=r, n=n, g=grading)
    with open(os.path.join(case, 'system', 'blockMeshDict'), 'w') as f:
        f.write(text)


if __name__ == '__main__':
    main()
