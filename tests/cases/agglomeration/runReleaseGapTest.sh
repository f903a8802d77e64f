#!/bin/bash
# The release gap of colloidDEMFoam's contact analysis (couplingProperties
# contactAnalysis: touching below 1 % of the radius, 5 nm; released at 2 %,
# 10 nm; agglomerate bonds only by contacts), on 2 ranks with the contact
# across the boundary between the DEM's ranks.  In the coupling tests'
# channel (tests/cases/coupling/case, spheres of d = 1 um, walls y = 0 and
# y = 100 um), the particles moved by the DEM's 'fix move', whatever the
# forces (units micro):
#   A at (49.5, 50, 25) at rest; B beside it across x = 50 (the ranks'
#   boundary on 2 ranks, processors * 1 1), wiggling along the line of
#   centres: gap = 7 - 6 sin(2 pi t/P) nm, P = 10 us;
#   C at (20, 0.507, 25) wiggling the same way towards the wall y = 0:
#   wall gap = 7 - 6 sin(2 pi t/P) nm.
# Three periods, an analysis every coupling step (0.02 us).
# checkReleaseGap.py: each contact forms at phase asin(1/3)/(2 pi) and ends
# at 7/12 (gap 10 nm), not at 1/2 - asin(1/3)/(2 pi) (gap 5 nm again):
# three pair and three wall contacts formed and ended, each lasting the
# closed form within one analysis interval; between, while the gap is
# between 5 and 10 nm, one pair contact, A and B each with one (both
# ranks know it), one agglomerate of 2.
# With resumeAt (s): the run stops at that write and is resumed from it
# to the end (colloidDEMFoam, startFrom latestTime; the DEM state and the
# contact histories from the write; 'fix move' continues from its
# restart).  At 5e-6 s both contacts are held (gap 7 nm, phase 1/2): the
# same checks hold only if the resumed run keeps them as contacts with
# their start times.
#
# usage: runReleaseGapTest.sh serial|parallel workDir [resumeAt]
set -e
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
mode=$1
work=$2
resumeAt=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

source "$here/channelCase.sh"
newChannelCase
runLength "${resumeAt:-3e-05}" 250
cat >> constant/couplingProperties <<'DICT'

contactAnalysis
{
    interval        1;
    touchingGap     0.01;
    releaseGap      0.02;
}
DICT
# the particles move as prescribed: no integration (a resumed run has them
# from the restart, and the same 'fix move' ids continue their motion)
cat > wavering.liggghts <<'DICT'
if "${colloid_restart} == 0" then &
    "create_atoms 1 single 49.5 50 25 units box" &
    "create_atoms 1 single 50.507 50 25 units box" &
    "create_atoms 1 single 20 0.507 25 units box"
unfix           integrate
group           still id 1
group           pairMover id 2
group           wallMover id 3
fix             still still move linear 0 0 0
fix             pairMover pairMover move wiggle -0.006 0 0 10
fix             wallMover wallMover move wiggle 0 -0.006 0 10
DICT
sed -i 's/^processors .*//; s/^boundary .*/&\nprocessors      * 1 1/' constant/DEM/in.liggghts
includeParticles wavering.liggghts
resumableBox
meshAndQuiescentFluid
runChannelSolver "$mode"
if [ -n "$resumeAt" ]
then
    [ -d "$resumeAt" ] || { echo "FAIL: no write at resumeAt $resumeAt (OpenFOAM's name, e.g. 5e-06)"; exit 1; }
    mv log.colloidDEMFoam log.colloidDEMFoam.to"$resumeAt"
    runLength 3e-05 250
    sed -i 's/^startFrom .*/startFrom       latestTime;/' system/controlDict
    runChannelSolver "$mode" resume
    grep -m1 "^Contact analysis: contact histories of time $resumeAt s read back" log.colloidDEMFoam \
        || { echo "FAIL: the resumed run did not read the contact histories of $resumeAt s back"; exit 1; }
fi
grep "^Contacts:" log.colloidDEMFoam | tail -1
python3 "$here/checkReleaseGap.py" .
