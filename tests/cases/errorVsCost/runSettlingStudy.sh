#!/bin/bash
# colloidErrorStudy on a case with a closed form: the settling particle of
# the coupling tests (tests/cases/coupling/case) released at rest in
# quiescent water, DEM step ladder 2e-8 ... 2.5e-9 s (relaxation time
# 1.39e-7 s) at a fixed coupling step, to t = 1.4e-7 s.  Then
# checkSettlingStudy.py asserts the tool's observed order and Richardson
# estimates.
#
# usage: runSettlingStudy.sh workDir
set -e
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
work=$1
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

rm -rf "$work"
mkdir -p "$(dirname "$work")"
cp -r "$here/../coupling/case" "$work"
cd "$work"
blockMesh > log.blockMesh 2>&1
mkdir -p 0
postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
python3 "$here/../coupling/setPoiseuilleU.py" . 1e-4 0     # U = 0
sed -i "s/^endTime .*/endTime 1.4e-07;/" system/controlDict  # one write
cp "$here/errorStudyDict.settling" system/errorStudyDict
cp "$here/settlingQuantities.py" system/

colloidErrorStudy
cat errorStudy/errorStudy.md
/usr/bin/python3 "$here/checkSettlingStudy.py" errorStudy
