#!/bin/bash
# Overlapping initial particles found across ranks and periodic faces: the
# periodic box of the two-way tests (1 mm, spheres of 50 um) with four
# pairs overlapping by 20 % of the radius (centres 45 um apart), one
# across each mid-plane x, y, z = 500 um (on 2 ranks one of them is
# LIGGGHTS' processor boundary) and one across the periodic face x = 0
# (centres at 10 um and 965 um), and six spheres far from everything.
# colloidDEMFoam must stop before LIGGGHTS' set-up, counting 4 pairs and
# naming them, serial and on 2 ranks.
#
# With "warn": one pair overlapping by 5 % (centres 48.75 um apart), which
# only warns: the run must go on to its end (exit 0), the warning naming
# the pair.
#
#   runOverlapTest.sh nProcs workDir [warn]
set -e
nProcs=$1
work=$2
mode=${3:-stop}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/testEnvironment.sh"

rm -rf "$work"
mkdir -p "$(dirname "$work")"
cp -r "$here/../twoWay/periodicBox" "$work"
cd "$work"
if [ "$mode" = warn ]
then
    printf '%s\n' "LIGGGHTS data file: 1 pair overlapping by 5 %" "" "3 atoms" \
        "1 atom types" "" "0 1000 xlo xhi" "0 1000 ylo yhi" "0 1000 zlo zhi" \
        "" "Atoms" "" "1 1 50 2.5 475.625 300 300" "2 1 50 2.5 524.375 300 300" \
        "3 1 50 2.5 100 700 700" > constant/DEM/suspension.data
    foamDictionary system/controlDict -entry endTime -set 4e-4 > /dev/null
    blockMesh > log.blockMesh 2>&1
    colloidDEMFoam > log.colloidDEMFoam 2>&1 \
        || { echo "FAIL: the run stopped"; tail -20 log.colloidDEMFoam; exit 1; }
    grep -a -A3 "pairs of the DEM" log.colloidDEMFoam | head -4
    grep -a -E -q "^ *1 pairs of the DEM's initial particles .* overlap by more than 1 % " log.colloidDEMFoam \
        && grep -a -q "particles 1 at .* and 2 at .*: overlap 5 % of the smaller radius" log.colloidDEMFoam \
        && grep -q "^End" log.colloidDEMFoam \
        || { echo "FAIL: no warning naming the pair (5 %), or the run did not end"; exit 1; }
    echo PASS
    exit 0
fi
{
    printf '%s\n' "LIGGGHTS data file: 4 overlapping pairs" "" "14 atoms" \
        "1 atom types" "" "0 1000 xlo xhi" "0 1000 ylo yhi" "0 1000 zlo zhi" \
        "" "Atoms" ""
    id=0
    atom() { id=$((id + 1)); echo "$id 1 50 2.5 $1 $2 $3"; }
    atom 477.5 200 200;  atom 522.5 200 200     # across x = 500
    atom 200 477.5 800;  atom 200 522.5 800     # across y = 500
    atom 800 800 477.5;  atom 800 800 522.5     # across z = 500
    atom 10 600 600;     atom 965 600 600       # across the periodic face
    atom 100 100 100;    atom 300 300 300;  atom 700 100 300
    atom 100 700 300;    atom 300 900 900;  atom 900 300 100
} > constant/DEM/suspension.data
blockMesh > log.blockMesh 2>&1
if [ "$nProcs" -gt 1 ]
then
    decomposePar > log.decomposePar 2>&1
    run() { mpirun -np "$nProcs" colloidDEMFoam -parallel; }
else
    run() { colloidDEMFoam; }
fi
set +e
run > log.colloidDEMFoam 2>&1
rc=$?
set -e

status=0
[ $rc -ne 0 ] || { echo "FAIL: exit status 0"; status=1; }
grep -a -E -q "^(\[[0-9]+\] )?4 pairs of the DEM's initial particles .* overlap by more than 10 %" log.colloidDEMFoam \
    || { echo "FAIL: not 4 overlapping pairs reported"; grep -a -A8 "FATAL" log.colloidDEMFoam | head -12; status=1; }
for pair in "1 at .* and 2 at" "3 at .* and 4 at" "5 at .* and 6 at" "7 at .* and 8 at"
do
    grep -a -q "particles $pair .*: overlap 20 % of the smaller radius" log.colloidDEMFoam \
        || { echo "FAIL: pair '$pair' (overlap 20 %) not named"; status=1; }
done
grep -a "pairs of the DEM" -A5 log.colloidDEMFoam | head -6
echo "exit status $rc"
[ $status -eq 0 ] && echo PASS
exit $status
