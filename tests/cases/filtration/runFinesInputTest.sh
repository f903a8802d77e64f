#!/bin/bash
# fineVolumeFraction and fineDiameter of system/filtrationParameters reach
# the suspension and the coupling, and bad values stop prepareRun.sh: for
# fineVolumeFraction -0.1, 1 and "some" and fineDiameter 0, 5.8e-06 (the
# spheres' own) and 7e-06 a non-zero exit, a message naming the file, the
# keyword, the value and the allowed range, and no DEM files; at the tests'
# size with fineVolumeFraction 0.487, both variants: the suspension holds
# the spheres of each size that the solids fraction and the share ask for
# (counted here from the case's sizes), and constant/couplingProperties
# particles/diameterRange (2.9e-06 5.8e-06), the file still reading its
# values from filtrationParameters (#include kept) and keeping its
# comments; with 0 then, in the
# same folder, spheres of one size and no diameterRange.  (The suspensions themselves:
# filtration.finesSuspension.)
#
# usage: runFinesInputTest.sh workDir
set -e
source "$(dirname "$0")/prepareRunInput.sh" "$1"

for bad in -0.1 1 some
do
    refused fineVolumeFraction $bad "0 <= fineVolumeFraction < 1"
done
sed -i "s/^fineVolumeFraction .*/fineVolumeFraction 0;/" $params
# (as foamDictionary writes the numbers back)
for bad in 0 5.8e-06 7e-06
do
    refused fineDiameter $bad "0 < fineDiameter < 5.8e-06"
done
sed -i "s/^fineDiameter .*/fineDiameter 2.9e-6;/" $params
grep -q "diameterRange" constant/couplingProperties \
    && fail "a refused value left particles/diameterRange in constant/couplingProperties"

for run in "0.487 stable" "0.487 flocculated" "0 stable"
do
    set -- $run
    rm -rf DEM
    sed -i -e "s/^fineVolumeFraction .*/fineVolumeFraction $1;/" \
        -e "s/^variant .*/variant $2;/" $params
    cp $params system/filtrationParameters.set
    "$COLLOIDFOAM_TUTORIALS/filtration/prepareRun.sh" -testSize > log.prepareRun \
        || fail "fineVolumeFraction $1, $2: prepareRun.sh failed"
    # the counts the case asks for: the tests' column (58 um across, 16
    # cells of 11.6 um of suspension), 13 % solids, the share x in fines
    expected=$(python3 -c "
import math
x = $1
v = 0.13*58*58*16*11.6
print('%d %d' % (round((1 - x)*v/(math.pi/6*5.8**3)), round(x*v/(math.pi/6*2.9**3))))")
    got=$(awk '/Atoms/ { on = 1; next } on && NF == 7 { n[$3]++ }
        END { printf "%d %d", n["5.8"], n["2.9"] }' DEM/suspension.data)
    [ "$got" = "$expected" ] \
        || fail "fineVolumeFraction $1, $2: spheres of 5.8 and 2.9 um: $got (expected $expected)"
    range=$(foamDictionary -entry particles/diameterRange -value constant/couplingProperties 2>/dev/null \
        | sed -e 's/( */(/' -e 's/ *)/)/' || true)
    if [ "$1" = 0 ]
    then
        [ -z "$range" ] || fail "fineVolumeFraction 0: diameterRange $range set"
    else
        [ "$range" = "(2.9e-06 5.8e-06)" ] \
            || fail "fineVolumeFraction $1: diameterRange '$range' (expected (2.9e-06 5.8e-06))"
        grep -q '^#include "$FOAM_CASE/system/filtrationParameters"' constant/couplingProperties \
            || fail "fineVolumeFraction $1: constant/couplingProperties lost its #include"
        grep -q '^// Stokes relaxation time' constant/couplingProperties \
            || fail "fineVolumeFraction $1: constant/couplingProperties lost its comments"
    fi
    echo "fineVolumeFraction $1, $2: spheres of 5.8 and 2.9 um $got (expected $expected), diameterRange '${range}'"
    cp system/filtrationParameters.set $params
done

[ "$failures" -eq 0 ] || { echo "$failures failures"; exit 1; }
echo "fines input: all checks passed"
