#!/bin/bash
# A particle carried by plane Poiseuille flow across the fluid's processor
# boundary (x = 50 um) in a 2-rank run, while LIGGGHTS splits its domain
# along y (the particle stays on DEM rank 0 and needs fluid data from rank
# 1 after the crossing).  Checks:
#  - it crosses (final x > 55 um) and is never lost to the fluid;
#  - incremental search does the work: at most 3 global searches in total
#    (one at the start, the crossing may need one per rank);
#  - its final velocity equals U_x(y_p) and -v_s within 1 % (closed form),
#    and the serial run of the same case within 1e-6 relative.
#
# usage: runParallelTest.sh workDir
set -e
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
work=$1
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

H=1e-4
Umax=1         # fast enough to cross ~20 um in 25 us

setup()
{
    rm -rf "$1"
    mkdir -p "$(dirname "$1")"
    cp -r "$here/case" "$1"
    cd "$1"
    # 25 us = 500 coupling steps of 25 DEM steps of 2e-9 s
    foamDictionary system/controlDict -entry endTime -set 2.5e-05 > /dev/null
    foamDictionary system/controlDict -entry deltaT -set 5e-08 > /dev/null
    foamDictionary system/controlDict -entry writeInterval -set 500 > /dev/null
    foamDictionary constant/couplingProperties -entry DEM/couplingInterval -set 25 > /dev/null
    sed -i 's/^create_box/processors      1 * 1\ncreate_box/' constant/DEM/in.liggghts
    blockMesh > log.blockMesh 2>&1
    mkdir -p 0
    postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
    python3 "$here/setPoiseuilleU.py" . $H $Umax
}

setup "$work/serial"
colloidDEMFoam > log.colloidDEMFoam 2>&1 || { tail -30 log.colloidDEMFoam; exit 1; }

setup "$work/parallel"
decomposePar > log.decomposePar 2>&1
mpirun -np 2 colloidDEMFoam -parallel > log.colloidDEMFoam 2>&1 \
    || { tail -30 log.colloidDEMFoam; exit 1; }

cd "$here"
python3 checkSettling.py "$work/parallel" $H $Umax
python3 checkCrossing.py "$work/serial" "$work/parallel"
