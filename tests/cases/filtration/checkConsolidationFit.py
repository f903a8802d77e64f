"""The fit of seed 002 eq. 14 in consolidationResults.py against packing
densities made by eq. 14 itself, eps_s = eps_s0 (1 + p/p0)^beta with
eps_s0 = 0.55, p0 = 4e5 Pa, beta = 0.07 at the case's five pressures (a
cake of one layer, the piston heights that give these densities):
- p0 held at consolidationCommonP0 = 4e5 Pa: beta and eps_s0 as made
  (within 1e-4, the printed digits);
- p0 free (a search over a grid of 2.3 % steps): p0 within one grid step
  of 4e5 Pa, beta within 0.002, R^2 1.0000;
- p0 held at 1e6 Pa (not the p0 of the data): beta and eps_s0 of the
  least-squares line of ln eps_s against ln(1 + p/1e6), computed here
  (within 1e-4), and beta differs from the free fit's;
- consolidationCommonP0 0: a non-zero exit naming the keyword and the
  allowed range, and no consolidation.txt.

usage: checkConsolidationFit.py tutorialDir workDir
"""
import math
import os
import re
import sys

from checkConsolidationIncomplete import make_run, run_results

EPS0, P0, BETA = 0.55, 4e5, 0.07


def set_common_p0(run, value):
    path = os.path.join(run, 'system', 'filtrationParameters')
    text = re.sub(r'^consolidationCommonP0\s+[^;]+;',
                  'consolidationCommonP0 %s;' % value, open(path).read(),
                  flags=re.M)
    open(path, 'w').write(text)


def results(run):
    path = os.path.join(run, 'consolidation.txt')
    return dict(line.split(None, 1) for line in open(path)) \
        if os.path.exists(path) else {}


def main():
    tutorial, work = sys.argv[1], sys.argv[2]
    params = open(os.path.join(tutorial, 'system', 'filtrationParameters')).read()
    pressures = [float(p) for p in re.search(
        r'^consolidationPressures\s+\(([^)]*)\);', params, re.M).group(1).split()]
    ok = True

    run = os.path.join(work, 'eq14')
    # the densities of eq. 14 need the cake's solids volume: a first pass
    solid, area = make_run(tutorial, run, pressures)
    heights = [solid/(area*EPS0*(1 + p/P0)**BETA) for p in pressures]
    make_run(tutorial, run, pressures, heights=heights)
    set_common_p0(run, '%g' % P0)
    r = run_results(tutorial, run)
    res = results(run)
    print('eq. 14 with eps_s0 %g, p0 %g Pa, beta %g: exit %d' % (EPS0, P0, BETA, r.returncode))
    if r.returncode != 0 or not res:
        print(r.stdout)
        print('FAIL')
        return 1
    beta_c = float(res['compressibility_index_at_common_p0'])
    eps0_c = float(res['eps_s0_at_common_p0'])
    p0 = float(res['p0_Pa'])
    beta = float(res['compressibility_index'])
    r2 = float(res['fit_r2'])
    print('  p0 held at %g Pa: beta %.4f, eps_s0 %.4f' % (P0, beta_c, eps0_c))
    print('  p0 free: p0 %g Pa, beta %.4f, R^2 %.4f' % (p0, beta, r2))
    ok &= abs(beta_c - BETA) <= 1e-4 and abs(eps0_c - EPS0) <= 1e-4
    ok &= abs(p0/P0 - 1) <= 10**0.01 - 1 and abs(beta - BETA) <= 0.002
    ok &= r2 >= 0.99995

    other = os.path.join(work, 'otherP0')
    make_run(tutorial, other, pressures, heights=heights)
    set_common_p0(other, '1e6')
    r = run_results(tutorial, other)
    res = results(other)
    xs = [math.log(1 + p/1e6) for p in pressures]
    ys = [math.log(EPS0*(1 + p/P0)**BETA) for p in pressures]
    mx, my = sum(xs)/len(xs), sum(ys)/len(ys)
    b_ref = (sum((x - mx)*(y - my) for x, y in zip(xs, ys))
             / sum((x - mx)**2 for x in xs))
    e_ref = math.exp(my - b_ref*mx)
    b_other = float(res.get('compressibility_index_at_common_p0', 'nan'))
    e_other = float(res.get('eps_s0_at_common_p0', 'nan'))
    print('  p0 held at 1e6 Pa: beta %.4f (least squares here %.5f),'
          ' eps_s0 %.4f (%.5f)' % (b_other, b_ref, e_other, e_ref))
    ok &= (r.returncode == 0 and abs(b_other - b_ref) <= 1e-4
           and abs(e_other - e_ref) <= 1e-4 and abs(b_other - beta) > 1e-3)

    bad = os.path.join(work, 'badP0')
    make_run(tutorial, bad, pressures, heights=heights)
    set_common_p0(bad, '0')
    r = run_results(tutorial, bad)
    print('consolidationCommonP0 0: exit %d, %s' % (r.returncode, r.stdout.strip()))
    ok &= (r.returncode != 0 and 'consolidationCommonP0' in r.stdout
           and '> 0' in r.stdout and not results(bad))

    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
