#!/bin/bash
# The random packed bed shared by the two-way tests (the packedBed
# tutorial's constant/DEM/in.pack, stock
# liggghts): workDir/bed.data.
#
# usage: makePack.sh workDir
set -e
work=$1
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u
rm -rf "$work"
mkdir -p "$work"
cd "$work"
cp "$COLLOIDFOAM_TUTORIALS/twoWay/packedBed/constant/DEM/in.pack" .
liggghts -in in.pack > log.pack 2>&1 || { tail -20 log.pack; exit 1; }
grep -c . bed.data > /dev/null
echo "packed bed: $(grep ' atoms$' bed.data)"
