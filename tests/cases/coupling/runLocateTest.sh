#!/bin/bash
# particleLocator against OpenFOAM's global search (polyMesh::findCell) for
# 10^5 points each, on the tet channel (convex: the incremental walk must
# never give up for a point inside) and on a concave L-shaped hex mesh.
# Builds the test program locateTest into the work folder first.
#
# usage: runLocateTest.sh workDir
set -e
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
work=$1
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

rm -rf "$work"
mkdir -p "$work/bin"
export COUPLING_TEST_BIN="$work/bin"
wmake -s "$here/locate" > "$work/log.wmake" 2>&1 || { tail -20 "$work/log.wmake"; exit 1; }

status=0

cp -r "$here/case" "$work/tet"
(
    cd "$work/tet"
    python3 "$here/makeTetMesh.py" channel.msh 10 20 5
    gmshToFoam channel.msh > log.gmshToFoam 2>&1
)
echo "tet channel:"
"$work/bin/locateTest" -convex -case "$work/tet" > "$work/tet/log.locateTest" 2>&1 || status=1
tail -2 "$work/tet/log.locateTest"

cp -r "$here/locate/lShape" "$work/lShape"
(cd "$work/lShape" && blockMesh > log.blockMesh 2>&1)
echo "L-shaped hex mesh:"
"$work/bin/locateTest" -case "$work/lShape" > "$work/lShape/log.locateTest" 2>&1 || status=1
tail -2 "$work/lShape/log.locateTest"

exit $status
