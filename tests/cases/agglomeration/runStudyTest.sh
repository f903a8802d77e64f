#!/bin/bash
# The agglomeration study's driver (tutorials/slotCoater/Allstudy) on a copy
# of the tutorial: one case (isoelectricBrownianSlowWeb) for two coupling
# steps at the study's size, and its numerical variant
# (isoelectricBrownianSlowWebSoftContacts) for one, then the report.
# Asserted: the case holds the
# study's settings (span 5 um, zeta 0, DEM step 4e-10 s, 25 steps per
# coupling step, Brownian motion on, a write every 5 us) and the flow
# change's (web 0.1 m/s; the steady flow's inflow half the full speed's,
# 0.1 m/s x 20 um wet film x 5 um span = 1e-11 m^3/s, within 1e-6), an
# unknown case name
# stops everything before a run, the run reaches its end
# with the fill of the 5 um span (between 1.9e5 and 2.1e5 particles, 0.05
# of the gap and the slot), a second set-up of the same case without
# -resume stops naming the folder, and the report writes its tables (a row
# for the case in summary.md and milestones.md, and in where.md: no agglomerate after two
# steps from a fill 100 nm apart; in gaps.md: no pair within 50 nm) and
# its plots.  The variant: contactStiffness 0.25 N/m, written for the DEM
# as K1 250 nN/um, K_T0 2/7 of it and the walls' E 1.25e4 (1e3 Pa: 1e8 Pa
# as K1^3/2), DEM
# step 8e-10 s, fluid step 2e-8 s, a write every 250 fluid steps (5 us);
# the DEM's printed contact duration and tangential half-period of two
# particles twice the case's (K1^-1/2, within 1e-5); the report's variants.md row for the pair;
# SoftContacts before SlowWeb refused.  The soft variant's own variant
# isoelectricBrownianSlowWebSoftContactsShortRange for one step: the three
# outer cut-offs 0.025 um (written for the DEM in um), the soft variant's
# settings kept, its variants.md row beside the soft variant; ShortRange
# before SoftContacts, and two cut-off suffixes, refused.  Its model
# variant isoelectricBrownianSlowWebSoftContactsTwoSphere for one step:
# lubricationForm twoSphere with the lubrication's outer cut-off 0.15 um
# (written for the DEM: lubricationFarField 1, 0.15 um), the other
# cut-offs and the soft variant's settings kept, its variants.md row;
# TwoSphere before SoftContacts, and a cut-off suffix after TwoSphere,
# refused.  Its numerical variant ...TwoSphereExplicit for one step:
# lubricationExplicitRatio 0.25 (written for the DEM), the rest as the
# two-sphere case, the solver's log naming the share of pairs damped
# explicitly, its variants.md row beside the two-sphere case; Explicit
# before TwoSphere refused.  A -resume of the soft variant to 4e-8 s
# reaches it with the set-up's lines still in the study log.
#
# usage: runStudyTest.sh workDir
set -e
export PYTHONDONTWRITEBYTECODE=1
work=$1
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

rm -rf "$work"
mkdir -p "$work"
cp -r "$COLLOIDFOAM_DIR/tutorials/slotCoater" "$work/"
cd "$work/slotCoater"
rm -rf study results

fail() { echo "FAIL: $*"; exit 1; }

# Allstudy refuses the names (arguments after -endTime 2e-8) naming the
# unknown case $1, before any run
refused()
{
    local unknown=$1
    shift
    if ./Allstudy -endTime 2e-8 "$@" > refused.out 2>&1
    then
        fail "$* was accepted"
    fi
    grep -q "unknown case '$unknown'" refused.out || { cat refused.out; fail "message for $unknown"; }
}
# an unknown case stops before any run
refused noSuchCase isoelectricBrownianSlowWeb noSuchCase
# the flow change's suffix goes last
refused isoelectricSlowWebBrownian isoelectricSlowWebBrownian
# the numerical variant's suffix goes last
refused isoelectricSoftContactsSlowWeb isoelectricSoftContactsSlowWeb
# the cut-offs' suffix goes after SoftContacts
refused isoelectricShortRangeSoftContacts isoelectricShortRangeSoftContacts
# one cut-off suffix at most
refused isoelectricLongRangeShortRange isoelectricLongRangeShortRange
# the model's suffix goes after SoftContacts, and no cut-off suffix after it
refused isoelectricTwoSphereSoftContacts isoelectricTwoSphereSoftContacts
refused isoelectricTwoSphereShortRange isoelectricTwoSphereShortRange
refused isoelectricTwoSphereExplicitShortRange isoelectricTwoSphereExplicitShortRange
# the explicit damping's suffix goes after TwoSphere
refused isoelectricExplicitTwoSphere isoelectricExplicitTwoSphere
[ ! -d study ] || fail "a case was set up before the unknown one was refused"

