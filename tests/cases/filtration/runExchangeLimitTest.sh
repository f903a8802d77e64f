#!/bin/bash
# The start-up limit of the explicit two-way exchange on the fluid step
# (src/colloidModels/exchangeStability.H) against the filtration it was
# made for: the stable variant at test size, serial, to 1 ms, with the
# fluid step on either side of the limit the solver prints (3.4e-7 s for
# the tutorial's particles):
#   below: 3e-7 s (couplingInterval 75) runs, and the cake holds;
#   above: 6e-7 s (couplingInterval 150) is refused at start-up, naming
#     couplingInterval and its allowed range, with nothing but logs
#     written; told that no particle moves freely below fluid fraction 0.8
#     (twoWay/freeFluidFraction) it runs, and the cake is blown apart
#     (checkExchangeLimit.py).
#
# usage: runExchangeLimitTest.sh workDir
set -e
work=$1
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../twoWay/caseFunctions.sh"

# setFluidStep couplingInterval: the fluid step (controlDict deltaT) of
# that many DEM steps of 4e-9 s, its writes every 50 us (to a step)
setFluidStep() {
    local dt
    dt=$(python3 -c "print('%g' % ($1*4e-9))")
    sed -i "s/^\( *couplingInterval \+\)[0-9]\+;/\1$1;/" constant/couplingProperties
    sed -i "s/^deltaT .*/deltaT          $dt;/" system/controlDict
    sed -i "s/^writeInterval .*/writeInterval   $(( 12500 / $1 ));/" system/controlDict
}

runFiltration() {
    ./Allrun -variant stable -testSize -noConsolidation -endTime 1e-3 \
        > log.Allrun 2>&1
}

# Below the limit
copyCase "$COLLOIDFOAM_TUTORIALS/filtration" "$work/below"
setFluidStep 75
runFiltration || { tail -30 log.Allrun; exit 1; }

# Above it: refused
copyCase "$COLLOIDFOAM_TUTORIALS/filtration" "$work/above"
setFluidStep 150
if runFiltration
then
    echo "FAIL: a fluid step of 6e-7 s was not refused"; exit 1
fi
expect="Keyword 'couplingInterval' in .*couplingProperties.DEM\"? is 150: the fluid step 150 x 4e-09 = 6e-07 s is longer than the largest step [0-9.e-]+ s at which the explicit two-way exchange is stable.*Allowed range: couplingInterval <= [0-9]+"
grep -E -q "$expect" runs/stable/log.colloidDEMFoam \
    || { echo "FAIL: no message matching: $expect"; tail -20 runs/stable/log.colloidDEMFoam; exit 1; }
# Nothing but the logs changed since the solver started: the case as
# prepared (mesh, fields, DEM input) before it, no time folder after
written=$(cd runs/stable && find . -newer log.blockMesh ! -path . ! -name 'log.*' | sort)
[ -z "$written" ] || { echo "FAIL: the refused run wrote: $written"; exit 1; }
grep -E -o "Allowed range: couplingInterval <= [0-9]+" runs/stable/log.colloidDEMFoam
mv runs/stable/log.colloidDEMFoam log.refused

# ... and run anyway, told that no particle moves freely below 0.8
sed -i "s/^\( *epsilonMin .*\)$/\1\n    freeFluidFraction 0.8;/" constant/couplingProperties
grep -q "freeFluidFraction 0.8;" constant/couplingProperties
runFiltration || { tail -30 log.Allrun; exit 1; }

python3 "$here/checkExchangeLimit.py" "$work/below/runs/stable/log.colloidDEMFoam" \
    "$work/above/runs/stable/log.colloidDEMFoam"
