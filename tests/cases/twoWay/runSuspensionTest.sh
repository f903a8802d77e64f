#!/bin/bash
# The settlingSuspension tutorial at test size (20 coupling steps): the
# mean velocity of the particles in the middle of the column, serial and
# on 2 ranks (METIS), must agree within 0.1 % (checkSuspension.py).
#
# usage: [COLLOIDFOAM_KERNEL=satellite|cellPoint [COLLOIDFOAM_KERNEL_RADIUS=R]] runSuspensionTest.sh workDir [nProcs serialDir]
set -e
work=$1
nProcs=${2:-1}
serial=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/caseFunctions.sh"
copyCase "$COLLOIDFOAM_TUTORIALS/twoWay/settlingSuspension" "$work"
python3 "$COLLOIDFOAM_TUTORIALS/twoWay/makeSuspension.py" \
    constant/DEM/suspension.data 4584 100 2000 6000 2000 4711 column
cp -r 0.orig 0
foamDictionary system/controlDict -entry endTime -set 2e-3 > /dev/null
foamDictionary system/controlDict -entry writeInterval -set 20 > /dev/null
setKernel "${COLLOIDFOAM_KERNEL:-}" "${COLLOIDFOAM_KERNEL_RADIUS:-}"
blockMesh > log.blockMesh 2>&1

runSolver "$nProcs"

python3 "$here/checkSuspension.py" "$work" $serial
