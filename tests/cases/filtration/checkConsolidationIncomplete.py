"""A consolidation that stopped before its last pressure (killed, or the
DEM failed) is an error of consolidationResults.py, not a fit of part of
the pressures: the tutorial's parameters, a cake of one layer and a
DEM/consolidation.dat holding 2 of the 5 pressures of
consolidationPressures.  Expected: a non-zero exit, a message naming
DEM/consolidation.dat, the count (2 of 5) and consolidationPressures, and
none of consolidation.csv, .txt, .png written.  A complete file of the
same rows and three more gives exit 0, consolidation.csv and .txt (the
.png too where matplotlib is there), so the failure above is the check,
not a broken fixture; every pressure at rest there.  The same complete
file, the run's consolidationStepLimit set to 100000 (not the tutorial's
2e6, so that the limit is seen to come from the case) and the third
pressure stopped on it (100000 steps): that pressure, and no other, is
not at rest in consolidation.csv, and consolidation.txt says all_at_rest
no.

usage: checkConsolidationIncomplete.py tutorialDir workDir
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

OUTPUTS = ('consolidation.csv', 'consolidation.txt', 'consolidation.png')


def make_run(tutorial, run, pressures, steps=None, heights=None):
    """A run folder: the tutorial's filtrationParameters, a cake of one
    layer, DEM/consolidation.dat with these pressures [Pa], steps and
    piston heights [m] (defaults: 30000, and 6 um falling by 0.1 um a
    step).  Returns the cake's solids volume [m^3] and cross-section
    [m^2]."""
    shutil.rmtree(run, ignore_errors=True)
    os.makedirs(os.path.join(run, 'system'))
    os.makedirs(os.path.join(run, 'DEM'))
    params = os.path.join(tutorial, 'system', 'filtrationParameters')
    shutil.copy(params, os.path.join(run, 'system'))
    # The case's width [um] (the one source); one layer of n x n spheres
    # of 5.8 um over its square
    width = float(re.search(r'^width\s+([0-9.eE+-]+);', open(params).read(),
                            re.M).group(1))
    n = int(width/5.8)
    with open(os.path.join(run, 'DEM', 'cake.data'), 'w') as f:
        f.write('one layer\n\n%d atoms\n1 atom types\n\n'
                '0 %g xlo xhi\n0 40 ylo yhi\n0 %g zlo zhi\n\nAtoms\n\n'
                % (n*n, width, width))
        for i in range(n*n):
            f.write('%d 1 5.8 2.5 %g 2.9 %g\n'
                    % (i + 1, 2.9 + 5.8*(i % n), 2.9 + 5.8*(i//n)))
    area = (width*1e-6)**2
    with open(os.path.join(run, 'DEM', 'consolidation.dat'), 'w') as f:
        f.write('# p_target_Pa force_N piston_height_m steps\n')
        for k, p in enumerate(pressures):
            f.write('%.17g %.17g %.17g %d\n' % (
                p, p*area, heights[k] if heights else 6.0e-6 - 0.1e-6*k,
                steps[k] if steps else 30000))
    return n*n*math.pi/6*(5.8e-6)**3, area


def at_rest(run):
    """The at_rest column of a run's consolidation.csv ([] without one)."""
    path = os.path.join(run, 'consolidation.csv')
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [row['at_rest'] for row in csv.DictReader(f)]


def run_results(tutorial, run):
    return subprocess.run(
        [sys.executable, os.path.join(tutorial, 'consolidationResults.py'),
         run], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
        universal_newlines=True)


def main():
    tutorial, work = sys.argv[1], sys.argv[2]
    ok = True

    partial = os.path.join(work, 'partial')
    make_run(tutorial, partial, [2e5, 4e5])
    r = run_results(tutorial, partial)
    print('2 of 5 pressures: exit %d, %s' % (r.returncode, r.stdout.strip()))
    for text in ('DEM/consolidation.dat', 'holds 2 of the 5 pressures',
                 'consolidationPressures'):
        if text not in r.stdout:
            print('  message lacks "%s"' % text)
            ok = False
    written = [o for o in OUTPUTS if os.path.exists(os.path.join(partial, o))]
    print('  written: %s' % (', '.join(written) or 'nothing'))
    ok &= r.returncode != 0 and not written

    complete = os.path.join(work, 'complete')
    make_run(tutorial, complete, [2e5, 4e5, 6e5, 8e5, 1e6])
    r = run_results(tutorial, complete)
    written = [o for o in OUTPUTS if os.path.exists(os.path.join(complete, o))]
    print('5 of 5 pressures: exit %d, written: %s'
          % (r.returncode, ', '.join(written)))
    ok &= r.returncode == 0 and set(OUTPUTS[:2]) <= set(written)
    rest = at_rest(complete)
    print('  at rest: %s' % ' '.join(rest))
    ok &= rest == ['yes']*5

    limit = 100000
    limited = os.path.join(work, 'limited')
    make_run(tutorial, limited, [2e5, 4e5, 6e5, 8e5, 1e6],
             [30000, 30000, limit, 30000, 30000])
    path = os.path.join(limited, 'system', 'filtrationParameters')
    text, n = re.subn(r'^consolidationStepLimit\s+[^;]+;',
                      'consolidationStepLimit %d;' % limit, open(path).read(),
                      flags=re.M)
    if n != 1:
        print('no consolidationStepLimit in %s' % path)
        return 1
    open(path, 'w').write(text)
    r = run_results(tutorial, limited)
    rest = at_rest(limited)
    summary = open(os.path.join(limited, 'consolidation.txt')).read() \
        if r.returncode == 0 else ''
    print('third pressure on the step limit (%d steps): exit %d, at rest: %s'
          % (limit, r.returncode, ' '.join(rest)))
    ok &= (r.returncode == 0 and rest == ['yes', 'yes', 'no', 'yes', 'yes']
           and re.search(r'^all_at_rest\s+no$', summary, re.M) is not None)

    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
