#!/bin/bash
# Contact flags of the particle file against the geometry of the initial
# packing (written before the first step): touching means a gap below 1 %
# of the radius.  Particles (d = 1 um, in um):
#   A (20, 50, 25) and B (21.002, 50, 25): gap 0.002 um -> both touch a particle
#   C (60, 0.5025, 25): 0.0025 um above the wall y = 0 -> touches a wall
#   D (40, 50, 25) and E (41.1, 50, 25): gap 0.1 um -> neither touches
#   F (80, 99.45, 25): 0.05 um below the wall y = 100 -> no wall contact
#
# usage: runContactFlagsTest.sh workDir
set -e
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
work=$1
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

rm -rf "$work"
mkdir -p "$(dirname "$work")"
cp -r "$here/case" "$work"
cd "$work"
foamDictionary system/controlDict -entry endTime -set 2e-08 > /dev/null
sed -i '/^create_atoms/d' constant/DEM/in.liggghts
sed -i 's/^set .*group all/create_atoms    1 single 20 50 25 units box\ncreate_atoms    1 single 21.002 50 25 units box\ncreate_atoms    1 single 60 0.5025 25 units box\ncreate_atoms    1 single 40 50 25 units box\ncreate_atoms    1 single 41.1 50 25 units box\ncreate_atoms    1 single 80 99.45 25 units box\n&/' constant/DEM/in.liggghts
blockMesh > log.blockMesh 2>&1
mkdir -p 0
postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
python3 "$here/setPoiseuilleU.py" . 1e-4 1e-3
colloidDEMFoam > log.colloidDEMFoam 2>&1 || { tail -30 log.colloidDEMFoam; exit 1; }

python3 - "$work/0" "$here" <<'PYEOF'
import sys
sys.path.insert(0, sys.argv[2] + '/../../../src/python')
import particleCloud
d = particleCloud.read(sys.argv[1])
expected = {  # x [um] -> (touchingParticle, touchingWall)
    20: (1, 0), 21.002: (1, 0), 60: (0, 1), 40: (0, 0), 41.1: (0, 0), 80: (0, 0)}
ok = len(d["position"]) == 6
for p, tp, tw in zip(d["position"], d["touchingParticle"], d["touchingWall"]):
    x = round(p[0]*1e6, 3)
    want = expected[x]
    got = (int(tp), int(tw))
    print("x = %7.3f um: touchingParticle %d touchingWall %d (expected %d %d)" % (x, got[0], got[1], *want))
    ok = ok and got == want
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
PYEOF
