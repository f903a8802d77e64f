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
# With "inserted": the check of the particles a script inserts during the
# run.  Particle 1 at z = 450 um; at DEM step 1 'fix insert/pack' puts
# particle 4 in a region 0.01 um wide around z = 503 um (same x, y;
# diameters 50 um: gap 3 um), across the mid-plane z = 500 (LIGGGHTS'
# processor boundary on 2 ranks: the test sets its grid to 1 by 1 by 2);
# particles 2 and 3, present from the start, are 1 um apart and must not
# count.  The log's "Inserted particles: smallest gap" must name 1 and 4
# and give 3 um within 0.02 um (the region's width, and the settling of
# the two in y over the 10 steps to the check: their centres' offset in
# y is below 0.1 um, which changes the gap by less than 1e-4 um).
#
#   runOverlapTest.sh nProcs workDir [warn|inserted]
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

# writeSpheres title "x y z" ...: the case's data file, spheres of 50 um
# (density 2.5 pg/um^3) at the given centres [um], ids from 1
writeSpheres()
{
    local title=$1 id=0 centre
    shift
    printf '%s\n' "LIGGGHTS data file: $title" "" "$# atoms" "1 atom types" "" \
        "0 1000 xlo xhi" "0 1000 ylo yhi" "0 1000 zlo zhi" "" "Atoms" ""
    for centre in "$@"
    do
        id=$((id + 1))
        echo "$id 1 50 2.5 $centre"
    done
} > constant/DEM/suspension.data

if [ "$mode" = warn ]
then
    writeSpheres "1 pair overlapping by 5 %" \
        "475.625 300 300" "524.375 300 300" "100 700 700"
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
if [ "$mode" = inserted ]
then
    writeSpheres "3 spheres, 2 and 3 1 um apart" \
        "300 300 450" "200 700 700" "251 700 700"
    cat >> constant/DEM/in.liggghts << 'EOI'

# One sphere inserted at DEM step 1, its centre within 0.005 um of
# (300, 300, 503) um (diameter 50 um).  'overlapcheck no': with it,
# insert/pack places no centre within a radius of a processor boundary
fix             insertTemplate all particletemplate/sphere 15485863 atom_type 1 &
                density constant ${colloid_density} radius constant ${colloid_radius}
fix             insertDistribution all particledistribution/discrete 32452843 1 insertTemplate 1.0
region          insertRegion block 299.995 300.005 299.995 300.005 502.995 503.005 units box
fix             insert all insert/pack seed 49979687 distributiontemplate insertDistribution &
                insert_every once overlapcheck no all_in no start 1 &
                particles_in_region 1 region insertRegion
EOI
    foamDictionary system/controlDict -entry endTime -set 4e-4 > /dev/null
    blockMesh > log.blockMesh 2>&1
    if [ "$nProcs" -gt 1 ]
    then
        sed -i 's/^read_data/processors      1 1 2\n&/' constant/DEM/in.liggghts
        decomposePar > log.decomposePar 2>&1
        mpirun -np "$nProcs" colloidDEMFoam -parallel > log.colloidDEMFoam 2>&1 \
            || { echo "FAIL: the run stopped"; tail -20 log.colloidDEMFoam; exit 1; }
    else
        colloidDEMFoam > log.colloidDEMFoam 2>&1 \
            || { echo "FAIL: the run stopped"; tail -20 log.colloidDEMFoam; exit 1; }
    fi
    line=$(grep -a "^Inserted particles" log.colloidDEMFoam || true)
    echo "$line"
    [ "$(grep -a -c "^Inserted particles" log.colloidDEMFoam)" -eq 1 ] \
        || { echo "FAIL: not one 'Inserted particles' line"; exit 1; }
    echo "$line" | awk '{
        gap = $5*1e6
        ok = ($0 ~ /between particles 1 and 4$/) && gap > 2.98 && gap < 3.02
        printf "smallest gap %.5f um (3 +- 0.02 um), pair 1-4: %s\n", gap, ok ? "yes" : "no"
        exit !ok }' || { echo FAIL; exit 1; }
    echo PASS
    exit 0
fi
writeSpheres "4 overlapping pairs" \
    "477.5 200 200" "522.5 200 200" \
    "200 477.5 800" "200 522.5 800" \
    "800 800 477.5" "800 800 522.5" \
    "10 600 600"    "965 600 600" \
    "100 100 100" "300 300 300" "700 100 300" \
    "100 700 300" "300 900 900" "900 300 100"
# (pairs across x, y, z = 500 and the periodic face x = 0, then six apart)
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
