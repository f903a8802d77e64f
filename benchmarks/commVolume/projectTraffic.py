"""The table of benchmarks/commVolume and its projection to more ranks.

    projectTraffic.py DIR C INTERVAL N P1 P2 ... [-project P]

DIR holds traffic.np<P>.c<C>.<rank> and traffic.np<P>.c<2C>.<rank> (see
mpiTraffic.c) and case/log.liggghts.np<P> (each rank count's LIGGGHTS log:
its box and processor grid); C coupling steps of INTERVAL DEM steps; N
particles.

Projection (stated with the figures it prints):
  DEM      the bytes LIGGGHTS sends per DEM step are its ghost particles'
           (positions, velocities, the plugin's per-atom values): in
           proportion to the area of the cuts between subdomains times
           the particles' number density there.  Calibrated on the
           smallest parallel rank count, checked on the others, projected
           with the grid LIGGGHTS would choose (`processors * * 1`: the
           px x py that minimises a subdomain's cut area), the density
           taken uniform over the box (the die's solid lips hold none:
           the true figure depends on where the cuts fall).
  coupling the bytes per coupling step are per particle whose DEM rank is
           not the fluid rank that owns its cell (located there, its
           record sent and answered): the bytes per such particle from
           the largest rank count measured, times the share of such
           particles (the solver's Records line).  With the DEM's ranks
           matched to METIS' parts (demCoupling::chooseDEMDecomposition)
           that share
           comes from where the two decompositions' boundaries differ:
           estimated as the largest rank count's share times the ratio of
           the DEM grids' cut areas, at most 1 - 1/P (every particle but
           a rank's own share: the upper bound, as if the two were
           unrelated).  (The share is the run's mean since its start and
           N the particles after the first coupling step; the feed adds
           about 1 % over these runs.)
"""
import glob
import re
import sys

args = sys.argv[1:]
project = 64
if '-project' in args:
    i = args.index('-project')
    project = int(args[i + 1])
    del args[i:i + 2]
d, C, interval, N = args[0], int(args[1]), int(args[2]), int(args[3])
ranks = [int(p) for p in args[4:]]


def counts(p, c):
    """Per rank: {'world'|'dem': [p2pCalls, p2pBytes, collCalls, collBytes]}"""
    out = []
    for f in sorted(glob.glob('%s/traffic.np%d.c%d.*' % (d, p, c))):
        r = {'world': [0]*4, 'dem': [0]*4}
        for line in open(f):
            w = line.split()
            key = 'world' if w[1] == 'world' else 'dem'
            for k, i in enumerate((5, 7, 9, 11)):
                r[key][k] += int(w[i])
        out.append(r)
    if len(out) != p:
        sys.exit('commVolume: %d traffic files for %d ranks, %d coupling steps'
                 % (len(out), p, c))
    return out


def boxAndGrid(p):
    """LIGGGHTS' box lengths and processor grid of the run on p ranks"""
    log = open('%s/case/log.liggghts.np%d' % (d, p)).read()
    lo, hi = re.findall(r'orthogonal box = \((\S+) (\S+) (\S+)\) to \((\S+) (\S+) (\S+)\)',
                        log)[0][:3], re.findall(
        r'orthogonal box = \((\S+) (\S+) (\S+)\) to \((\S+) (\S+) (\S+)\)', log)[0][3:]
    L = [float(b) - float(a) for a, b in zip(lo, hi)]
    grid = [int(g) for g in re.findall(r'(\d+) by (\d+) by (\d+) MPI processor grid', log)[0]]
    return L, grid


def awayShare(p):
    """The share of the particles on another rank than their cells (the
    coupled run's log, longer run)"""
    log = open('%s/case/log.colloidDEMFoam.np%d.c%d' % (d, p, 2*C)).read()
    found = re.findall(r'Records: (\S+) % of the particles', log)
    return float(found[-1])/100 if found else 0.0


def cutArea(L, grid):
    """Area of the planes between subdomains (the periodic span's faces
    are there at any rank count: not counted)"""
    return sum((g - 1)*L[(k + 1) % 3]*L[(k + 2) % 3] for k, g in enumerate(grid))


