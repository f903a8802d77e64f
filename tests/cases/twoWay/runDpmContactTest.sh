#!/bin/bash
# The contact model of benchmarks/dpmFoamGoldschmidt is DPMFoam's: a head-on
# collision of two of the Goldschmidt spheres, and one onto a bottom wall,
# in the stock liggghts with the materials goldschmidtSetup.py derives from
# the DPMFoam tutorial, against DPMFoam's spring-slider-dashpot force law
# (Hertz with Tsuji's damping) integrated in checkDpmContact.py: the
# loss 1 - e and the contact's duration within 0.2 %, at 0.1, 1 and
# 3 m/s (velocities in um/us = m/s; the sphere starts 50 um from the wall,
# the pair 100 um apart).
#
# usage: runDpmContactTest.sh workDir
set -e
work=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/caseFunctions.sh"
bench="$COLLOIDFOAM_DIR/benchmarks/dpmFoamGoldschmidt"
tutorial=$(ls -d "$COLLOIDFOAM_DIR"/ThirdParty/openfoam-*/tutorials/lagrangian/DPMFoam/Goldschmidt | head -1)
copyCase "$bench/case" "$work"
python3 "$bench/goldschmidtSetup.py" "$tutorial" . 0.01 0.01 3
# the tutorial's sphere [um] and density [pg/um^3], as the setup wrote them
d=$(awk '$2 == "particleDiameter" {print $4}' constant/DEM/goldschmidt.liggghts)
rho=$(awk '$2 == "particleDensity" {print $4}' constant/DEM/goldschmidt.liggghts)
zPair1=3000
zPair2=$(python3 -c "print($zPair1 + $d + 100)")
zWall=$(python3 -c "print($d/2 + 50)")
for v in 0.1 1 3
do
    for target in pair wall
    do
        # velocities: um/us = m/s
        if [ "$target" = pair ]
        then
            atoms="create_atoms 1 single 0 0 $zPair1 units box
create_atoms 1 single 0 0 $zPair2 units box
group one id 1
group two id 2
velocity one set 0 0 $(python3 -c "print($v/2)") units box
velocity two set 0 0 $(python3 -c "print(-$v/2)") units box"
        else
            atoms="create_atoms 1 single 0 0 $zWall units box
velocity all set 0 0 -$v units box"
        fi
        steps=$(python3 -c "print(int(300/0.005 + 200/$v/0.005))")
        cat > in.collision <<IN
units           micro
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
region          box block -5000 5000 -5000 5000 0 10000 units box
create_box      3 box
$atoms
set group all diameter $d density $rho
include         constant/DEM/goldschmidt.liggghts
neighbor        200 bin
pair_style      gran model hertz tangential history
pair_coeff      * *
fix             bottom all wall/gran model hertz tangential history primitive type 2 zplane 0
fix             integrate all nve/sphere
timestep        0.005
variable        vz1 equal vz[1]
variable        z1 equal z[1]
variable        vz2 equal vz[2]
variable        z2 equal z[2]
run             $steps
print           "RESULT ${target} $v $(python3 -c "print($steps*0.005)") \${z1} \${vz1} $( [ $target = pair ] && echo '${z2} ${vz2}' || echo '0 0' )"
IN
        liggghts -in in.collision > log.$target.$v 2>&1 || { tail -20 log.$target.$v; exit 1; }
        grep "^RESULT" log.$target.$v | tail -1 >> results.txt
    done
done
python3 "$here/checkDpmContact.py" "$tutorial" results.txt
