#!/bin/bash
# The filtration tutorial at test size (58 um across, 795 particles, to
# 1.2 ms), one variant, serial or on 2 ranks (METIS): its own Allrun in a
# copy of the tutorial, then checkFiltration.py on the run.
#
# The stable variant's t/V against V must be straight (Ruth, R^2 >= 0.98);
# the flocculated one's is printed only: its loose first layers of flocs
# make t/V bend up (0.977 at test size; see the tutorial's README).
#
# usage: runFiltrationTest.sh stable|flocculated workDir [-parallel serialWorkDir]
set -e
variant=$1
ruth=
if [ "$variant" = stable ]
then
    ruth=--ruth
fi
work=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../twoWay/caseFunctions.sh"
copyCase "$COLLOIDFOAM_TUTORIALS/filtration" "$work"
if [ "${3:-}" = -parallel ]
then
    ./Allrun -variant "$variant" -testSize -parallel -noConsolidation > log.Allrun 2>&1 \
        || { tail -30 log.Allrun; exit 1; }
    python3 "$here/checkFiltration.py" $ruth "runs/$variant-parallel" \
        "$4/runs/$variant"
else
    ./Allrun -variant "$variant" -testSize -noConsolidation > log.Allrun 2>&1 \
        || { tail -30 log.Allrun; exit 1; }
    python3 "$here/checkFiltration.py" $ruth "runs/$variant"
fi
