#!/bin/bash
# The mesh-level test programs of the coupling library, each built with
# wmake into the work folder first:
#
#   locate       particleLocator against OpenFOAM's global search
#                (polyMesh::findCell) for 10^5 points each, on the tet
#                channel (convex: the incremental walk must never give up
#                for a point inside) and on a concave L-shaped hex mesh,
#                as built and with its points moved (warped faces), and
#                the wall distances against all wall faces;
#   interpolate  cellPointInterpolator against OpenFOAM's
#                interpolationCellPoint at 10^5 random points each, on the
#                channel's hex, tet and polyhedral (dual of the tet)
#                meshes, scaled to a height of 1 m (the reference is exact
#                only on metre-sized tets: interpolate/interpolateTest.C).
#
# usage: runMeshProgramTest.sh locate|interpolate workDir
set -e
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
program=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

case $program in
    locate|interpolate) ;;
    *) echo "usage: $0 locate|interpolate workDir" 1>&2; exit 2 ;;
esac

rm -rf "$work"
mkdir -p "$work/bin"
export COUPLING_TEST_BIN="$work/bin"
wmake -s "$here/$program" > "$work/log.wmake" 2>&1 || { tail -20 "$work/log.wmake"; exit 1; }

# channel mesh of the given kind (hex, tet, polyDual) in folder $1
channelMesh()
{
    cp -r "$here/case" "$1"
    (
        cd "$1"
        case $2 in
            hex) blockMesh > log.blockMesh 2>&1 ;;
            *)   python3 "$here/makeTetMesh.py" channel.msh 10 20 5
                 gmshToFoam channel.msh > log.gmshToFoam 2>&1
                 # gmshToFoam makes every patch a plain patch: the
                 # channel's walls (the locator's wall distances) are walls
                 sed -i '/^ *walls$/,/}/s/^\( *type *\)patch;/\1wall;/' \
                     constant/polyMesh/boundary ;;
        esac
        if [ "$2" = polyDual ]
        then
            polyDualMesh 80 -overwrite > log.polyDualMesh 2>&1
        fi
    )
}

status=0
if [ "$program" = locate ]
then
    channelMesh "$work/tet" tet
    echo "tet channel:"
    "$work/bin/locateTest" -convex -case "$work/tet" > "$work/tet/log.locateTest" 2>&1 || status=1
    grep -E "^(points|wall distances|walks|the wall|PASS|FAIL)" "$work/tet/log.locateTest" || true

    cp -r "$here/locate/lShape" "$work/lShape"
    (cd "$work/lShape" && blockMesh > log.blockMesh 2>&1)
    echo "L-shaped hex mesh:"
    "$work/bin/locateTest" -case "$work/lShape" > "$work/lShape/log.locateTest" 2>&1 || status=1
    grep -E "^(points|wall distances|walks|the wall|PASS|FAIL)" "$work/lShape/log.locateTest" || true

    # the same with every point moved up to 1 um (a fifth of a cell):
    # warped faces, walls included, and non-convex cells
    cp -r "$here/locate/lShape" "$work/lShapeWarped"
    (
        cd "$work/lShapeWarped" && blockMesh > log.blockMesh 2>&1 &&
        python3 "$here/locate/perturbPoints.py" . 1e-6 > log.perturbPoints
    )
    echo "L-shaped mesh, warped:"
    "$work/bin/locateTest" -case "$work/lShapeWarped" > "$work/lShapeWarped/log.locateTest" 2>&1 || status=1
    grep -E "^(points|wall distances|walks|the wall|PASS|FAIL)" "$work/lShapeWarped/log.locateTest" || true
else
    for mesh in hex tet polyDual
    do
        channelMesh "$work/$mesh" $mesh
        # channel height 1e-4 m -> 1 m
        (cd "$work/$mesh" && transformPoints -scale '(1e4 1e4 1e4)' > log.transformPoints 2>&1)
        echo "$mesh mesh:"
        "$work/bin/interpolateTest" -case "$work/$mesh" > "$work/$mesh/log.interpolateTest" 2>&1 || status=1
        grep -E "^(points|wall distances|walks|the wall|PASS|FAIL)" "$work/$mesh/log.interpolateTest" || true
    done
fi

exit $status
