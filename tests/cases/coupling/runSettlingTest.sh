#!/bin/bash
# Particle settling in plane Poiseuille flow, run by colloidDEMFoam on a
# hex (blockMesh), tet (Kuhn-split hexes via gmshToFoam) or polyhedral
# (polyDualMesh of the tet mesh) mesh of the same channel, checked against
# the closed-form terminal velocity.
#
# usage: runSettlingTest.sh hex|tet|polyDual workDir
set -e
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
mesh=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

H=1e-4       # channel height [m] (system/blockMeshDict, makeTetMesh.py)
Umax=1e-3    # centre-line velocity [m/s]

rm -rf "$work"
mkdir -p "$(dirname "$work")"
cp -r "$here/case" "$work"
cd "$work"
rm -rf 0.orig

case $mesh in
    hex) blockMesh > log.blockMesh 2>&1 ;;
    tet) python3 "$here/makeTetMesh.py" channel.msh 10 20 5
         gmshToFoam channel.msh > log.gmshToFoam 2>&1 ;;
    polyDual)
         # Polyhedral cells around the points of the tet mesh
         python3 "$here/makeTetMesh.py" channel.msh 10 20 5
         gmshToFoam channel.msh > log.gmshToFoam 2>&1
         polyDualMesh 80 -overwrite > log.polyDualMesh 2>&1 ;;
    *)   echo "unknown mesh type $mesh"; exit 2 ;;
esac

mkdir -p 0
postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
python3 "$here/setPoiseuilleU.py" . $H $Umax

colloidDEMFoam > log.colloidDEMFoam 2>&1 || { tail -30 log.colloidDEMFoam; exit 1; }
grep "Particles:" log.colloidDEMFoam | tail -1

cd "$here"
python3 checkSettling.py "$work" $H $Umax
