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
work=$1
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../twoWay/caseFunctions.sh"
copyCase "$COLLOIDFOAM_TUTORIALS/filtration" "$work"
params=system/filtrationParameters
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

for bad in -0.1 1 rough
do
    rm -rf DEM
    sed -i "s/^rollingFriction .*/rollingFriction $bad;/" $params
    if "$COLLOIDFOAM_TUTORIALS/filtration/prepareRun.sh" > log.prepareRun 2> log.error
    then
        fail "rollingFriction $bad: prepareRun.sh exited 0"
    fi
    message=$(cat log.error)
    for part in "$params" "'rollingFriction'" "is $bad;" "0 <= rollingFriction < 1"
    do
        [[ "$message" == *"$part"* ]] \
            || fail "rollingFriction $bad: the message '$message' lacks '$part'"
    done
    [ ! -e DEM/filtration.liggghts ] \
        || fail "rollingFriction $bad: DEM/filtration.liggghts written"
    echo "rollingFriction $bad: $message"
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
