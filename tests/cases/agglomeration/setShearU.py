#!/usr/bin/env python3
"""Simple shear U_x = G (y - H/2) at the cell centres (0/Cy from
'postProcess -func writeCellCentres'), written to 0/U; the wall patches
zero-gradient (the test's particles stay five cells away from them, where
the cell-point interpolation of a linear field is exact).

usage: setShearU.py caseDir H G"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "coupling"))
from setPoiseuilleU import read_scalar_list  # noqa: E402


def main():
    case, H, G = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    ys = read_scalar_list(os.path.join(case, "0", "Cy"))
    with open(os.path.join(case, "0", "U"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class volVectorField;"
                " location \"0\"; object U; }\n")
        f.write("dimensions [0 1 -1 0 0 0 0];\n")
        f.write("internalField nonuniform List<vector> %d\n(\n" % len(ys))
        for y in ys:
            f.write("(%.15g 0 0)\n" % (G*(y - 0.5*H)))
        f.write(");\n")
        f.write("boundaryField\n{\n"
                "    walls { type zeroGradient; }\n"
                "    sides { type zeroGradient; }\n}\n")
    for name in ("C", "Cx", "Cy", "Cz"):
        os.remove(os.path.join(case, "0", name))


if __name__ == "__main__":
    main()
