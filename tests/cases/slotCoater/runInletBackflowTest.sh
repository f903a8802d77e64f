#!/bin/bash
# A particle that leaves the fluid back up through the inlet, next to the
# slot's wall where the liquid barely moves (as Brownian motion takes fed
# particles there): the tutorial's inlet outflow must remove it and count
# it; without it the particle, above the fluid and so free of drag, drifts
# to the DEM box's top face 1 um higher and is lost, and the run stops.
#
#   runInletBackflowTest.sh serial|parallel WORKDIR
#
# The tutorial at test size (testSizeCase.sh: inlet plane y = 15 um, the
# slot from x = 0 to 20 um), its own DEM script with, appended for the
# test, the particles within 0.5 um of (0.3, 14.8, span/2) um (0.2 um
# below the inlet) deleted and one particle placed at x = 0.2 um (0.05 um
# from the slot's upstream wall), 0.05 um below the inlet plane, moving
# up at 50 m/s (um/us).  The
# implicit drag of the still liquid stops it within about 50 m/s x 12.5 ns
# (its momentum relaxation time m/(6 pi mu a)) = 0.6 um: it crosses the
# plane within about 1 ns (2.5 DEM steps of 4e-10 s) and keeps about 90 % of its
# speed.
#
# Asserted: the run (Allrun, 0.2 us) ends without error (the coupling
# checks present = inserted - removed at every write: FatalError on a lost
# particle), and the inlet's outflow fix (inletBackflow) removed exactly
# this one particle.
set -e
here=$(cd "$(dirname "$0")" && pwd)
mode=$1
work=$2

set +u
source "$here/../../../etc/bashrc" || exit 1

source "$here/testSizeCase.sh"

# The test's particle: appended to the tutorial's own DEM script (a fresh
# run only; this test does not resume)
cat >> constant/DEM/in.liggghts <<'EOI'

# --- Test only (runInletBackflowTest.sh): a particle leaving up through
# the inlet next to the slot's upstream wall
variable        backflowZ equal 0.5*${span}
variable        backflowY equal ${yTop}-0.05
variable        backflowSpotY equal ${yTop}-0.2
region          backflowSpot sphere 0.3 ${backflowSpotY} ${backflowZ} 0.5 units box
delete_atoms    region backflowSpot
create_atoms    1 single 0.2 ${backflowY} ${backflowZ} units box
group           backflow region backflowSpot
set             group backflow diameter ${colloid_diameter} density ${colloid_density}
velocity        backflow set 0 50 0 units box
EOI

fail() { echo "FAIL: $*"; exit 1; }
case "$mode" in
serial)   ./Allrun -endTime 2e-7 ;;
parallel) ./Allrun -parallel -endTime 2e-7 ;;
*) echo "usage: $0 serial|parallel WORKDIR" 1>&2; exit 1 ;;
esac || { tail -20 log.colloidDEMFoam 2>/dev/null; fail "Allrun"; }

grep -a "^Particles: present\|^Removed per outflow fix:" log.colloidDEMFoam | tail -2
last=$(grep -a "^Removed per outflow fix:" log.colloidDEMFoam | tail -1)
[ -n "$last" ] || fail "no 'Removed per outflow fix' line in log.colloidDEMFoam"
inlet=$(echo "$last" | sed -n 's/.*inletBackflow \([0-9]*\).*/\1/p')
[ "$inlet" = 1 ] \
    || fail "the inlet's outflow removed '$inlet' particles, not the 1 that crossed it"
echo PASS
