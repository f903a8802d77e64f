#!/bin/bash
# The two-sphere lubrication's flow factor across a processor boundary:
# 343 pairs of 0.3 um spheres (gap 50 nm) along x, each in its own
# compressional flow along its line of centres, u_f = -E (x - X) at both
# spheres (X the pair's centre, E = 1e4 1/s, set once: the relative
# velocity of the liquid at the two centres stays E (2a + h0)), with the
# coupling's Stokes drag and lubricationFarField 1; the column of pairs at
# x = 0 straddles the boundary of 'processors 2 1 1'.  The flow factor
# needs the liquid's velocity at a ghost partner, which the implicit
# update communicates: every pair must close by the same gap (within
# 1e-9 um) in serial and on 2 ranks, and the two runs' positions agree
# within 1e-7 um (the global solve's residual 1e-10).  Every pair closes
# from 50 nm to 32.7 nm in 10 us (the near-field form: to 37.2 nm); with
# the communication left out, the pairs across the boundary close to
# 36.5 nm only, and the test fails.
# With a fourth argument, lubricationExplicitRatio (weak pairs damped
# explicitly, fix_colloid_implicit.h), the same at a tenth of the step
# (c dt/m at most 0.15), where every pair is damped explicitly (the
# update's share must be 1; without it, 0): the explicit damping needs the
# liquid's velocity and the weak pairs' sums at ghost partners.
#
#   runPairFlowParallelTest.sh liggghts plugin.so workDir [explicitRatio]
set -e
liggghts=$1
plugin=$2
work=$3
explicitRatio=${4:-0}
if awk -v r="$explicitRatio" 'BEGIN { exit !(r + 0 == 0) }'; then dt=0.01; steps=1000; else dt=0.001; steps=10000; fi
mkdir -p "$work"
cd "$work"
rm -f positions.* flow.*

# 686 atoms: pairs at (1.5 i, 1.5 j, 1.5 k), spheres at X -/+ 0.175 um;
# the liquid's velocity -E (x - X) [um/us], E = 0.01 1/us
awk 'BEGIN {
    n = 0
    for (i = -3; i <= 3; i++) for (j = -3; j <= 3; j++) for (k = -3; k <= 3; k++)
        for (s = -1; s <= 1; s += 2)
        {
            n++
            atoms[n] = sprintf("%d 1 0.3 2.5 %.10f %.10f %.10f", n, 1.5*i + s*0.175, 1.5*j, 1.5*k)
            flow[n] = sprintf("set atom %d property/atom uf %.12f 0 0", n, -0.01*s*0.175)
        }
    print "pairs in compression\n" > "pairs.data"
    print n " atoms\n2 atom types\n" > "pairs.data"
    print "-6 6 xlo xhi\n-6 6 ylo yhi\n-6 6 zlo zhi\n" > "pairs.data"
    print "Atoms\n" > "pairs.data"
    for (m = 1; m <= n; m++) { print atoms[m] > "pairs.data"; print flow[m] > "flow.in" }
}'

source "$(dirname "$0")/liggghtsScriptRun.sh"
{ twoSphereLubricationScript pairs.data 1 0.5 '${explicitRatio}' 0.05
cat <<'SCRIPT'
# Stokes drag 6 pi mu R (pg/us) towards the liquid's velocity
fix Ksl all property/atom Ksl scalar yes no no 2.827433388230814
fix uf all property/atom uf vector yes no no 0 0 0
run             0
include         flow.in
run             ${steps}
variable        share equal f_colloid_implicit[7]
print           "explicit share ${share}"
write_dump      all custom positions.${ranks} id x y z modify sort id format "%d %.15g %.15g %.15g"
SCRIPT
} > in.pairs

for ranks in 1 2
do
    runLiggghts $ranks in.pairs pairs -var explicitRatio "$explicitRatio" -var dt $dt -var steps $steps
done
wanted=$(awk -v r="$explicitRatio" 'BEGIN { print (r + 0 == 0) ? 0 : 1 }')
for n in 1 2
do
    share=$(awk '/^explicit share/ { print $3 }' "log.pairs.$n")
    echo "explicit share on $n rank(s): $share"
    [ "$share" = "$wanted" ] || { echo "FAIL: explicit share $share on $n rank(s), wanted $wanted"; exit 1; }
done

# each pair's gap (ids 2m - 1 and 2m), in both runs
awk 'FNR == 1 { file++; on = 0 }
     /^ITEM: ATOMS/ { on = 1; next }
     !on { next }
     file == 1 { x1[$1] = $2; y1[$1] = $3; z1[$1] = $4; n1++ }
     file == 2 { n2++
                 d = sqrt(($2 - x1[$1])^2 + ($3 - y1[$1])^2 + ($4 - z1[$1])^2)
                 if (d > worst) worst = d
                 x2[$1] = $2 }
     END {
         if (n1 != 686 || n2 != 686) { print "FAIL: atom counts " n1 " " n2; exit 1 }
         for (m = 2; m <= n1; m += 2)
         {
             g1 = x1[m] - x1[m - 1] - 0.3; g2 = x2[m] - x2[m - 1] - 0.3
             if (m == 2 || g1 < lo1) lo1 = g1; if (m == 2 || g1 > hi1) hi1 = g1
             if (m == 2 || g2 < lo2) lo2 = g2; if (m == 2 || g2 > hi2) hi2 = g2
         }
         printf "gaps after 10 us (from 0.05 um): serial %.9f to %.9f um, 2 ranks %.9f to %.9f um; largest position difference %.3g um\n", lo1, hi1, lo2, hi2, worst
         if (!(hi1 < 0.045)) { print "FAIL: the pairs did not close"; exit 1 }
         if (hi1 - lo1 > 1e-9 || hi2 - lo2 > 1e-9) { print "FAIL: pairs closed by different gaps"; exit 1 }
         if (worst > 1e-7) { print "FAIL: serial and 2 ranks differ"; exit 1 }
         print "PASS"
     }' positions.1 positions.2
