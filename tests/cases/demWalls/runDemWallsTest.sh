#!/bin/bash
# Export the walls of a blockMesh box with writeDEMWalls and check the STL
# files against the box's exact area and volume (checkStlBox.py).
#
#   runDemWallsTest.sh MODE WORKDIR
#
# MODE  serial    hex mesh, one rank
#       parallel  hex mesh decomposed in two, mpirun -np 2 ... -parallel:
#                 the master must write every face of both ranks once
#       polyDual  the polyhedral dual of the hex mesh: polygonal faces
#                 fanned into triangles
#       refined   hex mesh, triangles refined to edges of at most 5 um
#                 (-maxEdge 5: the box's triangles are 12-22 um long);
#                 -maxEdge 0 is refused
# The case is copied to WORKDIR (build tree); the source tree is not written.
set -e
here=$(cd "$(dirname "$0")" && pwd)
mode=$1
work=$2

set +u
source "$here/../../../etc/bashrc" || exit 1

rm -rf "$work"
mkdir -p "$(dirname "$work")"
cp -r "$here/box" "$work"
cd "$work"

run()
{
    echo "$*"
    "$@" > "log.$1" 2>&1 || { tail -20 "log.$1"; exit 1; }
}

# Every side of the box is a wall except 'outlet' (a plain patch), which is
# selected by name: both selection routes are used.
scale=1e6
nTriangles=188      # 2 per quadrilateral: 2*2*(5*4 + 4*3 + 3*5)

run blockMesh
case "$mode" in
serial)
    run writeDEMWalls -scale $scale -walls -patches '(outlet)'
    ;;
parallel)
    run decomposePar
    echo "mpirun -np 2 writeDEMWalls -parallel"
    mpirun -np 2 writeDEMWalls -parallel -scale $scale -walls \
        -patches '(outlet)' > log.writeDEMWalls 2>&1 \
        || { tail -20 log.writeDEMWalls; exit 1; }
    if ls processor*/DEM > /dev/null 2>&1
    then
        echo "FAIL: DEM files written inside processor folders"
        exit 1
    fi
    ;;
polyDual)
    # Feature angle 45 degrees keeps the box's edges and corners
    run polyDualMesh 45 -overwrite
    run writeDEMWalls -scale $scale -walls -patches '(outlet)'
    nTriangles=-1
    ;;
refined)
    if writeDEMWalls -scale $scale -maxEdge 0 > log.writeDEMWalls.bad 2>&1
    then
        echo "FAIL: writeDEMWalls accepted -maxEdge 0"
        exit 1
    fi
    grep -q "maxEdge 0" log.writeDEMWalls.bad \
        || { echo "FAIL: no message naming -maxEdge 0"; cat log.writeDEMWalls.bad; exit 1; }
    [ ! -d DEM ] || { echo "FAIL: files written for -maxEdge 0"; exit 1; }
    run writeDEMWalls -scale $scale -walls -patches '(outlet)' -maxEdge 5
    nTriangles="-1 5"
    ;;
*)
    echo "unknown mode $mode (serial, parallel, polyDual or refined)"
    exit 1
    ;;
esac

python3 "$here/checkStlBox.py" DEM/meshes system/boxParameters $scale $nTriangles
