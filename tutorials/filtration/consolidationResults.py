"""Results of a consolidation (consolidate.sh) in a filtration run folder:
the cake's packing density (solids volume fraction) at rest under each
piston pressure, and seed 002's compression function (eq. 14)

    eps_s(p) = eps_s0 (1 + p/p0)^beta,

fitted to them (p0 by a search over six decades, eps_s0 and beta by
least squares on ln eps_s against ln(1 + p/p0) for each p0; beta is the
compressibility index), and again with p0 held at consolidationCommonP0
of system/filtrationParameters (one p0 for both variants, so that their
beta compare).

Packing density: the particles' volume over the cross-section times the
piston's height above the medium (the cake's rough top included, as the
paper's wall on the highest particle).  At rest: the piston force within
2 % of pressure x area and the run did not stop on its step limit.

Writes consolidation.csv, consolidation.txt, consolidation.png (seed 002
Fig. 7: ln eps_s against ln(1 + p/p0)).

usage: consolidationResults.py runDir
"""
import math
import os
import sys

from filtrationResults import eval_entry, foam_entry

AT_REST = 0.02          # piston force against pressure x area


def main():
    run = sys.argv[1]
    params = os.path.join(run, 'system', 'filtrationParameters')
    area = (eval_entry(params, 'width')*1e-6)**2
    lines = open(os.path.join(run, 'DEM', 'cake.data')).read().splitlines()
    atoms = lines[lines.index('Atoms') + 2:]
    solid = sum(math.pi/6*(float(a.split()[2])*1e-6)**3 for a in atoms
                if a.strip())
    rows = []
    for line in open(os.path.join(run, 'DEM', 'consolidation.dat')):
        if line.startswith('#') or not line.strip():
            continue
        p, force, height, steps = [float(x) for x in line.split()]
        rows.append(dict(p=p, force=force, height=height, steps=int(steps),
                         eps_s=solid/(area*height),
                         force_error=force/(p*area) - 1))
    # Every pressure of the list reached, else the DEM stopped early (killed,
    # or failed): no fit of a part
    wanted = foam_entry(params, 'consolidationPressures').strip('()').split()
    if len(rows) != len(wanted):
        sys.exit('consolidationResults.py: %s holds %d of the %d pressures of'
                 ' %s consolidationPressures: the consolidation did not finish'
                 ' (see log.consolidation)'
                 % (os.path.join(run, 'DEM', 'consolidation.dat'), len(rows),
                    len(wanted), params))
    step_limit = eval_entry(params, 'consolidationStepLimit')
    for r in rows:
        r['at_rest'] = abs(r['force_error']) <= AT_REST and r['steps'] < step_limit

    # eq. 14: for each p0 a straight line ln eps_s = ln eps_s0 + beta x
    def line_fit(p0):
        xs = [math.log(1 + r['p']/p0) for r in rows]
        ys = [math.log(r['eps_s']) for r in rows]
        n = len(xs)
        mx, my = sum(xs)/n, sum(ys)/n
        sxx = sum((x - mx)**2 for x in xs)
        sxy = sum((x - mx)*(y - my) for x, y in zip(xs, ys))
        beta = sxy/sxx
        a = my - beta*mx
        ss = sum((y - a - beta*x)**2 for x, y in zip(xs, ys))
        return ss, beta, a
    best = min((line_fit(10**(3 + 6*k/600.0)) + (10**(3 + 6*k/600.0),)
                for k in range(601)), key=lambda f: f[0])
    ss, beta, a, p0 = best
    p0_common = eval_entry(params, 'consolidationCommonP0')
    if not p0_common > 0:
        sys.exit('consolidationResults.py: %s consolidationCommonP0 is %g;'
                 ' allowed range: > 0 Pa' % (params, p0_common))
    _, beta_common, a_common = line_fit(p0_common)
    ys = [math.log(r['eps_s']) for r in rows]
    my = sum(ys)/len(ys)
    r2 = 1 - ss/sum((y - my)**2 for y in ys) if len(ys) > 2 else float('nan')

    with open(os.path.join(run, 'consolidation.csv'), 'w') as f:
        f.write('pressure_Pa,piston_force_N,force_error,piston_height_m,'
                'packing_density,steps,at_rest\n')
        for r in rows:
            f.write('%g,%.6g,%.5f,%.6g,%.5f,%d,%s\n' % (
                r['p'], r['force'], r['force_error'], r['height'],
                r['eps_s'], r['steps'], 'yes' if r['at_rest'] else 'no'))
    results = [('packing_densities', ' '.join('%.4f' % r['eps_s'] for r in rows)),
               ('all_at_rest', 'yes' if all(r['at_rest'] for r in rows) else 'no'),
               ('largest_force_error', '%.4f' % max(abs(r['force_error'])
                                                    for r in rows)),
               ('eps_s0', '%.4f' % math.exp(a)),
               ('p0_Pa', '%.4g' % p0),
               ('compressibility_index', '%.4f' % beta),
               ('fit_r2', '%.4f' % r2),
               ('common_p0_Pa', '%.4g' % p0_common),
               ('eps_s0_at_common_p0', '%.4f' % math.exp(a_common)),
               ('compressibility_index_at_common_p0', '%.4f' % beta_common)]
    with open(os.path.join(run, 'consolidation.txt'), 'w') as f:
        for k, v in results:
            f.write('%s %s\n' % (k, v))
    for k, v in results:
        print('%-28s %s' % (k, v))

    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        print('consolidationResults.py: no matplotlib (python3-matplotlib): no PNG')
        return
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].plot([r['p']*1e-3 for r in rows], [r['eps_s'] for r in rows], 'o-')
    ax[0].set(xlabel='piston pressure [kPa]', ylabel='packing density',
              title='Consolidation')
    xs = [math.log(1 + r['p']/p0) for r in rows]
    ax[1].plot(xs, ys, 'o', label='run')
    ax[1].plot(xs, [a + beta*x for x in xs], 'k--',
               label='eq. 14: beta = %.3f, p0 = %.3g Pa' % (beta, p0))
    ax[1].set(xlabel='ln(1 + p/p0)', ylabel='ln packing density',
              title='Compressibility (seed 002 Fig. 7)')
    ax[1].legend()
    fig.tight_layout()
    fig.savefig(os.path.join(run, 'consolidation.png'), dpi=90)


if __name__ == '__main__':
    main()
