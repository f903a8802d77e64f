#!/bin/bash
# The slot-coater tutorial's Allrun (mesh, steady flow, DEM surfaces,
# coupled particle run) at test size, on a copy in WORKDIR.
#
#   runSlotCoaterRun.sh MODE WORKDIR
#
# MODE  serial | parallel (Allrun -parallel: 2 ranks, METIS)
#
# Test size: the tutorial's geometry shrunk 5 times (gap 10 um, slot 20 um,
# 1.25 um cells; about 2000 particles), run for 3 us with a particle file
# every 0.2 us.  Then checkBookkeeping.py checks every write's counts.
set -e
here=$(cd "$(dirname "$0")" && pwd)
tutorial="$here/../../../tutorials/slotCoater"
mode=$1
work=$2

set +u
source "$here/../../../etc/bashrc" || exit 1

rm -rf "$work"
mkdir -p "$work"
cp -r "$tutorial"/* "$work"
cd "$work"
# Start from the committed files, whatever a run in the source tree left
./Allclean > /dev/null

set_param()
{
    foamDictionary -entry "$1" -set "$2" system/slotCoaterParameters > /dev/null
}
set_param gap 10e-6;          set_param nGap 8
set_param slotWidth 20e-6;    set_param nSlotWidth 16
set_param slotLength 5e-6;    set_param nSlotLength 4
set_param upstreamLip 5e-6;   set_param nUpstreamLip 4
set_param downstreamLip 10e-6; set_param nDownstreamLip 8
set_param wetThickness 4e-6
# (sed, not foamDictionary -set, which drops the #includeIfPresent)
sed -i "s/^writeInterval .*/writeInterval   20;/" system/controlDict

case "$mode" in
serial)   ./Allrun -endTime 3e-6 ;;
parallel) ./Allrun -parallel -endTime 3e-6 ;;
*) echo "usage: $0 serial|parallel WORKDIR" 1>&2; exit 1 ;;
esac || { tail -20 log.colloidDEMFoam 2>/dev/null; exit 1; }

python3 "$here/checkBookkeeping.py" . 3e-6
