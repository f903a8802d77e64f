#!/usr/bin/env python3
"""Prescribe the exact plane Poiseuille profile
    U_x(y) = 4 Umax y (H - y) / H^2,  U_y = U_z = 0
at the cell centres (read from 0/Cy, written by
'postProcess -func writeCellCentres') and write 0/U: no-slip walls,
zero gradient on the other patches.

usage: setPoiseuilleU.py caseDir H Umax
"""
import os
import re
import sys


def read_scalar_list(path):
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", text)
    if not m:
        sys.exit("setPoiseuilleU: no nonuniform internalField in " + path)
    n = int(m.group(1))
    values = text[m.end():].split(")")[0].split()
    if len(values) != n:
        sys.exit("setPoiseuilleU: expected %d values in %s" % (n, path))
    return [float(v) for v in values]


def write_profile(case, ux, walls):
    """0/U with U_x = ux(y) at the cell centres (0/Cy), U_y = U_z = 0,
    the walls patch as given (a boundaryField entry), zero gradient on the
    others; the cell-centre files are removed"""
    ys = read_scalar_list(os.path.join(case, "0", "Cy"))
    with open(os.path.join(case, "0", "U"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class volVectorField;"
                " location \"0\"; object U; }\n")
        f.write("dimensions [0 1 -1 0 0 0 0];\n")
        f.write("internalField nonuniform List<vector> %d\n(\n" % len(ys))
        for y in ys:
            f.write("(%.15g 0 0)\n" % ux(y))
        f.write(");\n")
        f.write("boundaryField\n{\n"
                "    walls { %s }\n"
                "    sides { type zeroGradient; }\n}\n" % walls)
    for name in ("C", "Cx", "Cy", "Cz"):
        os.remove(os.path.join(case, "0", name))


def main():
    case, H, Umax = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    write_profile(case, lambda y: 4*Umax*y*(H - y)/H**2,
                  "type fixedValue; value uniform (0 0 0);")


if __name__ == "__main__":
    main()
