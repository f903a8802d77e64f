#!/bin/bash
# One sphere settling in a closed box (walls 320 diameters away), two-way
# coupled: its terminal velocity against Stokes' (checkSettlingVelocity.py).
#
# usage: runSettlingTest.sh workDir cellDiameters x y z kernelCells selfInduced tolerance [nProcs serialDir]
#   cellDiameters: size of the cells around the particle in diameters
#   x y z: the particle's offset from the box centre in cell sizes
#   kernelCells: twoWay/kernelRadius in cell sizes (0: the particle's own)
#   selfInduced: twoWay/selfInducedVelocity (yes/no)
#   tolerance: allowed relative error of the terminal velocity
set -e
work=$1
cells=$2
ox=$3; oy=$4; oz=$5
kernel=$6
selfInduced=$7
tol=$8
nProcs=${9:-1}
serial=${10:-}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/caseFunctions.sh"
copyCase "$here/settling" "$work"

d=1e-4
delta=$(python3 -c "print($cells*$d)")
python3 "$here/makeSettlingMesh.py" . "$delta"
blockMesh > log.blockMesh 2>&1
# particle position [um] in the DEM box of 64 mm
pos=$(python3 -c "print(' '.join('%.6f' % (32000 + o*$delta*1e6) for o in ($ox, $oy, $oz)))")
sed -i "s/^create_atoms .*/create_atoms    1 single $pos units box/" constant/DEM/in.liggghts
foamDictionary constant/couplingProperties -entry twoWay/kernelRadius \
    -set "$(python3 -c "print($kernel*$delta)")" > /dev/null
foamDictionary constant/couplingProperties -entry twoWay/selfInducedVelocity \
    -set "$selfInduced" > /dev/null

runSolver "$nProcs"

python3 "$here/checkSettlingVelocity.py" "$work" "$tol" $serial
