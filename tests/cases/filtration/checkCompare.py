"""filtrationCompare.py's flocculation rows against Ruth's law (constant
pressure: t/V = a V + b, a = mu alpha c/(2 A^2 dp), b = mu R_FM/(A dp)),
on two hand-built runs that filter the same V_end = 4e-13 m^3 through the
same medium (b = 1.5e9 s/m^3), the flocculated cake with half the
stable one's slope (a = 4e20 against 8e20 s/m^6):

- the filtration time reduction is t_f/t_s - 1 with t = a V_end^2 +
  b V_end: (0.64 + 6)/(1.28 + 6) - 1 = -8.79 %;
- the reduction where the cake dominates is a_f/a_s - 1 = -50 %;
- the experiment's -51 % stands beside both;
and, without a medium (b = 0: the cake is all the resistance), the two
rows agree: both -50 %, the meaning of the second row.  Each to the
table's three digits.

The Ergun-equivalent diameter: each hand-built cake is given the
permeability of Ergun's bed (viscous term, k = eps^3 d^2/(150
(1 - eps)^2), written here forwards) of spheres of a known diameter at its
porosity, 5.8 um at 0.42 (stable) and 4.0 um at 0.5 (flocculated): the
table gives them back within its three digits (0.5 %); and each cell of
Table 2's columns, put back into the same law at that column's porosity,
gives the column's permeability within 0.5 % (the rounding of the
diameter to three digits, at most 0.26 % in k).

usage: checkCompare.py tutorials/filtration workDir
"""
import os
import subprocess
import sys

V_END, B = 4e-13, 1.5e9
SLOPES = {'stable': 8e20, 'flocculated': 4e20}
# (porosity, diameter of the Ergun bed [m]) of each hand-built cake
CAKES = {'stable': (0.42, 5.8e-6), 'flocculated': (0.5, 4.0e-6)}
# Seed 002 Table 2, (porosity, permeability [m^2]) by the table's column:
# stable experiment and simulation, flocculated experiment and simulation
TABLE2 = {1: (0.43, 2.47e-14), 2: (0.449, 3.0e-14), 4: (0.601, 13.8e-14),
          5: (0.654, 23.6e-14)}
ERGUN_LABEL = 'Ergun-equivalent diameter'
DIAMETER_TOL = 0.005


def ergun_permeability(eps, d):
    """Ergun's viscous term: the permeability [m^2] of a bed of spheres of
    diameter d [m] at porosity eps."""
    return eps**3*d*d/(150*(1 - eps)**2)


def write_run(folder, a, b, cake):
    os.makedirs(folder, exist_ok=True)
    t_end = a*V_END**2 + b*V_END
    values = {'particles': 795, 'filtration_time_s': t_end,
              'ruth_slope_s_m6': a, 'ruth_intercept_s_m3': b,
              'cake_porosity': cake[0],
              'permeability_m2': ergun_permeability(*cake),
              'mean_contact_force_N': 6.5e-7, 'coordination_number': 5.2,
              'cake_height_m': 4.2e-5, 'ruth_r2': 1.0,
              'medium_resistance_fitted_1_m': 1e9}
    with open(os.path.join(folder, 'results.txt'), 'w') as f:
        for key, value in values.items():
            f.write('%s %s\n' % (key, value))
    with open(os.path.join(folder, 'filtration.csv'), 'w') as f:
        f.write('time_s,filtrate_m3,t_over_V_s_m3,lowest_layer_porosity\n')
        for k in range(1, 11):
            v = V_END*k/10
            t = a*v*v + b*v
            f.write('%g,%g,%g,0.5\n' % (t, v, t/v))
    return t_end


def cell(table, label, column):
    row = next(l for l in table.splitlines() if l.startswith('| ' + label))
    return row.split('|')[column + 1].strip()


def main():
    tutorial, work = sys.argv[1], sys.argv[2]
    failures = 0
    for b in (B, 0.0):
        folder = os.path.join(work, 'medium' if b else 'noMedium')
        times = {v: write_run(os.path.join(folder, v), a, b, CAKES[v])
                 for v, a in SLOPES.items()}
        subprocess.run([sys.executable,
                        os.path.join(tutorial, 'filtrationCompare.py'),
                        'stable', 'flocculated'], cwd=folder, check=True,
                       stdout=subprocess.DEVNULL)
        table = open(os.path.join(folder, 'comparison.md')).read()
        time_row = '%.3g %%' % (100*(times['flocculated']/times['stable'] - 1))
        expected = {
            ('filtration time reduction by flocculation', 6): time_row,
            ('the same where the cake dominates', 6):
                '%.3g %%' % (100*(SLOPES['flocculated']/SLOPES['stable'] - 1)),
            ('filtration time reduction by flocculation', 4): '-51 %',
            ('the same where the cake dominates', 4): '-51 % (time)'}
        if not b:
            # no medium: the slopes' ratio is the times' ratio
            expected[('the same where the cake dominates', 6)] = time_row
        for (label, column), want in expected.items():
            got = cell(table, label, column)
            ok = got == want
            failures += not ok
            print('%s: b = %g, %s, column %d: %s (expected %s)'
                  % ('ok' if ok else 'FAIL', b, label, column, got, want))
        if not b:
            continue
        # the model's columns: the diameters the cakes were built with
        for column, v in ((3, 'stable'), (6, 'flocculated')):
            got = float(cell(table, ERGUN_LABEL, column))*1e-6
            want = CAKES[v][1]
            ok = abs(got/want - 1) <= DIAMETER_TOL
            failures += not ok
            print('%s: %s, column %d: %.4g um (built with %.4g um)'
                  % ('ok' if ok else 'FAIL', ERGUN_LABEL, column, got*1e6,
                     want*1e6))
        # Table 2's columns: back through Ergun's law to their permeability
        for column, (eps, k) in TABLE2.items():
            d = float(cell(table, ERGUN_LABEL, column))*1e-6
            ok = abs(ergun_permeability(eps, d)/k - 1) <= DIAMETER_TOL
            failures += not ok
            print('%s: %s, column %d: %.4g um gives k %.4g m^2 at eps %g'
                  ' (Table 2: %.4g)' % ('ok' if ok else 'FAIL', ERGUN_LABEL,
                                        column, d*1e6,
                                        ergun_permeability(eps, d), eps, k))
    if failures:
        sys.exit('%d failures' % failures)
    print('filtration comparison: all checks passed')


if __name__ == '__main__':
    main()
