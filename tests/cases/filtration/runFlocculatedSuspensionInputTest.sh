#!/bin/bash
# flocculatedSuspension of system/filtrationParameters reaches the
# suspension, and a bad value stops prepareRun.sh: for "jelly" and "Gel" a
# non-zero exit, a message naming the file, the keyword, the value and the
# allowed values (flocs or gel), and no DEM/filtration.liggghts nor
# DEM/suspension.data; for the flocculated variant, "flocs" writes
# 100 separate flocs of 8 and "gel" one network of the test size's 795
# spheres (the title makeFlocs.py writes); a gel that cannot be made (a
# period below 2.5 diameters) stops it and leaves no files behind.
# (The network's geometry: case.filtration.gelSuspension.)
#
# usage: runFlocculatedSuspensionInputTest.sh workDir
set -e
source "$(dirname "$0")/prepareRunInput.sh" "$1"
sed -i "s/^variant .*/variant flocculated;/" $params

for bad in jelly Gel
do
    refused flocculatedSuspension $bad "flocs or gel"
done

for good in "flocs 795 spheres in 100 flocs" "gel 795 spheres in one network"
do
    set -- $good
    value=$1; shift
    rm -rf DEM
    sed -i "s/^flocculatedSuspension .*/flocculatedSuspension $value;/" $params
    "$COLLOIDFOAM_TUTORIALS/filtration/prepareRun.sh" -testSize > log.prepareRun \
        || fail "flocculatedSuspension $value: prepareRun.sh failed"
    head -1 DEM/suspension.data | grep -q "$*" \
        || fail "flocculatedSuspension $value: DEM/suspension.data is '$(head -1 DEM/suspension.data)', not '$*'"
    echo "flocculatedSuspension $value: $(head -1 DEM/suspension.data)"
done

# A gel that cannot be made (a period below 2.5 diameters: 12 um for
# 5.8 um spheres) stops prepareRun.sh with makeFlocs.py's message and
# leaves neither the suspension, the DEM's values nor log.timeStep
rm -rf DEM log.timeStep
sed -i -e "s/^flocculatedSuspension .*/flocculatedSuspension gel;/" \
    -e "s/^width .*/width 12;/" $params
if "$COLLOIDFOAM_TUTORIALS/filtration/prepareRun.sh" > log.prepareRun 2> log.error
then
    fail "gel in a 12 um period: prepareRun.sh exited 0"
fi
grep -q "period x = 12 um is below 2.5 diameters" log.error \
    || fail "gel in a 12 um period: the message '$(cat log.error)' does not name the period"
[ ! -e DEM/suspension.data ] && [ ! -e DEM/filtration.liggghts ] && [ ! -e log.timeStep ] \
    || fail "gel in a 12 um period: files left behind"
echo "gel in a 12 um period: $(tail -1 log.error)"

[ "$failures" -eq 0 ] || { echo "$failures failures"; exit 1; }
echo "flocculatedSuspension input: all checks passed"
