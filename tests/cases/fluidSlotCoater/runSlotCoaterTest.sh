#!/bin/bash
# Steady flow of the slot-coater tutorial (tutorials/slotCoater, default
# size), checked by checkSlotCoaterFlow.py: mass conservation and the
# Couette-Poiseuille profile under the downstream lip.
#
#   runSlotCoaterTest.sh MODE WORKDIR
#
# MODE  serial    blockMesh, simpleFoam
#       parallel  blockMesh, decomposePar, mpirun -np 2 simpleFoam -parallel,
#                 reconstructPar
# The tutorial is copied to WORKDIR (build tree) and run there with the
# same applications its Allrun uses; the source tree is not written.
set -e
here=$(cd "$(dirname "$0")" && pwd)
tutorial="$here/../../../tutorials/slotCoater"
mode=$1
work=$2

set +u
source "$here/../../../etc/bashrc" || exit 1

rm -rf "$work"
mkdir -p "$work"
cp -r "$tutorial/constant" "$tutorial/system" "$work"
cp -r "$tutorial/0.orig" "$work/0"
cd "$work"
# The tutorial's steady-flow step (its Allrun runs it in a case folder of
# its own with this controlDict)
cp system/controlDict.steadyFlow system/controlDict

run()
{
    echo "$*"
    "$@" > "log.$1" 2>&1 || { tail -20 "log.$1"; exit 1; }
}

run blockMesh
case "$mode" in
serial)
    run simpleFoam
    ;;
parallel)
    # METIS, as in the tutorial (Allwmake builds the real libmetisDecomp).
    run decomposePar
    echo "mpirun -np 2 simpleFoam -parallel"
    mpirun -np 2 simpleFoam -parallel > log.simpleFoam 2>&1 \
        || { tail -20 log.simpleFoam; exit 1; }
    run reconstructPar -latestTime
    ;;
*)
    echo "unknown mode $mode (serial or parallel)"
    exit 1
    ;;
esac
run postProcess -func writeCellCentres -latestTime
python3 "$here/checkSlotCoaterFlow.py" . 0.01
