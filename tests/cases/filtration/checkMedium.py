"""Superficial velocity through the clean filter medium against Darcy's
law q = dp/(mu R_FM), from the case's own system/filtrationParameters;
tolerance 0.1 %.

usage: checkMedium.py caseDir
"""
import glob
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', 'fluidCommon'))
import foamFields  # noqa: E402

TOL = 1e-3


def main():
    case = sys.argv[1]
    par = foamFields.read_parameters(
        os.path.join(case, 'system', 'filtrationParameters'))
    width = par['width']*1e-6
    q_ref = par['filtrationPressure']/(par['mu']*par['mediumResistance'])
    rows = [[float(x) for x in line.split()] for line in open(glob.glob(
        os.path.join(case, 'postProcessing', 'filtrate', '*',
                     'surfaceFieldValue.dat'))[0])
            if line.strip() and not line.startswith('#')]
    q = rows[-1][1]/width**2
    err = q/q_ref - 1
    print('superficial velocity %.6g m/s, Darcy dp/(mu R_FM) %.6g m/s:'
          ' %+.3f %% (tolerance %.1f %%)' % (q, q_ref, 100*err, 100*TOL))
    ok = abs(err) <= TOL
    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
