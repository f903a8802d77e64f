#!/bin/bash
# Consolidation of the stable test-size cake (the filtration.stable run):
# the tutorial's consolidate.sh at 200 ... 1000 kPa in a copy of the run,
# then checkConsolidation.py.
#   -parallel serialWorkDir: on 2 ranks, and the packing densities as the
#       serial consolidation's in serialWorkDir
#   -rolling serialWorkDir: with rolling resistance (rollingFriction 0.1
#       in the copy's DEM values: LIGGGHTS' epsd2 through
#       constant/DEM/contacts.liggghts, particles and walls), and the cake
#       looser than without it (serialWorkDir)
#
# usage: runConsolidationTest.sh filtrationRunDir workDir [-parallel|-rolling serialWorkDir]
set -e
run=$1
work=$2
mode=${3:-}
reference=${4:-}
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
flag=
case "$mode" in
    "") ;;
    -parallel) flag=-parallel; check=--same-as ;;
    -rolling)
        check=--looser-than
        sed -i -e 's/^variable rollingFriction equal .*/variable rollingFriction equal 0.1/' \
            -e 's/^variable rollingModel string .*/variable rollingModel string epsd2/' \
            DEM/filtration.liggghts
        [ "$(grep -c '^variable rolling.* \(0.1\|epsd2\)$' DEM/filtration.liggghts)" = 2 ] \
            || { echo "no rolling resistance set in DEM/filtration.liggghts" 1>&2; exit 1; }
        ;;
    *) echo "usage: $0 filtrationRunDir workDir [-parallel|-rolling serialWorkDir]" 1>&2; exit 1 ;;
esac
"$COLLOIDFOAM_TUTORIALS/filtration/consolidate.sh" $flag > log.consolidate 2>&1 \
    || { tail -30 log.consolidate; exit 1; }
python3 "$here/checkConsolidation.py" . ${mode:+$check "$reference"}
