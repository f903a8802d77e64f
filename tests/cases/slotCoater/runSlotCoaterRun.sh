#!/bin/bash
# The slot-coater tutorial's Allrun (mesh, steady flow, DEM surfaces,
# coupled particle run) at test size, on a copy in WORKDIR.
#
#   runSlotCoaterRun.sh MODE WORKDIR
#
# MODE  serial | parallel (Allrun -parallel: 2 ranks, METIS)
#
# Test size (testSizeCase.sh): about 2000 particles, run for 3 us with a
# write every 0.2 us.  Then checkBookkeeping.py checks every write's counts.
set -e
here=$(cd "$(dirname "$0")" && pwd)
mode=$1
work=$2

set +u
source "$here/../../../etc/bashrc" || exit 1

source "$here/testSizeCase.sh"

case "$mode" in
serial)   ./Allrun -endTime 3e-6 ;;
parallel) ./Allrun -parallel -endTime 3e-6 ;;
*) echo "usage: $0 serial|parallel WORKDIR" 1>&2; exit 1 ;;
esac || { tail -20 log.colloidDEMFoam 2>/dev/null; exit 1; }

python3 "$here/checkBookkeeping.py" . 3e-6
