"""Mean settling velocity of the particles in the middle of the column
(1.5 to 4.5 mm, away from the sediment and the top interface) against
time, beside Stokes' velocity of one sphere and Richardson & Zaki's
hindered settling v = v_s eps^4.65 (Re_p < 0.2) at the suspension's fluid
fraction; the fluid's mean upflow against the volume balance
eps u + (1 - eps) v = 0.  Writes settling.csv and settling.png.

Richardson, J.F. & Zaki, W.N. (1954), Trans. Inst. Chem. Eng. 32, 35.

usage: plotSettling.py   (Debian's /usr/bin/python3: matplotlib)
"""
import math
import os
import re
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', '..', 'src', 'python'))  # particleCloud
import particleCloud  # noqa: E402

Y0, Y1 = 1.5e-3, 4.5e-3          # the middle of the column [m]
AREA = 2e-3*2e-3                 # cross-section [m^2]


def number(text, key):
    return float(re.search(r'\b%s\s+([^;\s]+)\s*;' % key, text).group(1))


def main():
    props = open(os.path.join(HERE, 'constant', 'couplingProperties')).read()
    rho_f = number(props[props.index('fluid'):], 'rho')
    mu = number(props[props.index('fluid'):], 'mu')
    d = number(props[props.index('particles'):], 'diameter')
    rho_p = number(props[props.index('particles'):], 'density')
    v_s = (rho_p - rho_f)*9.81*d*d/(18*mu)

    rows = []
    for f in particleCloud.write_times(HERE):
        data = particleCloud.read(f)
        vy = [v[1] for x, v in zip(data['position'], data['velocity'])
              if Y0 < x[1] < Y1]
        if not vy:
            continue
        eps = 1 - len(vy)*math.pi/6*d**3/(AREA*(Y1 - Y0))
        rows.append((particleCloud.time(f), sum(vy)/len(vy), eps))
    rows = [r for r in rows if r[0] > 0]

    late = [r for r in rows if r[0] >= 0.25*rows[-1][0]]
    v_mean = sum(r[1] for r in late)/len(late)
    eps = sum(r[2] for r in late)/len(late)
    v_rz = v_s*eps**4.65

    with open(os.path.join(HERE, 'settling.csv'), 'w') as f:
        f.write('time_s,mean_settling_velocity_m_per_s,fluid_fraction\n')
        for r in rows:
            f.write('%.6g,%.6g,%.6f\n' % r)
    print('Stokes v_s %.4g m/s; Richardson-Zaki at eps %.4f: %.4g m/s;'
          ' colloidDEMFoam (mean from t = %.3g s): %.4g m/s (%+.1f %%)'
          % (v_s, eps, v_rz, late[0][0], -v_mean, 100*(-v_mean/v_rz - 1)))

    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    t = [r[0] for r in rows]
    ax.plot(t, [-r[1]*1e3 for r in rows], 'o-', color='C3', ms=3,
            label='colloidDEMFoam: mean of the particles at 1.5-4.5 mm')
    ax.axhline(v_s*1e3, color='k', ls=':', label='Stokes, one sphere')
    ax.axhline(v_rz*1e3, color='k', ls='-',
               label='Richardson & Zaki, $v_s\\,\\varepsilon^{4.65}$, '
                     '$\\varepsilon$ = %.3f' % eps)
    ax.set_xlabel('time [s]')
    ax.set_ylabel('settling velocity [mm/s]')
    ax.set_ylim(0, 1.15*v_s*1e3)
    ax.set_title('4584 spheres of 100 um, 10 % solids, two-way coupled')
    ax.grid(True, alpha=0.3)
    ax.legend(loc='lower right')
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, 'settling.png'), dpi=120)
    print('wrote settling.csv, settling.png')


if __name__ == '__main__':
    main()
