#!/bin/bash
# A touching pair carried across the DEM's periodic face by a uniform flow
# (U = 0.1 m/s along x in the coupling tests' channel, the DEM periodic in
# x): spheres of d = 1 um at x = 99.5 and 0.502 um (2 nm apart across the
# face x = 0 = 100), moved 3 um in 30 us: the pair is carried over the
# face, from straddling it to both on one side.  On 2
# ranks the face is also the boundary between the DEM's ranks (processors
# * 1 1).  checkPeriodicCrossing.py: the contact is there at every
# analysis, never broken or formed again, one agglomerate of 2; both
# particles kept and moving with the flow.
#
# usage: runPeriodicCrossingTest.sh serial|parallel workDir
set -e
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
mode=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

source "$here/channelCase.sh"
newChannelCase
runLength 3e-05 500
cat >> constant/couplingProperties <<'DICT'

contactAnalysis
{
    interval        10;
    touchingGap     0.01;
    agglomerateGap  0.01;
}
DICT
cat > pair.liggghts <<'DICT'
create_atoms 1 single 99.5 50 25 units box
create_atoms 1 single 0.502 50 25 units box
DICT
sed -i 's/^boundary .*/boundary        p f f\nprocessors      * 1 1/' constant/DEM/in.liggghts
includeParticles pair.liggghts
blockMesh > log.blockMesh 2>&1
mkdir -p 0
postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
python3 - "$here" <<'PYEOF'
import sys
sys.path.insert(0, sys.argv[1] + "/../coupling")
from setPoiseuilleU import write_profile
write_profile(".", lambda y: 0.1, "type fixedValue; value uniform (0.1 0 0);")
PYEOF
runChannelSolver "$mode"
grep "^Contacts:" log.colloidDEMFoam | tail -1
python3 "$here/checkPeriodicCrossing.py" .
