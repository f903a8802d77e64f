#!/bin/bash
# A particle of the DEM outside the fluid mesh at the start (the coupling
# test case: mesh 100 x 100 x 50 um; the DEM box widened to x = 120 um and
# a second particle put at x = 110 um): the run goes on (it is legal: an
# insertion zone may lie outside the fluid) but warns, counting the
# particles outside and naming each by id and position.
#
#   runOutsideFluidTest.sh workDir
set -e
work=$1
here=$(cd "$(dirname "$0")" && pwd)
source "$here/testEnvironment.sh"

rm -rf "$work"
mkdir -p "$(dirname "$work")"
cp -r "$here/../coupling/case" "$work"
cd "$work"
sed -i 's/^region          domain block 0 100 /region          domain block 0 120 /' constant/DEM/in.liggghts
sed -i 's/^create_atoms .*/&\ncreate_atoms    1 single 110 40 20 units box/' constant/DEM/in.liggghts
foamDictionary system/controlDict -entry endTime -set 2e-08 > /dev/null
blockMesh > log.blockMesh 2>&1
mkdir -p 0
postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
python3 "$here/../coupling/setPoiseuilleU.py" . 1e-4 1e-3
colloidDEMFoam > log.colloidDEMFoam 2>&1 || { echo "FAIL: the run failed"; tail -20 log.colloidDEMFoam; exit 1; }

status=0
grep -a -A3 "particles of the DEM lie outside the fluid" log.colloidDEMFoam | head -4
grep -a -E -q "^ *1 particles of the DEM lie outside the fluid mesh at the start" log.colloidDEMFoam \
    || { echo "FAIL: no warning counting 1 particle outside the fluid"; status=1; }
grep -a -q "particle 2 at (0.00011 4e-05 2e-05) m" log.colloidDEMFoam \
    || { echo "FAIL: particle 2 at (110 40 20) um not named"; status=1; }
[ $status -eq 0 ] && echo PASS
exit $status