./Allstudy -endTime 2e-8 isoelectricBrownianSlowWeb > allstudy.out 2>&1 \
    || { cat allstudy.out; tail -20 study/isoelectricBrownianSlowWeb.log; fail "Allstudy"; }
case=study/isoelectricBrownianSlowWeb
value() { awk -v k="$2" '$1 == k { sub(";", "", $2); print $2; exit }' "$1"; }
[ "$(value $case/system/slotCoaterParameters span)" = 5e-6 ] || fail "span"
[ "$(value $case/system/slotCoaterParameters zetaPotential)" = 0 ] || fail "zetaPotential"
[ "$(value $case/constant/couplingProperties timeStep)" = 4e-10 ] || fail "DEM timeStep"
[ "$(value $case/constant/couplingProperties couplingInterval)" = 25 ] || fail "couplingInterval"
[ "$(value $case/system/controlDict writeInterval)" = 500 ] || fail "writeInterval"
grep -q "^Brownian motion: 293.15 K, seed 1" $case/log.colloidDEMFoam || fail "no Brownian motion"
[ "$(value $case/system/slotCoaterParameters webSpeed)" = 0.1 ] || fail "webSpeed"
grep -q "^variable webSpeed equal 0.1$" $case/DEM/slotCoater.liggghts || fail "web speed not written for the DEM"
inflow=$(sed -n 's/^Steady flow converged .*(inflow \([^ ]*\) m^3\/s.*/\1/p' $case.log)
echo "steady flow's inflow: $inflow m^3/s"
awk -v q="$inflow" 'BEGIN { exit !(q != "" && (q < 0 ? -q : q) > 1e-11*(1 - 1e-6) && (q < 0 ? -q : q) < 1e-11*(1 + 1e-6)) }' \
    || fail "inflow '$inflow', not 1e-11 m^3/s"
grep -q "^variable zetaPotential equal 0$" $case/DEM/slotCoater.liggghts || fail "zeta not written for the DEM"
[ -f $case/2e-08/uniform/colloidCoupling ] || fail "the run did not reach 2e-08"
n=$(awk '/^Particles: present/ { sub(",", "", $3); print $3 }' $case/log.colloidDEMFoam | tail -1)
echo "particles present at the end: $n"
awk -v n="$n" 'BEGIN { exit !(n >= 1.9e5 && n <= 2.1e5) }' || fail "$n particles, not the 5 um span's 2.0e5"

# the numerical variant: softer contacts at twice the DEM step
./Allstudy -endTime 2e-8 isoelectricBrownianSlowWebSoftContacts > soft.out 2>&1 \
    || { cat soft.out; tail -20 study/isoelectricBrownianSlowWebSoftContacts.log; fail "Allstudy soft"; }
soft=study/isoelectricBrownianSlowWebSoftContacts
[ "$(value $soft/system/slotCoaterParameters contactStiffness)" = 0.25 ] || fail "contactStiffness"
[ "$(value $soft/constant/couplingProperties timeStep)" = 8e-10 ] || fail "soft DEM timeStep"
[ "$(value $soft/system/controlDict deltaT)" = 2e-8 ] || fail "soft deltaT"
[ "$(value $soft/system/controlDict writeInterval)" = 250 ] || fail "soft writeInterval"
[ "$(value $soft/system/slotCoaterParameters webSpeed)" = 0.1 ] || fail "soft webSpeed"
grep -q "^Brownian motion: 293.15 K, seed 1" $soft/log.colloidDEMFoam || fail "soft: no Brownian motion"
grep -q "^variable contactStiffness equal 250$" $soft/DEM/slotCoater.liggghts || fail "K1 for the DEM"
grep -q "^variable tangentialStiffness equal 71.42857143$" $soft/DEM/slotCoater.liggghts || fail "K_T0 for the DEM"
grep -q "^variable wallYoungsModulus equal 12500$" $soft/DEM/slotCoater.liggghts || fail "E for the DEM"
grep -q "^variable contactStiffness equal 1000$" $case/DEM/slotCoater.liggghts || fail "the case's K1"
# the printed limits of the DEM's log: normal and tangential, K1^-1/2
limitOf() { sed -n "s/.*$2: \([^ ]*\) s.*/\1/p" "$1" | head -1; }
for limit in "Walton-Braun contact duration of two of the lightest particles" \
             "tangential half-period of two of the lightest particles"
