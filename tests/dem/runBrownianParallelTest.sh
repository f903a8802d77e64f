#!/bin/bash
# Brownian motion with lubrication noise, serial against 2 ranks: pairs
# of lubricated spheres, many of them straddling the processor boundary
# (x = 0, 'processors 2 1 1'), with drag and Brownian motion, 300 steps
# of the stock liggghts with the plugin preloaded, once on 1 rank and
# once on 2.  Each pair's noise is drawn from both atoms' ids, so both
# ranks of a pair across the boundary give it the same impulse: the
# positions must agree within 1e-7 um (the global conjugate-gradient solve
# of a pair across ranks against the serial direct solve: relative
# residual 1e-10), against a mean Brownian displacement of about 3e-4 um.
#
#   runBrownianParallelTest.sh liggghts plugin.so workDir
set -e
liggghts=$1
plugin=$2
work=$3
mkdir -p "$work"
cd "$work"
rm -f positions.* positions0.*

# 343 pairs along x (0.3 um spheres, 5 nm gap), centres 1.5 um apart, the
# column at x = 0 across the boundary; ids written, so that both runs
# number them alike (create_atoms numbers them by rank)
awk 'BEGIN {
    n = 0
    for (i = -3; i <= 3; i++) for (j = -3; j <= 3; j++) for (k = -3; k <= 3; k++)
    {
        line[++n] = sprintf("%d 1 0.3 2.5 %.10f %.10f %.10f", n, 1.5*i - 0.1525, 1.5*j, 1.5*k)
        line[++n] = sprintf("%d 1 0.3 2.5 %.10f %.10f %.10f", n, 1.5*i + 0.1525, 1.5*j, 1.5*k)
    }
    print "lubricated pairs\n"
    print n " atoms\n2 atom types\n"
    print "-6 6 xlo xhi\n-6 6 ylo yhi\n-6 6 zlo zhi\n"
    print "Atoms\n"
    for (m = 1; m <= n; m++) print line[m]
}' > pairs.data

cat > in.pairs <<'SCRIPT'
units           micro
atom_modify     map array sort 0 0.0
boundary        f f f
newton          off
communicate     single vel yes
processors      ${ranks} 1 1
atom_style      sphere
read_data       pairs.data
fix m1 all property/global loadingStiffness peratomtypepair 2 1000 1000 1000 1000
fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5
fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3
fix l1 all property/global liquidViscosity scalar 1.0
fix l2 all property/global lubricationInnerCutoff scalar 0.001
fix l3 all property/global lubricationOuterCutoff scalar 0.1
neighbor        0.05 bin
neigh_modify    delay 0
pair_style      gran model walton_braun tangential history cohesion colloid/lub
pair_coeff      * *
timestep        0.0001
fix integrate all nve/sphere
# Stokes drag 6 pi mu R (pg/us) into liquid at rest, and Brownian motion
fix Ksl all property/atom Ksl scalar yes no no 2.827433388230814
fix uf all property/atom uf vector yes no no 0 0 0
fix bT all property/global brownianTemperature scalar 293.15
fix bS all property/global brownianSeed scalar 8128
write_dump      all custom positions0.${ranks} id x y z modify sort id format "%d %.15g %.15g %.15g"
run             300
write_dump      all custom positions.${ranks} id x y z modify sort id format "%d %.15g %.15g %.15g"
SCRIPT

LD_PRELOAD="$plugin" "$liggghts" -in in.pairs -var ranks 1 -log log.serial > screen.serial 2>&1 \
    || { echo "FAIL: the serial run"; tail -20 screen.serial; exit 1; }
LD_PRELOAD="$plugin" mpirun -np 2 -x LD_PRELOAD "$liggghts" -in in.pairs -var ranks 2 \
    -log log.parallel > screen.parallel 2>&1 \
    || { echo "FAIL: the 2-rank run"; tail -20 screen.parallel; exit 1; }

# The runs' positions against each other (and the serial run's against
# the start: the Brownian displacement); pairs across the boundary: both
# atoms of a pair on either side of x = 0
awk 'FNR == 1 { file++; on = 0 }
     /^ITEM: ATOMS/ { on = 1; next }
     !on { next }
     file == 1 { x0[$1] = $2; y0[$1] = $3; z0[$1] = $4 }
     file == 2 { x1[$1] = $2; y1[$1] = $3; z1[$1] = $4; n1++
                 moved += sqrt(($2 - x0[$1])^2 + ($3 - y0[$1])^2 + ($4 - z0[$1])^2) }
     file == 3 { n2++
                 d = sqrt(($2 - x1[$1])^2 + ($3 - y1[$1])^2 + ($4 - z1[$1])^2)
                 if (d > worst) worst = d
                 if ($1 % 2 == 0 && x1[$1] > 0 && x1[$1 - 1] < 0) across++ }
     END {
         printf "%d and %d atoms, %d pairs across x = 0; mean displacement %.3g um, largest difference serial - 2 ranks %.3g um\n", n1, n2, across, moved/n1, worst
         if (n1 == 0 || n1 != n2) { print "FAIL: atom counts"; exit 1 }
         if (across != 49) { print "FAIL: not the 49 pairs across the boundary"; exit 1 }
         if (moved/n1 < 1e-4) { print "FAIL: no Brownian motion"; exit 1 }
         if (worst > 1e-7) { print "FAIL: serial and 2 ranks differ"; exit 1 }
         print "PASS"
     }' positions0.1 positions.1 positions.2
