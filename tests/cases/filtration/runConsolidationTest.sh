#!/bin/bash
# Consolidation of the stable test-size cake (the filtration.stable run):
# the tutorial's consolidate.sh at 200 ... 1000 kPa in a copy of the run,
# then checkConsolidation.py; with -parallel on 2 ranks, and
# checkConsolidation.py also compares it with the serial consolidation in
# serialWorkDir.
#
# usage: runConsolidationTest.sh filtrationRunDir workDir [-parallel serialWorkDir]
set -e
run=$1
work=$2
parallel=${3:-}
serial=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../twoWay/caseFunctions.sh"
rm -rf "$work"
mkdir -p "$work"
latest=$(foamListTimes -case "$run" -latestTime -noZero | tail -1)
[ -d "$run/$latest/lagrangian" ] || { echo "no particles at $run/$latest" 1>&2; exit 1; }
mkdir -p "$work/$latest"
cp -r "$run"/system "$run"/constant "$run"/DEM "$work"/
cp -r "$run/$latest/lagrangian" "$work/$latest"/
cd "$work"
"$COLLOIDFOAM_TUTORIALS/filtration/consolidate.sh" $parallel > log.consolidate 2>&1 \
    || { tail -30 log.consolidate; exit 1; }
python3 "$here/checkConsolidation.py" . $serial
