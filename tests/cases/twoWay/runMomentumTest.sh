#!/bin/bash
# Momentum of a closed two-way run: 200 spheres settling in a fully
# periodic box of water (checkMomentum.py).
#
# usage: [COLLOIDFOAM_KERNEL=satellite|cellPoint] runMomentumTest.sh A|B workDir
set -e
model=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/caseFunctions.sh"
copyCase "$here/periodicBox" "$work"
python3 "$COLLOIDFOAM_TUTORIALS/twoWay/makeSuspension.py" constant/DEM/suspension.data 200 50 1000 1000 1000 12345 periodic
setModel "$model"
setKernel "${COLLOIDFOAM_KERNEL:-}"
checkTranspose
blockMesh > log.blockMesh 2>&1
runSolver 1

python3 "$here/checkMomentum.py" "$work"
