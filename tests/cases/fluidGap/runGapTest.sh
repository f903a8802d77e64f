#!/bin/bash
# Run one plane-gap case (Poiseuille or Couette-Poiseuille) with Debian's
# simpleFoam and compare the profile with the closed form.
#
#   runGapTest.sh PARAMETERS WORKDIR
#
# The case in case/ is copied to WORKDIR (in the build tree) together with
# the parameter file, which becomes WORKDIR/system/gapParameters; nothing is
# written to the source tree.
set -e
here=$(cd "$(dirname "$0")" && pwd)
params=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
work=$2

set +u
source "$here/../../../etc/bashrc" || exit 1

rm -rf "$work"
mkdir -p "$(dirname "$work")"
cp -r "$here/case" "$work"
cp "$params" "$work/system/gapParameters"
cd "$work"

run()
{
    echo "$*"
    "$@" > "log.$1" 2>&1 || { tail -20 "log.$1"; exit 1; }
}

run blockMesh
run simpleFoam
run postProcess -func writeCellCentres -latestTime
python3 "$here/checkGapProfile.py" . 0.01
