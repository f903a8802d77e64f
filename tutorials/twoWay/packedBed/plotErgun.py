"""Pressure gradient across the bed's interior against Ergun's equation,
for the runs of Allrun (runs/Us<velocity>): ergun.csv and ergun.png.

usage: plotErgun.py velocity...   (Debian's /usr/bin/python3: matplotlib)
"""
import os
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

import bedPressureDrop as bed  # noqa: E402


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    rows = []
    for us in sys.argv[1:]:
        case = os.path.join(here, 'runs', 'Us' + us)
        r = bed.analyse(case, float(us))
        rows.append(r)

    with open(os.path.join(here, 'ergun.csv'), 'w') as f:
        f.write('Us_m_per_s,Re_p,dp_per_L_Pa_per_m,ergun_Pa_per_m,error_percent,'
                'bed_porosity\n')
        for r in rows:
            f.write('%.6g,%.4g,%.6g,%.6g,%+.3f,%.4f\n' % (
                r['us'], r['re'], r['dp']/r['length'], r['ergun']/r['length'],
                100*(r['dp']/r['ergun'] - 1), r['eps_mean']))
    print('%-10s %-8s %-14s %-14s %s' % ('Us [m/s]', 'Re_p', 'dp/L [Pa/m]',
                                         'Ergun [Pa/m]', 'error'))
    for r in rows:
        print('%-10.3g %-8.3g %-14.6g %-14.6g %+.2f %%' % (
            r['us'], r['re'], r['dp']/r['length'], r['ergun']/r['length'],
            100*(r['dp']/r['ergun'] - 1)))

    fig, ax = plt.subplots(figsize=(6, 4.5))
    us = [r['us'] for r in rows]
    fine = [us[0]*(us[-1]/us[0])**(k/100) for k in range(101)]
    eps = sum(r['eps_mean'] for r in rows)/len(rows)
    ax.loglog(fine, [bed.ergun(eps, u) for u in fine], 'k-',
              label='Ergun (1952), porosity %.3f' % eps)
    ax.loglog(fine, [150*bed.MU*(1 - eps)**2*u/(eps**3*bed.D**2) for u in fine],
              'k:', label='viscous term alone (Blake-Kozeny)')
    ax.loglog(us, [r['dp']/r['length'] for r in rows], 'o', color='C3',
              label='colloidDEMFoam, two-way')
    ax.set_xlabel('superficial velocity $U_s$ [m/s]')
    ax.set_ylabel('pressure gradient across the bed [Pa/m]')
    ax.set_title('Fixed bed of 2300 spheres, d = 100 um')
    ax.grid(True, which='both', alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(here, 'ergun.png'), dpi=120)
    print('wrote ergun.csv, ergun.png')


if __name__ == '__main__':
    main()
