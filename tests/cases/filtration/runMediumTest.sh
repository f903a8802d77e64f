#!/bin/bash
# The filter medium alone: the filtration case (test size) with one
# particle at the top of the column: the liquid passes the medium at the
# superficial velocity of Darcy's law, q = dp/(mu R_FM), within 0.1 %
# (the particle's drag takes 1e-5 of the pressure difference).  The
# medium is a Darcy zone of two cells under the suspension: with the face
# pressures of two resistances in series it carries its whole
# resistance (with linear face values it carried 14 % less).
#
# usage: runMediumTest.sh workDir
set -e
work=$1
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../twoWay/caseFunctions.sh"
copyCase "$COLLOIDFOAM_TUTORIALS/filtration" "$work"
cp -r 0.orig 0
"$COLLOIDFOAM_TUTORIALS/filtration/prepareRun.sh" -testSize > log.prepareRun
# One sphere near the top of the column in place of the suspension
python3 - <<'PY'
lines = open('DEM/suspension.data').read().splitlines()
box = {l.split()[2][0]: [float(v) for v in l.split()[:2]]
       for l in lines if l.endswith(('xlo xhi', 'ylo yhi', 'zlo zhi'))}
atom = lines[lines.index('Atoms') + 2].split()   # id type d rho x y z
d = float(atom[2])
with open('DEM/suspension.data', 'w') as f:
    f.write('one particle near the top\n\n1 atoms\n1 atom types\n\n')
    for k in 'xyz':
        f.write('%g %g %slo %shi\n' % (box[k][0], box[k][1], k, k))
    f.write('\nAtoms\n\n1 1 %s %s %g %g %g\n' % (
        atom[2], atom[3], sum(box['x'])/2, box['y'][1] - d, sum(box['z'])/2))
PY
foamDictionary system/controlDict -entry endTime -set 2e-5 > /dev/null
blockMesh > log.blockMesh 2>&1
runSolver 1

python3 "$here/checkMedium.py" "$work"
