"""Results of one filtration run (a case folder of ./Allrun), as the
filtration engineer reads them: filtrate volume V(t) and t/V against V
with its straight-line fit (Ruth), cake height, porosity of the lowest
fluid-cell layer (seed 002 Fig. 6) and of the cake, the cake's
permeability from Darcy's law, mean contact force and coordination number.

Reads: system/filtrationParameters, constant/couplingProperties,
postProcessing/filtrate (flux through the bottom), postProcessing/
lowestLayer (its mean fluid fraction), <time>/lagrangian/particles,
DEM/contacts/.
Writes: filtration.csv (time series), filtration.png, results.txt.

Definitions (SI):
- cake height H_c: where the solids fraction, in slabs of one diameter
  from the medium up, first falls below 0.3 (the suspension has 0.13, a
  cake 0.35 to 0.6); the cake's particles are those below H_c + d (its
  rough top included).  (Not by velocity: the cake's contacts ring at up
  to 1 m/s while loaded.)  The filtration ends (t_f, V_f) at the first
  write with 99 % of the solids' volume in the cake (by volume: with
  fines, a count would be the fines'), or, where an open cake's rough
  top keeps more than 1 % of the solids above the cut, when the cake
  stops growing (end_of_filtration).
- cake porosity: 1 - (particle volume below H_c - d)/(A (H_c - d)), each
  sphere cut exactly by the plane: the rough top diameter left out.
- Ruth's law t/V = a V + b: a = mu alpha c/(2 A^2 dp), b = mu R_m/(A dp);
  fitted from V = 0.1 V_f (after the start-up) to V_f.  The fitted R_m is
  the filter medium's resistance as the run sees it (compare R_FM).
- permeability k = mu q H_c/dp_cake at the end of the run (Darcy's law
  across the cake), dp_cake the filtration pressure less the medium's
  drop mu R_FM q (the suspension is all in the cake by then).
- contacts: pairs that overlap (DEM/contacts: pairs within the surface
  forces' range are listed too); coordination number 2 N_c/N; mean
  contact force |F| over those pairs (the whole pair force); results.txt
  gives them at the latest contact dump of the run (contacts_time_s).

usage: filtrationResults.py <run folder>
"""
import glob
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ.get(
    'COLLOIDFOAM_DIR', os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                    '..', '..')), 'src', 'python'))
import particleCloud  # noqa: E402

SOLIDS_CUT = 0.3    # solids fraction at the cake's top: suspension 0.13,
                    # cakes 0.35 ... 0.6


def foam_entry(path, key):
    """The value of a plain 'key value;' line (no macros) in a dictionary."""
    for line in open(path):
        m = re.match(r'^\s*%s\s+([^;]+);' % re.escape(key), line)
        if m:
            return m.group(1).strip()
    raise SystemExit('filtrationResults.py: no %s in %s' % (key, path))


def eval_entry(path, key):
    """A parameter that may be '#eval{ ... }' of other parameters."""
    v = foam_entry(path, key)
    m = re.match(r'#eval\{(.*)\}', v)
    if not m:
        return float(v)
    expr = re.sub(r'\$(\w+)', lambda g: repr(eval_entry(path, g.group(1))),
                  m.group(1))
    return float(eval(expr, {'__builtins__': {}, 'round': round}))


def read_results(run):
    """{key: text} of a run's results.txt (written by main())."""
    out = {}
    for line in open(os.path.join(run, 'results.txt')):
        key, value = line.split(None, 1)
        out[key] = value.strip()
    return out


def read_series(run, function, file):
    """Rows of a function object's file over the whole run: a resumed run
    writes its rows under postProcessing/<function>/<start time>/; the
    folders are joined in time order, the rows of the run it resumed kept
    up to its start."""
    folders = glob.glob(os.path.join(run, 'postProcessing', function, '*'))
    rows = []
    for folder in sorted(folders, key=lambda f: float(os.path.basename(f))):
        # a later start replaces what an interrupted run wrote after it
        start = float(os.path.basename(folder))
        rows = [row for row in rows if row[0] <= start]
        rows += read_columns(os.path.join(folder, file))
    if not rows:
        raise SystemExit('no %s/*/%s in %s/postProcessing'
                         % (function, file, run))
    return rows


def read_columns(path):
    rows = []
    for line in open(path):
        if line.startswith('#') or not line.strip():
            continue
        rows.append([float(x) for x in line.split()])
    return rows


