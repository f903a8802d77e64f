#!/bin/bash
# Consolidation of the stable test-size cake (the filtration.stable run):
# the tutorial's consolidate.sh at 200 ... 1000 kPa in a copy of the run,
# then checkConsolidation.py.
#
# usage: runConsolidationTest.sh filtrationRunDir workDir
set -e
run=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../twoWay/caseFunctions.sh"
rm -rf "$work"
mkdir -p "$work"
cp -r "$run"/system "$run"/constant "$run"/DEM "$run"/VTK "$work"/
cd "$work"
"$COLLOIDFOAM_TUTORIALS/filtration/consolidate.sh" > log.consolidate 2>&1 \
    || { tail -30 log.consolidate; exit 1; }
python3 "$here/checkConsolidation.py" .
