#!/bin/bash
# Fluid fraction of the packed bed (makePack.sh) on a hex, tet or
# polyhedral mesh of its column (cells 2.5 diameters wide: particles
# straddle cells and, on 2 ranks, processor boundaries), after one
# coupling step: bounds, the solid volume of the field against the
# particles' volume, and the sampling against the transpose of the
# deposit (checkFluidFraction.py).  With a serial run's folder as
# reference, the reconstructed field must equal the serial one.
#
# usage: [COLLOIDFOAM_KERNEL=satellite|cellPoint] runFluidFractionTest.sh hex|tet|polyDual packDir workDir [nProcs [serialDir [movedTolerance]]]
set -e
mesh=$1
pack=$2
work=$3
nProcs=${4:-1}
serial=${5:-}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/prepareCase.sh"
rm -rf 0.orig
mkdir 0
cp "$here/fraction/U" "$here/fraction/p" 0/
foamDictionary system/controlDict -entry endTime -set 1e-5 > /dev/null
foamDictionary system/controlDict -entry writeInterval -set 1 > /dev/null
setKernel "${COLLOIDFOAM_KERNEL:-}"
checkTranspose

case $mesh in
    hex) cp "$here/fraction/blockMeshDict" system/
         blockMesh > log.blockMesh 2>&1 ;;
    tet|polyDual)
         # makeTetMesh.py's 100 x 100 x 50 um box in 4 x 14 x 4 hexahedra
         # (6 tets each), stretched onto the column
         python3 "$here/../coupling/makeTetMesh.py" column.msh 4 14 4
         gmshToFoam column.msh > log.gmshToFoam 2>&1
         transformPoints -scale '(10 35 20)' > log.transformPoints 2>&1
         transformPoints -translate '(0 -0.0005 0)' >> log.transformPoints 2>&1
         if [ "$mesh" = polyDual ]
         then
             polyDualMesh 80 -overwrite > log.polyDualMesh 2>&1
         fi ;;
    *)   echo "unknown mesh type $mesh"; exit 2 ;;
esac

runSolver "$nProcs"

python3 "$here/checkFluidFraction.py" "$work" $serial ${6:-}