do
    d=$(limitOf $case/log.liggghts "$limit"); ds=$(limitOf $soft/log.liggghts "$limit")
    echo "$limit: $d s, soft $ds s"
    awk -v d="$d" -v s="$ds" 'BEGIN { exit !(d > 0 && s > 0 && (s/d - 2 < 1e-5) && (2 - s/d < 1e-5)) }' \
        || fail "soft $limit $ds s, not twice $d s"
done
[ -f $soft/2e-08/uniform/colloidCoupling ] || fail "the soft run did not reach 2e-08"
[ "$(value $soft/system/slotCoaterParameters vdwOuterCutoff)" = 0.05e-6 ] || fail "soft: the tutorial's cut-off"

# the variant's variant: its colloid cut-offs at 0.025 um (the error
# study's colloidRange), all else as the soft variant
./Allstudy -endTime 2e-8 isoelectricBrownianSlowWebSoftContactsShortRange > short.out 2>&1 \
    || { cat short.out; tail -20 $soft.log; fail "Allstudy short range"; }
short=${soft}ShortRange
for cutoff in vdwOuterCutoff doubleLayerOuterCutoff lubricationOuterCutoff
do
    [ "$(value $short/system/slotCoaterParameters $cutoff)" = 0.025e-6 ] || fail "short range: $cutoff"
    grep -q "^variable $cutoff equal 0.025$" $short/DEM/slotCoater.liggghts \
        || fail "short range: $cutoff not written for the DEM (um)"
done
[ "$(value $short/system/slotCoaterParameters contactStiffness)" = 0.25 ] || fail "short range: contactStiffness"
[ "$(value $short/constant/couplingProperties timeStep)" = 8e-10 ] || fail "short range: DEM timeStep"
[ "$(value $short/system/slotCoaterParameters webSpeed)" = 0.1 ] || fail "short range: webSpeed"
grep -q "^Brownian motion: 293.15 K, seed 1" $short/log.colloidDEMFoam || fail "short range: no Brownian motion"
[ -f $short/2e-08/uniform/colloidCoupling ] || fail "the short-range run did not reach 2e-08"

# the variant's model variant: the two-sphere hydrodynamics, the
# lubrication's cut-off at a radius, all else as the soft variant
./Allstudy -endTime 2e-8 isoelectricBrownianSlowWebSoftContactsTwoSphere > twoSphere.out 2>&1 \
    || { cat twoSphere.out; tail -20 $soft.log; fail "Allstudy two-sphere"; }
two=${soft}TwoSphere
[ "$(value $two/system/slotCoaterParameters lubricationForm)" = twoSphere ] || fail "two-sphere: lubricationForm"
[ "$(value $two/system/slotCoaterParameters lubricationOuterCutoff)" = 0.15e-6 ] || fail "two-sphere: its cut-off"
grep -q "^variable lubricationFarField equal 1$" $two/DEM/slotCoater.liggghts \
    || fail "two-sphere: lubricationFarField not written for the DEM"
grep -q "^variable lubricationOuterCutoff equal 0.15$" $two/DEM/slotCoater.liggghts \
    || fail "two-sphere: the cut-off not written for the DEM (um)"
grep -q "^variable lubricationFarField equal 0$" $soft/DEM/slotCoater.liggghts \
    || fail "soft: not the near-field form"
for cutoff in vdwOuterCutoff doubleLayerOuterCutoff
do
    [ "$(value $two/system/slotCoaterParameters $cutoff)" = 0.05e-6 ] || fail "two-sphere: $cutoff"
done
[ "$(value $two/system/slotCoaterParameters contactStiffness)" = 0.25 ] || fail "two-sphere: contactStiffness"
[ "$(value $two/system/slotCoaterParameters webSpeed)" = 0.1 ] || fail "two-sphere: webSpeed"
[ -f $two/2e-08/uniform/colloidCoupling ] || fail "the two-sphere run did not reach 2e-08"
grep -q "^variable lubricationExplicitRatio equal 0$" $two/DEM/slotCoater.liggghts \
    || fail "two-sphere: every pair in the solve not written for the DEM"

# its numerical variant: the weak pairs damped explicitly, all else kept
./Allstudy -endTime 2e-8 isoelectricBrownianSlowWebSoftContactsTwoSphereExplicit > explicit.out 2>&1 \
    || { cat explicit.out; tail -20 ${two}Explicit.log; fail "Allstudy explicit"; }
