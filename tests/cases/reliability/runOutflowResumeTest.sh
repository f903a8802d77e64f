#!/bin/bash
# A particle an outflow counted but has not deleted yet when the DEM state
# is written, then a resume (fix_colloid_reneighbor.h): it must be deleted
# and counted as removed, not kept by the restart and lost after the
# resume.
#
# The coupling test case (fluid 100 x 100 x 50 um, quiescent), the DEM box
# widened to x = 160 um, gravity off, two particles outside the fluid: one
# at x = 149.005 um moving at 1 m/s (= 1 um/us) in +x, one at rest at
# x = 120 um (LIGGGHTS cannot set up a run without particles): outside the
# fluid no force acts on them.  A massflow/mesh outflow plane at x = 150 um with
# delete_atoms (LIGGGHTS deletes a counted particle at the next rebuild of
# the neighbour lists); a neighbour skin of 16 um, so that the particle's
# own motion rebuilds the lists only every 8 um.  It crosses the plane at
# 0.995 us, 2.5 DEM steps (5e-9 s) before the write at 1 us.
#   part 1: 'write': from 0 to 1.2 us, writing every 50 steps: 1 us is a
#           write time within the run; 'end': from 0 to 1 us, writing
#           every 60 steps: 1 us is written only as the end time, which
#           the solver writes anyway (a resumed study run ends so);
#   part 2: resumed from the write at 1 us to 12 us; the particle would
#           leave the DEM box at 11 us (x = 160 um).
# Asserted: both parts end without error, the moving particle removed
# (present 1, inserted 2, removed 1) and none lost.
#
# Serial, or on 2 ranks (fluid by METIS, DEM spatially; the particle on
# the upper rank in x).
#
#   runOutflowResumeTest.sh serial|parallel write|end workDir
set -e
mode=$1
at=$2
work=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/testEnvironment.sh"
case $mode in
serial)   run() { colloidDEMFoam > "$1" 2>&1; } ;;
parallel) run() { mpirun -np 2 colloidDEMFoam -parallel > "$1" 2>&1; } ;;
*)  echo "usage: $0 serial|parallel write|end workDir" 1>&2; exit 1 ;;
esac
case $at in
write) writeInterval=50; endTime=1.2e-06 ;;
end)   writeInterval=60; endTime=1e-06 ;;
*)  echo "usage: $0 serial|parallel write|end workDir" 1>&2; exit 1 ;;
esac

rm -rf "$work"
mkdir -p "$(dirname "$work")"
cp -r "$here/../coupling/case" "$work"
cd "$work"
# The DEM script: a fresh start creates the particles, a resume reads them
cat > constant/DEM/in.liggghts <<'EOI'
newton          off
if "${colloid_restart} == 0" then &
    "atom_style      sphere" &
    "boundary        f f f" &
    "region          domain block 0 160 0 100 0 50 units box" &
    "create_box      1 domain" &
    "create_atoms    1 single 149.005 40 20 units box" &
    "create_atoms    1 single 120 40 20 units box" &
    "set             group all diameter ${colloid_diameter} density ${colloid_density}" &
    "group           mover id 1" &
    "velocity        mover set 1 0 0 units box" &
else &
    "read_restart    ${colloid_restart_file}"
communicate     single vel yes

neighbor        16 bin
neigh_modify    delay 0

fix             m1 all property/global youngsModulus peratomtype 1e5
fix             m2 all property/global poissonsRatio peratomtype 0.3
fix             m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix             m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style      gran model hertz tangential history
pair_coeff      * *

fix             integrate all nve/sphere

# Outflow: a plane at x = 150 um across the box (y 0..100, z 0..50 um)
fix             outMesh all mesh/surface file ${colloid_case}/outflow.stl type 1
fix             outflow all massflow/mesh mesh outMesh vec_side 1 0 0 &
                count once delete_atoms yes
EOI
cat > outflow.stl <<'EOI'
solid outflow
  facet normal 1 0 0
    outer loop
      vertex 150 0 0
      vertex 150 100 0
      vertex 150 100 50
    endloop
  endfacet
  facet normal 1 0 0
    outer loop
      vertex 150 0 0
      vertex 150 100 50
      vertex 150 0 50
    endloop
  endfacet
endsolid outflow
EOI
sed -i 's/^value .*/value (0 0 0);/' constant/g
foamDictionary system/controlDict -entry endTime -set $endTime > /dev/null
foamDictionary system/controlDict -entry writeInterval -set $writeInterval > /dev/null
blockMesh > log.blockMesh 2>&1
mkdir -p 0
postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
python3 "$here/../coupling/setPoiseuilleU.py" . 1e-4 0

fail() { echo "FAIL: $*"; exit 1; }
if [ "$mode" = parallel ]
then
    decomposePar > log.decomposePar 2>&1 || { tail log.decomposePar; fail "decomposePar"; }
fi
run log.part1 || { tail -20 log.part1; fail "part 1"; }
[ -f 1e-06/uniform/colloidCoupling ] || [ -f processor0/1e-06/uniform/colloidCoupling ] \
    || fail "no complete write at 1e-06"
grep -a "^Particles:" log.part1 | tail -1

foamDictionary system/controlDict -entry startFrom -set startTime > /dev/null
foamDictionary system/controlDict -entry startTime -set 1e-06 > /dev/null
foamDictionary system/controlDict -entry endTime -set 1.2e-05 > /dev/null
run log.part2 || { tail -12 log.part2; fail "part 2 (the resumed run) stopped"; }
grep -a "^Particles:" log.part2 | tail -1
grep -a -q "^Particles: present 1, inserted 2, removed 1" log.part2 \
    || fail "the particle is not counted as removed at the end"
echo PASS
