#!/bin/bash
# Weak pairs damped explicitly (lubricationExplicitRatio,
# fix_colloid_implicit.h) across a processor boundary, serial against 2
# ranks: the 108-particle FCC block of the stiff test
# weakPairsExplicitMixedBlock (0.3 um spheres, nearest gaps 0.2 um, the
# two-sphere form to 0.4 um (the fade starts beyond the nearest gap, the
# next neighbours are 0.41 um apart), c dt/m 0.058 for the nearest pairs,
# no drag, random velocities), centred on the boundary x = 0 of
# 'processors 2 1 1'.  An inner particle's twelve pairs add up to 0.70
# and stay in the solve; pairs between particles of the surface (at most
# eight neighbours: 0.46) go explicit; a pair is explicit only if both particles' sums are within
# 1/2, so a pair across the boundary needs its ghost's sum, which the
# update communicates.  Both runs must mix explicit and implicit pairs
# (the shares differ: a pair across ranks counts on both) and agree in
# position within 1e-9 um after 400 steps
# (the particles move about 5e-3 um); a rank that took a pair explicit
# while the other kept it in the solve would push its two particles
# unequally.
#
#   runWeakPairsParallelTest.sh liggghts plugin.so workDir
set -e
liggghts=$1
plugin=$2
work=$3
mkdir -p "$work"
cd "$work"
rm -f positions.*

# FCC 3 x 3 x 3 cells, cell sqrt(2) (2R + 0.2 um), centred on x = y = 0;
# velocities up to 0.01 um/us in each component from a fixed sequence
awk 'BEGIN {
    R = 0.15; L = sqrt(2)*(2*R + 0.2); n = 0
    split("0 0 0 0.5 0.5 0 0.5 0 0.5 0 0.5 0.5", b, " ")
    srand(12345)
    for (i = 0; i < 3; i++) for (j = 0; j < 3; j++) for (k = 0; k < 3; k++) for (q = 0; q < 4; q++)
    {
        n++
        atoms[n] = sprintf("%d 1 0.3 2.5 %.12f %.12f %.12f", n, (i + b[3*q + 1] - 1.25)*L, (j + b[3*q + 2] - 1.25)*L, (k + b[3*q + 3] - 1.25)*L)
        vel[n] = sprintf("%d %.12f %.12f %.12f", n, 0.02*(rand() - 0.5), 0.02*(rand() - 0.5), 0.02*(rand() - 0.5))
    }
    print "FCC block\n" > "block.data"
    print n " atoms\n2 atom types\n" > "block.data"
    print "-4 4 xlo xhi\n-4 4 ylo yhi\n-4 4 zlo zhi\n" > "block.data"
    print "Atoms\n" > "block.data"
    for (m = 1; m <= n; m++) print atoms[m] > "block.data"
    print "\nVelocities\n" > "block.data"
    for (m = 1; m <= n; m++) print vel[m] " 0 0 0" > "block.data"
}'

# c dt/m = 0.058 at the nearest gap 0.2 um: c = 3 pi mu R (1/G - 1),
# G(u) = (6u^2 + 4u)/(6u^2 + 13u + 2) at u = 4/3
dt=$(awk 'BEGIN { pi = atan2(0, -1); R = 0.15; u = 0.2/R
                  G = (6*u*u + 4*u)/(6*u*u + 13*u + 2); c = 3*pi*R*(1/G - 1)
                  m = 2.5*4/3*pi*R^3; printf "%.12g", 0.058*m/c }')

source "$(dirname "$0")/liggghtsScriptRun.sh"
{ twoSphereLubricationScript block.data 1000 0.4 '0.25' 0.1
cat <<'SCRIPT'
run             400
variable        share equal f_colloid_implicit[7]
print           "explicit share ${share}"
write_dump      all custom positions.${ranks} id x y z modify sort id format "%d %.15g %.15g %.15g"
SCRIPT
} > in.block

runLiggghts 1 in.block block -var dt "$dt"
runLiggghts 2 in.block block -var dt "$dt"

share1=$(awk '/^explicit share/ { print $3 }' log.block.1)
share2=$(awk '/^explicit share/ { print $3 }' log.block.2)
echo "explicit share: serial $share1, 2 ranks $share2"
for share in "$share1" "$share2"
do
    awk -v s="$share" 'BEGIN { exit !(s > 0 && s < 1) }' \
        || { echo "FAIL: a share of $share is not a mix of explicit and implicit pairs"; exit 1; }
done

awk 'FNR == 1 { file++; on = 0 }
     /^ITEM: ATOMS/ { on = 1; next }
     !on { next }
     file == 1 { x[$1] = $2; y[$1] = $3; z[$1] = $4; n1++ }
     file == 2 { n2++
                 d = sqrt(($2 - x[$1])^2 + ($3 - y[$1])^2 + ($4 - z[$1])^2)
                 if (d > worst) worst = d }
     END {
         if (n1 != 108 || n2 != 108) { print "FAIL: atom counts " n1 " " n2; exit 1 }
         printf "largest position difference, serial against 2 ranks: %.3g um\n", worst
         if (worst > 1e-9) { print "FAIL: serial and 2 ranks differ"; exit 1 }
         print "PASS"
     }' positions.1 positions.2
