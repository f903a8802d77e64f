#!/bin/bash
# The contact and agglomerate analysis of colloidDEMFoam (couplingProperties
# contactAnalysis) on a hand-built arrangement in the coupling tests'
# channel (tests/cases/coupling/case, 100 x 100 x 50 um, spheres of
# d = 1 um), with the DEM periodic in z and, on 2 ranks, split at x = 50 um
# (processors * 1 1).  Touching below 1 % of the radius (5 nm), agglomerate
# bonds below 5 % (25 nm).  Arrangement (um):
#   chain of 5 at gaps of 2 nm across x = 50 (the ranks' boundary);
#   ring of 6 (hexagon of side 1.002) around (20, 70, 25);
#   a pair at 2 nm, and another across x = 50;
#   a chain of 3 across the periodic face z = 0 = 50, at (70, 70);
#   a pair at 10 nm (bonded, not touching);
#   one isolated sphere, and one 2.5 nm above the wall y = 0.
# Expected at the start (checkArrangement.py): 14 particle and 1 wall
# contact; 4, 8 and 10 particles with 0, 1 and 2 contacts; agglomerates of
# sizes 2 (x3), 3, 5 and 6, 20 particles in them; in the time-0 cloud each
# particle's agglomerateSize and agglomerateId; the time-0 cell fields (densities of
# particles, contacts and agglomerated particles) cell by cell.
#
# usage: runArrangementTest.sh serial|parallel workDir
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
sed -i "s/^endTime .*/endTime 2e-08;/" system/controlDict
cat >> constant/couplingProperties <<'DICT'

contactAnalysis
{
    interval        1;
    touchingGap     0.01;
    agglomerateGap  0.05;
}
DICT
python3 "$here/writeArrangement.py" > arrangement.liggghts
sed -i 's/^boundary .*/boundary        f f p\nprocessors      * 1 1/' constant/DEM/in.liggghts
includeParticles arrangement.liggghts
meshAndQuiescentFluid
runChannelSolver "$mode"
grep "^Contacts:" log.colloidDEMFoam | head -1
python3 "$here/checkArrangement.py" . "$mode"
