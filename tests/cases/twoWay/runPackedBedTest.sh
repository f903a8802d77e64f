#!/bin/bash
# Upward flow through the fixed random packed bed (makePack.sh) with
# two-way coupling: the pressure drop across the bed's interior against
# Ergun's equation (checkErgun.py).
#
# usage: runPackedBedTest.sh A|B Us packDir workDir [nProcs [serialDir]]
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
foamDictionary constant/couplingProperties -entry twoWay/modelType -set "$model" > /dev/null
if [ "$model" = B ]
then
    # Model B's drag (K/eps) carries the pressure gradient
    foamDictionary constant/couplingProperties -entry forceModels \
        -set "(gravityBuoyancy)" > /dev/null
fi
blockMesh > log.blockMesh 2>&1

if [ "$nProcs" -gt 1 ]
then
    decomposePar > log.decomposePar 2>&1
    mpirun -np "$nProcs" colloidDEMFoam -parallel > log.colloidDEMFoam 2>&1 \
        || { tail -30 log.colloidDEMFoam; exit 1; }
    reconstructPar -latestTime > log.reconstructPar 2>&1
else
    colloidDEMFoam > log.colloidDEMFoam 2>&1 || { tail -30 log.colloidDEMFoam; exit 1; }
fi
postProcess -func writeCellCentres -latestTime > log.writeCellCentres 2>&1

python3 "$here/checkErgun.py" "$work" "$Us" ${6:-}
