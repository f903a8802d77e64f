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
# Then the same pairs shifted by half the box across a periodic face
# (boundary p f f): serial, a pair with the image of an atom of its own
# rank is folded onto that atom and solved on the rank (the global solve
# must hold no particle), and must move as the unshifted pairs did (within
# 1e-7 um: a pair counted twice, once from each image, or dropped, moves
# differently); on 2 ranks the column on the periodic face lies across
# the ranks, and its 49 pairs (98 particles) must be the global solve's.
#
#   runBrownianParallelTest.sh liggghts plugin.so workDir
set -e
liggghts=$1
plugin=$2
work=$3
mkdir -p "$work"
cd "$work"
rm -f positions.* positions0.* periodic.* periodic0.*

# 343 pairs along x (0.3 um spheres, 5 nm gap), centres 1.5 um apart, the
# column at x = 0 across the boundary; ids written, so that both runs
# number them alike (create_atoms numbers them by rank)
pairsData()   # shift [um], output file: x shifted and wrapped into [-6, 6)
{
awk -v shift="$1" 'function wrap(x) { x += shift; return x >= 6 ? x - 12 : x }
BEGIN {
    n = 0
    for (i = -3; i <= 3; i++) for (j = -3; j <= 3; j++) for (k = -3; k <= 3; k++)
    {
        line[++n] = sprintf("%d 1 0.3 2.5 %.10f %.10f %.10f", n, wrap(1.5*i - 0.1525), 1.5*j, 1.5*k)
        line[++n] = sprintf("%d 1 0.3 2.5 %.10f %.10f %.10f", n, wrap(1.5*i + 0.1525), 1.5*j, 1.5*k)
    }
    print "lubricated pairs\n"
    print n " atoms\n2 atom types\n"
    print "-6 6 xlo xhi\n-6 6 ylo yhi\n-6 6 zlo zhi\n"
    print "Atoms\n"
    for (m = 1; m <= n; m++) print line[m]
}' > "$2"
}
pairsData 0 pairs.data
pairsData 6 periodic.data

cat > in.pairs <<'SCRIPT'
units           micro
atom_modify     map array sort 0 0.0
boundary        ${bx} f f
newton          off
communicate     single vel yes
processors      ${ranks} 1 1
atom_style      sphere
read_data       ${data}.data
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
write_dump      all custom ${out}0.${ranks} id x y z modify sort id format "%d %.15g %.15g %.15g"
run             300
write_dump      all custom ${out}.${ranks} id x y z modify sort id format "%d %.15g %.15g %.15g"
# particles in the solve across ranks per update (the plugin's statistic)
variable        global equal f_colloid_implicit[6]
print           "global solve: ${global} particles"
SCRIPT

source "$(dirname "$0")/liggghtsScriptRun.sh"
run()   # ranks boundary-x data output
{
    runLiggghts "$1" in.pairs "$4" -var bx "$2" -var data "$3" -var out "$4"
}
globalSolve()   # log: the statistic printed at the end
{
    sed -n 's/^global solve: \([0-9.e+-]*\) particles$/\1/p' "$1" | tail -1
}
run 1 f pairs positions
run 2 f pairs positions
run 1 p periodic periodic
run 2 p periodic periodic

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
         print "processor boundary: serial and 2 ranks agree"
     }' positions0.1 positions.1 positions.2

# The pairs across the periodic face: folded serial, global on 2 ranks
g1=$(globalSolve log.positions.1); g2=$(globalSolve log.positions.2)
p1=$(globalSolve log.periodic.1); p2=$(globalSolve log.periodic.2)
echo "particles in the global solve per update: processor boundary $g1 (serial) $g2 (2 ranks); periodic face $p1 (serial) $p2 (2 ranks)"
awk -v g1="$g1" -v g2="$g2" -v p1="$p1" -v p2="$p2" 'BEGIN {
    if (g1 == "" || g2 == "" || p1 == "" || p2 == "") { print "FAIL: no statistic of the global solve"; exit 1 }
    if (g1 != 0 || p1 != 0) { print "FAIL: a serial run with particles in the global solve"; exit 1 }
    if (g2 != 98 || p2 != 98) { print "FAIL: not the 98 particles of the 49 pairs across the ranks in the global solve"; exit 1 }
}' || exit 1

# The periodic runs against the unshifted serial run (x shifted back by
# 6 um and wrapped), and against each other
awk 'function back(x) { x -= 6; return x < -6 ? x + 12 : x }
     FNR == 1 { file++; on = 0 }
     /^ITEM: ATOMS/ { on = 1; next }
     !on { next }
     file == 1 { x1[$1] = $2; y1[$1] = $3; z1[$1] = $4; n1++ }
     file == 2 { n2++
                 if ($1 % 2 == 0 && $2 < -5 && prev > 5) across++
                 prev = $2 }
     file == 2 || file == 3 {
                 d = sqrt((back($2) - x1[$1])^2 + ($3 - y1[$1])^2 + ($4 - z1[$1])^2)
                 if (d > worst[file]) worst[file] = d }
     file == 3 { n3++ }
     END {
         printf "periodic face: %d pairs across it; largest difference from the unshifted serial run %.3g um (serial), %.3g um (2 ranks)\n", across, worst[2], worst[3]
         if (n1 == 0 || n1 != n2 || n1 != n3) { print "FAIL: atom counts"; exit 1 }
         if (across != 49) { print "FAIL: not the 49 pairs across the periodic face"; exit 1 }
         if (worst[2] > 1e-7 || worst[3] > 1e-7) { print "FAIL: the pairs across the periodic face move differently"; exit 1 }
         print "PASS"
     }' positions.1 periodic.1 periodic.2
