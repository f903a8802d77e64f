#!/bin/bash
# Particles inserted in the middle of a coupling interval feel the fluid
# from their first DEM step: the settling case of runSettlingTest.sh, with
# four more particles inserted at rest at DEM step 15 by 'fix insert/pack'
# (coupling interval 10 steps: halfway through the second).  Each follows
# v(t) = (U_x(y_p), -v_s, 0)(1 - exp(-(t - t_i)/tau)) from its insertion
# (checkInsertedDrag.py); before the plugin's drag callback it had no
# drag, gravity or buoyancy until the exchange at step 20.  serial, or
# parallel: 2 ranks, the fluid split in x, LIGGGHTS in y (the inserted
# particles lie on both DEM ranks, their fluid on one).
#
# usage: runInsertedDragTest.sh serial|parallel workDir
set -e
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
mode=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

H=1e-4          # channel height [m] (system/blockMeshDict)
Umax=1e-3       # centre-line velocity [m/s]
insertStep=15   # DEM step of the insertion (not a multiple of couplingInterval)
nInserted=4

rm -rf "$work"
mkdir -p "$(dirname "$work")"
cp -r "$here/case" "$work"
cd "$work"
cat >> constant/DEM/in.liggghts <<EOT

# $nInserted particles inserted at rest at step $insertStep, away from the
# first (insert/pack's own keywords must follow 'start')
fix             insTemplate all particletemplate/sphere 15485863 atom_type 1 &
                density constant \${colloid_density} radius constant \${colloid_radius}
fix             insDistribution all particledistribution/discrete 32452843 1 insTemplate 1.0
region          insRegion block 60 90 40 90 10 40 units box
fix             insert all insert/pack seed 49979687 distributiontemplate insDistribution &
                insert_every once overlapcheck yes all_in yes start $insertStep &
                particles_in_region $nInserted region insRegion
EOT
blockMesh > log.blockMesh 2>&1
mkdir -p 0
postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
python3 "$here/setPoiseuilleU.py" . $H $Umax

case $mode in
    serial)
        colloidDEMFoam > log.colloidDEMFoam 2>&1 \
            || { tail -30 log.colloidDEMFoam; exit 1; } ;;
    parallel)
        sed -i 's/^create_box/processors      1 * 1\ncreate_box/' constant/DEM/in.liggghts
        decomposePar > log.decomposePar 2>&1
        mpirun -np 2 colloidDEMFoam -parallel > log.colloidDEMFoam 2>&1 \
            || { tail -30 log.colloidDEMFoam; exit 1; } ;;
    *)  echo "unknown mode $mode"; exit 2 ;;
esac
grep "inserted at DEM step" log.colloidDEMFoam || true

cd "$here"
python3 checkInsertedDrag.py "$work" $H $Umax $insertStep $nInserted
