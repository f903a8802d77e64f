#!/bin/bash
# rollingFriction of system/filtrationParameters reaches the DEM, and a
# bad value stops prepareRun.sh: for -0.1, 1 and "rough" a non-zero exit,
# a message naming the file, the keyword, the value and the allowed range
# 0 <= rollingFriction < 1, and no DEM/filtration.liggghts; for 0 the
# DEM's rolling model "off", for 0.1 "epsd2" with the coefficient 0.1.
# (The rolling model's mechanics: dem.rollingResistance*.)
#
# usage: runRollingFrictionInputTest.sh workDir
set -e
source "$(dirname "$0")/prepareRunInput.sh" "$1"

for bad in -0.1 1 rough
do
    refused rollingFriction $bad "0 <= rollingFriction < 1"
done

for good in "0 off" "0.1 epsd2"
do
    set -- $good
    rm -rf DEM
    sed -i "s/^rollingFriction .*/rollingFriction $1;/" $params
    "$COLLOIDFOAM_TUTORIALS/filtration/prepareRun.sh" -testSize > log.prepareRun \
        || fail "rollingFriction $1: prepareRun.sh failed"
    grep -q "^variable rollingModel string $2\$" DEM/filtration.liggghts \
        || fail "rollingFriction $1: no rolling model $2 in DEM/filtration.liggghts"
    awk -v v="$1" '$2 == "rollingFriction" { found = 1; if ($4 + 0 != v + 0) bad = 1 }
        END { exit !found || bad }' DEM/filtration.liggghts \
        || fail "rollingFriction $1: the coefficient in DEM/filtration.liggghts is not $1"
    echo "rollingFriction $1: checked (rolling model $2 expected)"
done

[ "$failures" -eq 0 ] || { echo "$failures failures"; exit 1; }
echo "rollingFriction input: all checks passed"
