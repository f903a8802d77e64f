#!/bin/bash
# Upward flow through the fixed random packed bed (makePack.sh) with
# two-way coupling: the pressure drop across the bed's interior against
# Ergun's equation (the tutorial's bedPressureDrop.py).
#
# usage: [COLLOIDFOAM_KERNEL=satellite|cellPoint] runPackedBedTest.sh A|B Us packDir workDir [nProcs [serialDir]]
#   Us: superficial velocity [m/s]; nProcs 2: decomposePar (METIS) and
#   mpirun -np 2, then reconstructPar
set -e
model=$1
Us=$2
pack=$3
work=$4
nProcs=${5:-1}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/prepareCase.sh"
cp -r 0.orig 0
sed -i "s/^Us .*;/Us $Us;/" 0/U
setModel "$model"
setKernel "${COLLOIDFOAM_KERNEL:-}"
blockMesh > log.blockMesh 2>&1

runSolver "$nProcs"
postProcess -func writeCellCentres -latestTime > log.writeCellCentres 2>&1

python3 "$COLLOIDFOAM_TUTORIALS/twoWay/packedBed/bedPressureDrop.py" "$work" "$Us" ${6:-}