explicit=${two}Explicit
[ "$(value $explicit/system/slotCoaterParameters lubricationExplicitRatio)" = 0.25 ] || fail "explicit: the ratio"
[ "$(value $explicit/system/slotCoaterParameters lubricationForm)" = twoSphere ] || fail "explicit: lubricationForm"
[ "$(value $explicit/system/slotCoaterParameters lubricationOuterCutoff)" = 0.15e-6 ] || fail "explicit: the cut-off"
[ "$(value $explicit/system/slotCoaterParameters contactStiffness)" = 0.25 ] || fail "explicit: contactStiffness"
grep -q "^variable lubricationExplicitRatio equal 0.25$" $explicit/DEM/slotCoater.liggghts \
    || fail "explicit: the ratio not written for the DEM"
grep -Eq "^Implicit update of lubrication and drag: .* ([0-9.e+-]+) % of the lubricated pairs damped explicitly" \
    $explicit/log.colloidDEMFoam || fail "explicit: no share in the solver's log"
share=$(sed -n 's/^Implicit update of lubrication and drag: .*; \(.*\) % of the lubricated pairs damped explicitly$/\1/p' \
    $explicit/log.colloidDEMFoam | tail -1)
awk -v s="$share" 'BEGIN { exit !(s > 0 && s <= 100) }' || fail "explicit: $share % of the pairs damped explicitly"

if ./Allstudy -endTime 2e-8 isoelectricBrownianSlowWeb > again.out 2>&1
then
    fail "a second set-up of the case did not stop"
fi
grep -q "study/isoelectricBrownianSlowWeb exists: add -resume" again.out || { cat again.out; fail "message"; }

./Allstudy -report > report.out 2>&1 || { cat report.out; fail "report"; }
grep -q "^| isoelectricBrownianSlowWeb | 0.02 |" results/summary.md || { cat results/summary.md; fail "summary row"; }
[ -s results/contacts.png ] || fail "no contacts.png"
# two steps reach no milestone: the end's row only, no contact yet
grep -q "^| isoelectricBrownianSlowWeb | 0.02 | 0 | 0 | 0 | 0 (0 %) | 0 | 0 / 0 | 0 |" results/milestones.md \
    || { cat results/milestones.md; fail "milestones row"; }
grep -q "^| isoelectricBrownianSlowWeb | 0.02 | all | 0 | 0 | 0 | 0 | 0 | 0 | 0 |" results/where.md \
    || { cat results/where.md; fail "where counts row"; }
grep -q "^| isoelectricBrownianSlowWeb | 0.02 | none |" results/where.md || { cat results/where.md; fail "where row"; }
[ -s results/where.png ] || fail "no where.png"
# the fill starts every pair 100 nm apart: after two steps none within 50 nm
grep -q "^| isoelectricBrownianSlowWeb | 0.02 | none | 0 | 0 | 0 | 0 |" results/gaps.md \
    || { cat results/gaps.md; fail "gaps row"; }
[ -s results/gaps.png ] || fail "no gaps.png"
# the case beside its variant: no contact and no agglomerate in either
grep -q "^| isoelectricBrownianSlowWeb | SoftContacts | 0.02 | 0 / 0 | 0 | 0 / 0 | 0 | 0 |" results/variants.md \
    || { cat results/variants.md; fail "variants row"; }
grep -q "^| isoelectricBrownianSlowWebSoftContacts | ShortRange | 0.02 | 0 / 0 | 0 | 0 / 0 | 0 | 0 |" results/variants.md \
    || { cat results/variants.md; fail "short range's variants row"; }
grep -q "^| isoelectricBrownianSlowWebSoftContacts | TwoSphere | 0.02 | 0 / 0 | 0 | 0 / 0 | 0 | 0 |" results/variants.md \
    || { cat results/variants.md; fail "two-sphere variants row"; }
grep -q "^| isoelectricBrownianSlowWebSoftContactsTwoSphere | Explicit | 0.02 | 0 / 0 | 0 | 0 / 0 | 0 | 0 |" results/variants.md \
    || { cat results/variants.md; fail "explicit variants row"; }

# a resume continues the run and keeps the study log of its set-up
./Allstudy -resume -endTime 4e-8 isoelectricBrownianSlowWebSoftContacts > resume.out 2>&1 \
    || { cat resume.out; tail -20 $soft.log; fail "Allstudy -resume"; }
[ -f $soft/4e-08/uniform/colloidCoupling ] || fail "the resumed run did not reach 4e-08"
grep -q "^Steady flow converged" $soft.log || { cat $soft.log; fail "the set-up's log was lost by the resume"; }
grep -q "^==== .*Allstudy -resume, end time 4e-8 s" $soft.log || { cat $soft.log; fail "no line naming the resume"; }
grep -q "^Resuming the particle run from time 2e-08" $soft.log || { cat $soft.log; fail "the resume's log"; }
echo PASS
