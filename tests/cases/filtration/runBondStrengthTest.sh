#!/bin/bash
# The flocculated variant at the tests' size with 30 times the case's
# (seed 002's) Hamaker constant, rolling resistance 0.1 (without it the
# bonds hold less: the tutorial's README) and otherwise the tutorial's
# settings, at a DEM step its stiffer van der Waals spring allows (the
# start-up check's limit falls as 1/sqrt(30): 1.14e-9 s; run at 1e-9 s,
# the fluid step kept), from its own Allrun in a copy of the tutorial;
# then checkFiltration.py, and checkBondStrength.py against the stable
# variant's run of case.filtration.stable.
#
# usage: runBondStrengthTest.sh workDir stableRunDir
set -e
work=$1
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../twoWay/caseFunctions.sh"
copyCase "$COLLOIDFOAM_TUTORIALS/filtration" "$work"
params=system/filtrationParameters
hamaker=$(foamDictionary -entry hamakerConstant -value $params)
sed -i -e "s/^hamakerConstant .*/hamakerConstant $(awk -v A="$hamaker" 'BEGIN { printf "%.6g", 30*A }');/" \
    -e "s/^rollingFriction .*/rollingFriction 0.1;/" $params
dt=$(foamDictionary -entry DEM/timeStep -value constant/couplingProperties)
interval=$(foamDictionary -entry DEM/couplingInterval -value constant/couplingProperties)
# sed, not foamDictionary -set, which writes the file's #include expanded
sed -i -E -e "s/^( *timeStep +)[^;]*;/\1 1e-9;/" \
    -e "s/^( *couplingInterval +)[^;]*;/\1 $(awk -v dt="$dt" -v n="$interval" \
        'BEGIN { printf "%d", dt*n/1e-9 + 0.5 }');/" constant/couplingProperties
echo "hamakerConstant $(foamDictionary -entry hamakerConstant -value $params)," \
    "DEM step $(foamDictionary -entry DEM/timeStep -value constant/couplingProperties) s," \
    "couplingInterval $(foamDictionary -entry DEM/couplingInterval -value constant/couplingProperties)"
./Allrun -variant flocculated -testSize -noConsolidation > log.Allrun 2>&1 \
    || { tail -30 log.Allrun; exit 1; }
python3 "$here/checkFiltration.py" runs/flocculated
python3 "$here/checkBondStrength.py" "$2" runs/flocculated
