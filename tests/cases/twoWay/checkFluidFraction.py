"""Fluid fraction after one coupling step of a two-way run.

- Every cell's fluid fraction lies in [epsilonMin, 1] (couplingProperties).
- The field's solid volume sum((1 - eps) V) equals the particles' volume
  to 1e-12 relative, for every step in the log ('Fluid fraction' lines:
  the coupling's sum over cells against its sum over the particles),
  and for the written field, with V from the mesh (writeCellVolumes) and
  the particles' volume from the DEM data file.
- The sampling is the transpose of the deposit: at every sample (the
  kernel's debug check in the log), sum over particles of volume x
  sampled fluid fraction equals sum over cells of the deposited solid
  volume x fluid fraction, to 1e-12 relative.
- With a reference case (serial run of the same mesh): the same field,
  cell by cell, to 1e-10 (the deposit does not depend on the
  decomposition); or, with a tolerance given, the solid volume placed in
  other cells than in the reference, sum(|eps - eps_ref| V), at most that
  fraction of the particles' volume (polyhedral meshes: near the corners
  of the domain the cells of a point found by a walk from either side of
  a processor boundary can differ, for a few satellite points).

usage: checkFluidFraction.py caseDir [referenceCaseDir [movedTolerance]]
"""
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..', 'fluidCommon'))
import foamFields  # noqa: E402


def field(case, name):
    t = foamFields.latest_time(case)
    return foamFields.read_internal_field(os.path.join(case, t, name))


def particle_volume(case):
    text = open(os.path.join(case, 'constant', 'DEM', 'bed.data')).read()
    atoms = text.split('Atoms')[1].split('Velocities')[0]
    d = [float(r.split()[2])*1e-6 for r in atoms.strip().splitlines() if r.strip()]
    return sum(math.pi/6*x**3 for x in d)


def main():
    case = sys.argv[1]
    reference = sys.argv[2] if len(sys.argv) > 2 else None
    moved_tol = float(sys.argv[3]) if len(sys.argv) > 3 else None
    ok = True

    eps_min = float(re.search(r'epsilonMin\s+([^;]+);', open(
        os.path.join(case, 'constant', 'couplingProperties')).read()).group(1))
    eps = field(case, 'voidfraction')
    lo, hi = min(eps), max(eps)
    print('fluid fraction in [%.6f, %.6f] (allowed [%g, 1])' % (lo, hi, eps_min))
    ok &= eps_min <= lo and hi <= 1

    log = open(os.path.join(case, 'log.colloidDEMFoam')).read()
    lines = re.findall(r'Fluid fraction: .*\(relative difference (\S+)\)', log)
    worst = max(float(x) for x in lines)
    print('log: %d steps, solid volume against particles: %.2e relative (max)'
          % (len(lines), worst))
    ok &= bool(lines) and worst <= 1e-12

    checks = re.findall(r'depositKernel: transpose check: .*\(relative difference (\S+)\)', log)
    worst = max(float(x) for x in checks) if checks else float('nan')
    print('log: %d samples, particles\' volume x sampled fluid fraction against'
          ' the cells\' deposited solid x fluid fraction: %.2e relative (max)'
          % (len(checks), worst))
    ok &= bool(checks) and worst <= 1e-12

    subprocess.run(['postProcess', '-case', case, '-func', 'writeCellVolumes',
                    '-latestTime'], check=True, stdout=subprocess.DEVNULL)
    vol = field(case, 'V')
    solid = math.fsum((1 - e)*v for e, v in zip(eps, vol))
    vp = particle_volume(case)
    rel = abs(solid/vp - 1)
    print('field: solid volume %.12g m^3, particles %.12g m^3 (%.2e relative;'
          ' the field is written with 12 digits)' % (solid, vp, rel))
    ok &= rel <= 1e-9

    if reference:
        ref = field(reference, 'voidfraction')
        diff = max(abs(a - b) for a, b in zip(eps, ref))
        moved = math.fsum(abs(a - b)*v for a, b, v in zip(eps, ref, vol))/vp
        print('against %s: max |eps - eps_ref| = %.2e over %d cells; solid'
              ' volume in other cells: %.2e of the particles\''
              % (reference, diff, len(ref), moved))
        ok &= len(ref) == len(eps)
        ok &= (diff <= 1e-10) if moved_tol is None else (moved <= moved_tol)

    print('PASS' if ok else 'FAIL')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
