#!/usr/bin/env python3
"""Simple shear U_x = G (y - H/2) at the cell centres (0/Cy from
'postProcess -func writeCellCentres'), written to 0/U; the wall patches
zero-gradient (the test's particles stay five cells away from them, where
the cell-point interpolation of a linear field is exact).

usage: setShearU.py caseDir H G"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "coupling"))
from setPoiseuilleU import write_profile  # noqa: E402


def main():
    case, H, G = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    write_profile(case, lambda y: G*(y - 0.5*H), "type zeroGradient;")


if __name__ == "__main__":
    main()