def read_particles(path):
    """time [s], positions and velocities [m, m/s], radii [m] of the
    particles of one write time (particleCloud: the solver's lagrangian
    cloud, serial, reconstructed or per processor)."""
    data = particleCloud.read(path)
    return (particleCloud.time(path), data['position'], data['velocity'],
            data['radius'])


def cap_volume(r, h):
    """Volume of a sphere of radius r below a plane h above its lowest point."""
    h = min(max(h, 0.0), 2*r)
    return math.pi*h*h*(3*r - h)/3


def cake_fraction(ys, radii, top):
    """Fraction of the solids' volume whose sphere centres lie below top
    (heights and radii in one unit): by volume, not by count, so that
    fines (eight 2.9 um spheres to one 5.8 um sphere's volume) do not
    decide alone when the suspension is gone."""
    total = sum(r**3 for r in radii)
    return sum(r**3 for y, r in zip(ys, radii) if y < top)/total


def latest_contacts(contacts, t_end):
    """(time, value) of the latest contact dump at or before t_end: the
    DEM dumps its contacts at the write interval, and an end time between
    two writes (-endTime) is written by the fluid only.  (nan, (nan, nan))
    without a dump."""
    times = [t for t in contacts if t <= t_end*(1 + 1e-9)]
    if not times:
        return float('nan'), (float('nan'),)*2
    return max(times), contacts[max(times)]


def end_of_filtration(series, still):
    """(t_f, how) from the cake fraction at each write, series = [(time,
    fraction), ...]: 'yes' at 99 % of the solids in the cake, linear in
    the fraction between the writes around it (the particles arrive at a
    nearly steady rate until the last: the filtrate's rate is steady),
    not the write interval's steps; 'stopped' at the first write from
    which the fraction, above 0.9, changes by less than still over each
    of the next two write intervals (the cake has stopped growing below
    99 %: the last flocs stand on the rough top of an open cake, above
    the cut; two, so that a pause between arriving flocs is not taken
    for the end; t_f then lies up to one write interval before the
    write, at the whole fraction the cake reaches, where 'yes' is at
    99 %); 'no' (t_f the last write) when neither happened."""
    for k, (t, c) in enumerate(series):
        if c >= 0.99:
            if k == 0:
                return t, 'yes'
            t0, c0 = series[k - 1]
            return t0 + (0.99 - c0)/(c - c0)*(t - t0), 'yes'
        if k + 2 < len(series) and c > 0.9 \
                and all(abs(series[j][1] - c) < still for j in (k + 1, k + 2)):
            return t, 'stopped'
    return series[-1][0], 'no'


