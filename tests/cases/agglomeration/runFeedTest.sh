#!/bin/bash
# The coupling's feed (particleFeed) through the inlet of the coupling
# tests' channel (100 x 100 x 50 um, spheres of d = 1 um): liquid in
# plane Poiseuille flow along x between the walls y = 0 and 100 um
# (U_max 0.05 m/s, inlet x = 0, outlet x = 100 um), the DEM periodic in
# z, 5 % solids fed every 1 us for 30 us, at least 0.1 um from particles
# and walls.  On 2 ranks the fluid is split across the inlet (simple
# 1 2 1), so that both ranks hold inlet faces.  The DEM starts with the
# channel's own particle (id 1) far from the inlet.  checkFeed.py checks the
# count of every insertion, the flux profile, the placement in the swept
# region, the gaps; with two cases, that they hold the same particles.
# plug: serial, the liquid at U_max everywhere (the walls move with it),
# so that the inflow next to the walls is not small and the feed's gap to
# the walls is put to the test.
#
# usage: runFeedTest.sh serial|parallel|plug workDir
set -e
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
mode=$1
work=$2
profile=poiseuille
if [ "$mode" = plug ]
then
    mode=serial
    profile=plug
fi
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

source "$here/channelCase.sh"
newChannelCase
runLength 3e-05 500
sed -i 's/coeffs { n (2 1 1); }/coeffs { n (1 2 1); }/' system/decomposeParDict
grep -q "n (1 2 1)" system/decomposeParDict
python3 - <<'PYEOF'
import re
p = "system/blockMeshDict"
t = open(p).read()
t = re.sub(r"    sides\n    \{.*?\n    \}", """    inlet { type patch; faces ( (0 4 7 3) ); }
    outlet { type patch; faces ( (1 2 6 5) ); }
    sides { type patch; faces ( (0 3 2 1) (4 5 6 7) ); }""", t, flags=re.S)
open(p, "w").write(t)
PYEOF
grep -q "inlet { type patch" system/blockMeshDict
cat >> constant/couplingProperties <<'DICT'

feed
{
    patch           inlet;
    solidsFraction  0.05;
    minimumGap      1e-7;
    interval        1e-6;
    seed            12345;
}
DICT
# The channel's own particle (id 1, at x = 47.3 um, far from where the
# feed's particles go: LIGGGHTS cannot start without one); the feed
# brings the others
sed -i 's/^boundary .*/boundary        f f p/' constant/DEM/in.liggghts
blockMesh > log.blockMesh 2>&1
mkdir -p 0
postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
python3 - "$here" "$profile" <<'PYEOF'
import sys
sys.path.insert(0, sys.argv[1] + "/../coupling")
import setPoiseuilleU
H, Umax = 1e-4, 0.05
# The inlet's face values are those of its cells (zero gradient): the
# profile at the cell centres
if sys.argv[2] == "plug":
    setPoiseuilleU.write_profile(".", lambda y: Umax,
                                 "type fixedValue; value uniform (%g 0 0);" % Umax)
else:
    setPoiseuilleU.write_profile(".", lambda y: 4*Umax*y*(H - y)/H**2,
                                 "type fixedValue; value uniform (0 0 0);")
p = "0/U"
t = open(p).read()
t = t.replace("    sides { type zeroGradient; }",
              "    inlet { type zeroGradient; }\n    outlet { type zeroGradient; }\n"
              "    sides { type zeroGradient; }")
open(p, "w").write(t)
PYEOF
grep -q "inlet { type zeroGradient" 0/U
runChannelSolver "$mode"
grep "^Feed:" log.colloidDEMFoam | head -2
python3 "$here/checkFeed.py" . $profile
