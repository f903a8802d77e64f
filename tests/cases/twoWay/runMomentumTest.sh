#!/bin/bash
# Momentum of a closed two-way run: 200 spheres settling in a fully
# periodic box of water (checkMomentum.py).  With 'decay': no gravity, and
# the spheres start moving through still water (each at its own velocity
# about a common mean): the drag hands their momentum to the water, whose
# sum must come out unchanged once they move with it.
#
# usage: [COLLOIDFOAM_KERNEL=satellite|cellPoint] runMomentumTest.sh A|B workDir [decay]
set -e
model=$1
work=$2
variant=${3:-settling}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/caseFunctions.sh"
copyCase "$here/periodicBox" "$work"
python3 "$COLLOIDFOAM_TUTORIALS/twoWay/makeSuspension.py" constant/DEM/suspension.data 200 50 1000 1000 1000 12345 periodic
setModel "$model"
if [ "$variant" = decay ]
then
    foamDictionary constant/g -entry value -set "(0 0 0)" > /dev/null
    # [um/us = m/s]: a common mean and a spread (uniform on +-1 mm/s per
    # component, seeded), so that the particles also part from each other
    cat >> constant/DEM/in.liggghts <<'DEM'

variable        vx atom 2e-3+random(-1e-3,1e-3,15485863)
variable        vy atom -1e-3+random(-1e-3,1e-3,32452843)
variable        vz atom 5e-4+random(-1e-3,1e-3,49979687)
velocity        all set v_vx v_vy v_vz
DEM
fi
setKernel "${COLLOIDFOAM_KERNEL:-}"
checkTranspose
blockMesh > log.blockMesh 2>&1
runSolver 1

python3 "$here/checkMomentum.py" "$work"
