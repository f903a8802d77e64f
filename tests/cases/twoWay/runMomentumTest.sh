#!/bin/bash
# Momentum of a closed two-way run: 200 spheres settling in a fully
# periodic box of water (checkMomentum.py).  With 'decay': no gravity, and
# the spheres start moving through still water (each at its own velocity
# about a common mean): the drag hands their momentum to the water, whose
# sum must come out unchanged once they move with it; 'decayLubricated':
# the same with lubrication between the particles.
#
# usage: [COLLOIDFOAM_KERNEL=satellite|cellPoint] runMomentumTest.sh A|B workDir [decay|decayLubricated]
set -e
model=$1
work=$2
variant=${3:-settling}
case "$variant" in
    settling|decay|decayLubricated) ;;
    *) echo "$0: variant $variant: settling, decay or decayLubricated" 1>&2; exit 1 ;;
esac
here=$(cd "$(dirname "$0")" && pwd)
source "$here/caseFunctions.sh"
copyCase "$here/periodicBox" "$work"
python3 "$COLLOIDFOAM_TUTORIALS/twoWay/makeSuspension.py" constant/DEM/suspension.data 200 50 1000 1000 1000 12345 periodic
setModel "$model"
if [ "$variant" = decay ] || [ "$variant" = decayLubricated ]
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
if [ "$variant" = decayLubricated ]
then
    # Lubrication between particles up to a gap of one diameter (far
    # beyond its physical range: here it only has to put most particles
    # into pairs, whose damping is internal, so that their drag impulse
    # comes through the implicit update's coupled path); micro units:
    # viscosity 1 = 1e-3 Pa s, cut-offs in um
    sed -i 's|^pair_style .*|fix lub1 all property/global liquidViscosity scalar 1.0\
fix lub2 all property/global lubricationInnerCutoff scalar 0.5\
fix lub3 all property/global lubricationOuterCutoff scalar 50\
pair_style      gran model hertz tangential history cohesion colloid/lub|' \
        constant/DEM/in.liggghts
fi
setKernel "${COLLOIDFOAM_KERNEL:-}"
checkTranspose
blockMesh > log.blockMesh 2>&1
runSolver 1

python3 "$here/checkMomentum.py" "$work" $([ "$variant" = decayLubricated ] && echo --lubricated)
