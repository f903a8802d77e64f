#!/bin/bash
# Consolidation of the cake of a finished filtration run (in the current
# case folder): the piston pressures of system/filtrationParameters
# (consolidationPressures) in turn, each held until the cake is at rest
# (constant/DEM/in.consolidation: stock liggghts with the plugin
# preloaded), then consolidationResults.py: packing density against
# pressure and the compressibility index of seed 002 eq. 14.
#
# Output: DEM/cake.data, DEM/piston.stl, DEM/consolidation.dat,
# log.consolidation, consolidation.csv, consolidation.png,
# consolidation.txt.
#
#   consolidate.sh [-parallel]
#   -parallel: the DEM on the ranks of system/decomposeParDict, side by
#   side across the cake (in.consolidation: processors * 1 *)
set -e
tutorial=$(cd "$(dirname "$0")" && pwd)
. "$COLLOIDFOAM_DIR"/etc/AllrunFunctions
plugin="$FOAM_USER_LIBBIN/libliggghtsColloid.so"
case "${1:-}" in
    "") ranks=1; launch=(env LD_PRELOAD="$plugin") ;;
    -parallel) ranks=$(nRanks); launch=(mpirun -np "$ranks" -x LD_PRELOAD="$plugin") ;;
    *) echo "usage: $0 [-parallel]" 1>&2; exit 1 ;;
esac
value() { foamDictionary -entry "$2" -value "$1"; }

# checked before anything is written or run (consolidationResults.py
# reads them after the DEM's minutes)
checkParameter system/filtrationParameters consolidationStepLimit 0 -
checkParameter system/filtrationParameters consolidationCommonP0 0 -

pistonY=$(python3 "$tutorial"/makeCake.py .)
d=$(value system/filtrationParameters particleDiameter)
rhop=$(value system/filtrationParameters particleDensity)
mu=$(value system/filtrationParameters mu)
dt=$(value constant/couplingProperties DEM/timeStep)
pressures=$(value system/filtrationParameters consolidationPressures | tr -d '()')
stepLimit=$(value system/filtrationParameters consolidationStepLimit)

echo "Consolidation: piston at $pistonY um, pressures $pressures Pa," \
    "$ranks rank(s): log.consolidation"
"${launch[@]}" liggghts \
    -in constant/DEM/in.consolidation -log log.consolidation -echo none \
    -var colloid_case "$PWD" \
    -var colloid_diameter "$(awk -v d="$d" 'BEGIN { printf "%.10g", d*1e6 }')" \
    -var colloid_density "$(awk -v r="$rhop" 'BEGIN { printf "%.10g", r*1e-3 }')" \
    -var colloid_fluid_viscosity "$(awk -v m="$mu" 'BEGIN { printf "%.10g", m*1e3 }')" \
    -var colloid_timestep "$(awk -v t="$dt" 'BEGIN { printf "%.10g", t*1e6 }')" \
    -var pistonY "$pistonY" -var stepLimit "$stepLimit" -var p $pressures > log.consolidation.screen 2>&1 \
    || { tail -20 log.consolidation.screen; exit 1; }
grep "^consolidation:" log.consolidation
/usr/bin/python3 "$tutorial"/consolidationResults.py .