def main():
    run = sys.argv[1]
    params = os.path.join(run, 'system', 'filtrationParameters')
    width = eval_entry(params, 'width')*1e-6
    area = width*width
    dp = eval_entry(params, 'filtrationPressure')
    mu = eval_entry(params, 'mu')
    r_fm = eval_entry(params, 'mediumResistance')
    d = eval_entry(params, 'particleDiameter')
    variant = foam_entry(params, 'variant')
    cpl = os.path.join(run, 'constant', 'couplingProperties')
    text = open(cpl).read()
    dt_dem = float(re.search(r'timeStep\s+([^;]+);', text).group(1))

    # Filtrate flow rate Q(t) [m^3/s] and volume V(t) (trapezoidal)
    flux = read_series(run, 'filtrate', 'surfaceFieldValue.dat')
    t_q = [0.0] + [r[0] for r in flux]
    q = [flux[0][1]] + [r[1] for r in flux]
    vol = [0.0]
    for k in range(1, len(t_q)):
        vol.append(vol[-1] + 0.5*(q[k] + q[k - 1])*(t_q[k] - t_q[k - 1]))

    def at(t, ts, ys):
        """ys at time t, linear between samples."""
        for k in range(1, len(ts)):
            if ts[k] >= t:
                w = (t - ts[k - 1])/(ts[k] - ts[k - 1])
                return ys[k - 1] + w*(ys[k] - ys[k - 1])
        return ys[-1]

    lowest = read_series(run, 'lowestLayer', 'volFieldValue.dat')

    # Particles at each write: the solids fraction in slabs of one
    # diameter (spheres cut exactly); the cake is the dense layer on the
    # medium, its top H_c where the profile first falls through SOLIDS_CUT
    # going up (between the suspension's and a cake's); a particle belongs
    # to the cake when its centre is below H_c + d; the cake fraction is
    # by volume
    snaps = [read_particles(path) for path in particleCloud.write_times(run)]
    n_particles = len(snaps[0][1])
    below = 0
    series = []
    profiles = []
    for time, pos, vel, rad in snaps:
        below = max(below, sum(1 for p, r in zip(pos, rad) if p[1] < 0))
        ys = [p[1] for p in pos]
        n_slabs = int(max(ys)/d) + 2
        solids = []
        for k in range(n_slabs):
            y0, y1 = k*d, (k + 1)*d
            vs = sum(cap_volume(r, y1 - (y - r)) - cap_volume(r, y0 - (y - r))
                     for y, r in zip(ys, rad) if y0 - r < y < y1 + r)
            solids.append(vs/(area*d))
        profiles.append(solids)
        h_c = 0.0
        for k in range(n_slabs - 1):
            if solids[k] >= SOLIDS_CUT > solids[k + 1]:
                w = (solids[k] - SOLIDS_CUT)/(solids[k] - solids[k + 1])
                h_c = (k + 0.5 + w)*d
                break
        in_cake = cake_fraction(ys, rad, h_c + d)
        h_in = h_c - d
        eps_c = float('nan')
        if h_in > d:
            vs = sum(cap_volume(r, h_in - (y - r)) for y, r in zip(ys, rad))
            eps_c = 1 - vs/(area*h_in)
        series.append([time, in_cake, h_c, eps_c])

    # Contacts at each write
    contacts = {}
    for path in glob.glob(os.path.join(run, 'DEM', 'contacts',
                                       'contacts_*.local')):
        step = int(re.search(r'contacts_(\d+)\.local', path).group(1))
        lines = open(path).read().split('\n')
        i = next(k for k, l in enumerate(lines) if l.startswith('ITEM: CONTACTS'))
        forces = []
        for l in lines[i + 1:]:
            c = l.split()
            if len(c) == 6 and float(c[5]) > 0:
                forces.append(math.sqrt(sum(float(x)**2 for x in c[2:5])))
        contacts[round(step*dt_dem, 12)] = (
            2.0*len(forces)/n_particles,
            1e-9*sum(forces)/len(forces) if forces else 0.0)   # nN -> N

    # End of filtration (end_of_filtration): the smallest sphere's share
    # of the solids volume, below which a change of the cake fraction
    # means no particle joined the cake
    smallest = min(snaps[0][3])
    share = smallest**3/sum(r**3 for r in snaps[0][3])
    t_f, ending = end_of_filtration([s[:2] for s in series], 0.5*share)
    finished = ending != 'no'
    v_f = at(t_f, t_q, vol)

    # Ruth's t/V = a V + b from 0.1 V_f to V_f
    pts = [(vol[k], t_q[k]/vol[k]) for k in range(1, len(t_q))
           if 0.1*v_f <= vol[k] <= v_f and t_q[k] <= t_f]
    n = len(pts)
    mx = sum(p[0] for p in pts)/n
    my = sum(p[1] for p in pts)/n
    sxx = sum((p[0] - mx)**2 for p in pts)
    sxy = sum((p[0] - mx)*(p[1] - my) for p in pts)
    syy = sum((p[1] - my)**2 for p in pts)
    a = sxy/sxx
    b = my - a*mx
    r2 = sxy*sxy/(sxx*syy)
    r_m_fit = b*area*dp/mu
    alpha_c = 2*a*area*area*dp/mu     # specific cake resistance x c [1/m^2]

    # Permeability across the cake at the end of the run (the suspension
    # is gone: the pressure difference less the medium's is the cake's)
    t_end = series[-1][0]
    h_end = series[-1][2]
    q_end = at(t_end, t_q, q)/area
    dp_cake = dp - mu*r_fm*q_end
    k_perm = mu*q_end*h_end/dp_cake if dp_cake > 0 else float('nan')
    eps_end = series[-1][3]
    t_contacts, (z_end, f_end) = latest_contacts(contacts, t_end)
    eps_low = lowest[-1][1]

    with open(os.path.join(run, 'filtration.csv'), 'w') as f:
        f.write('time_s,filtrate_m3,flowrate_m3_s,t_over_V_s_m3,'
                'cake_fraction,cake_height_m,cake_porosity,'
                'lowest_layer_porosity,coordination,mean_contact_force_N\n')
        for time, sf, h_c, eps_c in series:
            z, fm = contacts.get(round(time, 12), (float('nan'),)*2)
            v = at(time, t_q, vol)
            f.write('%.6g,%.6g,%.6g,%.6g,%.4f,%.6g,%.5f,%.5f,%.4f,%.5g\n' % (
                time, v, at(time, t_q, q), time/v if v > 0 else float('nan'),
                sf, h_c, eps_c, at(time, [r[0] for r in lowest],
                                   [r[1] for r in lowest]), z, fm))

    results = [
        ('variant', variant),
        ('particles', n_particles),
        ('particles_below_medium', below),
        ('filtration_finished', 'yes' if finished else 'no'),
        ('filtration_end', ending),
        ('filtration_time_s', '%.5g' % t_f),
        ('filtrate_volume_m3', '%.5g' % v_f),
        ('ruth_slope_s_m6', '%.5g' % a),
        ('ruth_intercept_s_m3', '%.5g' % b),
        ('ruth_r2', '%.5f' % r2),
        ('ruth_points', n),
        ('specific_cake_resistance_times_c_1_m2', '%.5g' % alpha_c),
        ('medium_resistance_fitted_1_m', '%.5g' % r_m_fit),
        ('medium_resistance_set_1_m', '%.5g' % r_fm),
        ('cake_height_m', '%.5g' % h_end),
        ('cake_porosity', '%.4f' % eps_end),
        ('lowest_layer_porosity', '%.4f' % eps_low),
        ('permeability_m2', '%.4g' % k_perm),
        ('cake_pressure_drop_Pa', '%.5g' % dp_cake),
        ('contacts_time_s', '%.5g' % t_contacts),
        ('coordination_number', '%.3f' % z_end),
        ('mean_contact_force_N', '%.4g' % f_end),
    ]
    with open(os.path.join(run, 'results.txt'), 'w') as f:
        for k, v in results:
            f.write('%s %s\n' % (k, v))
    for k, v in results:
        print('%-40s %s' % (k, v))

    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        print('filtrationResults.py: no matplotlib (python3-matplotlib): no PNG')
        return
    fig, ax = plt.subplots(2, 3, figsize=(14, 8))
    ms = [t*1e3 for t in t_q]
    ax[0][0].plot(ms, [v*1e12 for v in vol])
    ax[0][0].axvline(t_f*1e3, ls=':', c='k', label='end of filtration')
    ax[0][0].set(xlabel='t [ms]', ylabel='filtrate V [nL]',
                 title='Filtrate volume')
    ax[0][0].legend()
    vv = [vol[k]*1e12 for k in range(1, len(t_q)) if t_q[k] <= t_f]
    tv = [t_q[k]/vol[k] for k in range(1, len(t_q)) if t_q[k] <= t_f]
    ax[0][1].plot(vv, tv, label='run')
    ax[0][1].plot([p*1e12 for p, _ in pts], [a*p + b for p, _ in pts], 'k--',
                  label='fit: R^2 = %.4f' % r2)
    ax[0][1].set(xlabel='V [nL]', ylabel='t/V [s/m^3]',
                 title='t/V against V (Ruth)')
    ax[0][1].legend()
    st = [s[0]*1e3 for s in series]
    ax[0][2].plot(st, [s[2]*1e6 for s in series], 'o-')
    ax[0][2].set(xlabel='t [ms]', ylabel='H_c [um]', title='Cake height')
    ax[1][0].plot([r[0]*1e3 for r in lowest], [r[1] for r in lowest],
                  label='lowest fluid-cell layer')
    ax[1][0].plot(st, [s[3] for s in series], 'o', label='cake')
    ax[1][0].set(xlabel='t [ms]', ylabel='porosity', title='Porosity')
    ax[1][0].legend()
    ct = sorted(contacts)
    ax[1][1].plot([t*1e3 for t in ct], [contacts[t][0] for t in ct], 'o-')
    ax[1][1].set(xlabel='t [ms]', ylabel='coordination number',
                 title='Contacts per particle')
    ax[1][2].plot([t*1e3 for t in ct], [contacts[t][1]*1e6 for t in ct], 'o-')
    ax[1][2].set(xlabel='t [ms]', ylabel='mean |F| [uN]',
                 title='Mean contact force')
    fig.suptitle('Filtration, %s suspension: %d particles' % (variant,
                                                             n_particles))
    fig.tight_layout()
    fig.savefig(os.path.join(run, 'filtration.png'), dpi=90)


if __name__ == '__main__':
    main()
