#!/bin/bash
# Darcy: liquid driven by a pressure difference down through a fixed packed
# bed inside the filtration geometry (tutorials/filtration: cyclic sides,
# pressure above, the filter medium's Darcy zone below, flux measured at
# the outlet) gives the bed the permeability that the same bed gives in
# the packed-bed (Ergun) test (tutorials/twoWay/packedBed: one cell
# across, fixed upward inflow) within 3 %.  Re_p = 0.1 in both: the
# permeability mu q L/dp of the bed's interior, y = 0.625 .. 1.625 mm
# (cell centres in both meshes).
#
# usage: runDarcyTest.sh packDir workDir
set -e
pack=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
twoWay=$here/../twoWay

# 1. The packed-bed test's run of this bed at Us = 1e-3 m/s (it asserts
#    Ergun within 3 % itself)
rm -rf "$work"
mkdir -p "$work"
"$twoWay/runPackedBedTest.sh" A 1e-3 "$pack" "$work/packedBed" \
    > "$work/log.packedBed" 2>&1 || { cat "$work/log.packedBed"; exit 1; }

# 2. The same bed in the filtration case, its sizes scaled to the bed:
#    column 1 mm across in one cell (as the packed-bed case: the layers'
#    mean porosities set the drag; on 4 x 4 cells of 2.5 diameters across
#    the bed's own unevenness gave 20 % more permeability), 2.5 mm high in
#    cells of 0.25 mm; 100 um spheres;
#    1200 Pa across (about 1000 Pa in the medium, R_FM 1e9 1/m, and 190 Pa
#    in the bed at q = 1e-3 m/s)
source "$twoWay/caseFunctions.sh"
copyCase "$COLLOIDFOAM_TUTORIALS/filtration" "$work/filtration"
mkdir -p DEM
cp "$pack/bed.data" DEM/suspension.data
cp -r 0.orig 0
sed -i -e "s/^cellSize .*/cellSize 250;/" -e "s/^width .*/width 1000;/" -e "s/^nWidth .*/nWidth 1;/" \
    -e 's/^nUpper .*/nUpper 9;/' -e 's/^particleDiameter .*/particleDiameter 1e-4;/' \
    -e 's/^filtrationPressure .*/filtrationPressure 1200;/' \
    system/filtrationParameters
cp "$here/in.fixedBed" constant/DEM/in.liggghts
foamDictionary constant/couplingProperties -entry DEM/timeStep -set 1e-6 > /dev/null
foamDictionary constant/couplingProperties -entry DEM/couplingInterval -set 10 > /dev/null
foamDictionary constant/couplingProperties -entry twoWay/epsilonMin -set 0.1 > /dev/null
# 20 ms: ten times the column's approach to steady flow rho L/(mu R_total)
foamDictionary system/controlDict -entry deltaT -set 1e-5 > /dev/null
foamDictionary system/controlDict -entry endTime -set 2e-2 > /dev/null
foamDictionary system/controlDict -entry writeInterval -set 2000 > /dev/null
blockMesh > log.blockMesh 2>&1
runSolver 1
postProcess -func writeCellCentres -latestTime > log.writeCellCentres 2>&1

python3 "$here/checkDarcy.py" "$work/filtration" "$work/packedBed" 1e-3