def lammpsGrid(L, P):
    """px x py x 1 minimising a subdomain's cut area, as LIGGGHTS' grid"""
    best = None
    for px in range(1, P + 1):
        if P % px:
            continue
        py = P//px
        a = L[0]/px*L[2] + L[1]/py*L[2] + L[0]/px*L[1]/py
        if best is None or a < best[0]:
            best = (a, [px, py, 1])
    return best[1]


rows = {}
print()
print('Slot coater, %d particles; per step, from the difference of runs of %d and %d coupling'
      ' steps (%d DEM steps each)' % (N, C, 2*C, interval))
print()
print('%5s %9s | %12s %12s %10s %10s | %13s %12s %10s %7s %10s'
      % ('ranks', 'grid', 'DEM B/step', 'max rank', 'msgs/step', 'coll/step',
         'coupling B/cs', 'max rank', 'msgs/cs', 'away', 'B/away'))
for p in ranks:
    a, b = counts(p, C), counts(p, 2*C)

    def per(key, k, steps):
        v = [(b[r][key][k] - a[r][key][k])/steps for r in range(p)]
        return sum(v), max(v)
    dB, dBmax = per('dem', 1, C*interval)
    dM, _ = per('dem', 0, C*interval)
    dC, _ = per('dem', 2, C*interval)
    cB, cBmax = per('world', 1, C)
    cBc, _ = per('world', 3, C)
    cM, _ = per('world', 0, C)
    L, grid = boxAndGrid(p)
    away = awayShare(p)
    perAway = (cB + cBc)/(away*N) if away > 0 else 0
    rows[p] = (dB, cB + cBc, L, grid, perAway)
    print('%5d %9s | %12.0f %12.0f %10.1f %10.1f | %13.0f %12.0f %10.1f %6.1f%% %10.1f'
          % (p, 'x'.join(map(str, grid)), dB, dBmax, dM, dC, cB + cBc, cBmax, cM,
             100*away, perAway))
print()
print('DEM B/step: bytes sent per DEM step, all ranks (point-to-point); max rank: the largest')
print("rank's; msgs, coll: point-to-point messages and collective calls per step, all ranks;")
print('coupling B/cs: bytes per coupling step on MPI_COMM_WORLD (locating, records and their')
print('answers, reductions), all ranks; away: particles on another rank than their cells (the')
print("solver's Records line); B/away: coupling bytes per such particle.")

par = [p for p in ranks if p > 1]
if not par:
    sys.exit(0)
p0 = min(par)
dB0, _, L0, grid0, _ = rows[p0]
perArea = dB0/cutArea(L0, grid0)
print()
print('Projection (assumptions: projectTraffic.py)')
for p in par[1:]:
    dB, _, L, grid, _ = rows[p]
    model = perArea*cutArea(L, grid)
    print('  DEM, %d ranks (%s): %.0f B/step predicted from %d ranks, %.0f measured (%+.0f %%)'
          % (p, 'x'.join(map(str, grid)), model, p0, dB, 100*(model - dB)/dB))
gridP = lammpsGrid(L0, project)
demP = perArea*cutArea(L0, gridP)
pmax = max(par)
perParticle = rows[pmax][4]
awayMax = awayShare(pmax)
_, _, Lmax, gridMax, _ = rows[pmax]
awayP = min(1 - 1.0/project, awayMax*cutArea(L0, gridP)/cutArea(Lmax, gridMax))
couplingP = perParticle*N*awayP
couplingUpper = perParticle*N*(1 - 1.0/project)
print('  DEM, %d ranks (%s): %.3g B per DEM step, all ranks; %.3g per rank'
      % (project, 'x'.join(map(str, gridP)), demP, demP/project))
print('  coupling, %d ranks: %.0f %% of the particles on another rank (%.1f %% at %d ranks x the'
      ' cut areas\' ratio, at most 1 - 1/%d): %.3g B per coupling step, all ranks, %.3g per rank;'
      ' upper bound %.3g per rank (%.0f B per such particle, from %d ranks)'
      % (project, 100*awayP, 100*awayMax, pmax, project, couplingP, couplingP/project,
         couplingUpper/project, perParticle, pmax))
print('  per DEM step (coupling every %d DEM steps), per rank: DEM %.3g B, coupling %.3g B'
      % (interval, demP/project, couplingP/project/interval))
