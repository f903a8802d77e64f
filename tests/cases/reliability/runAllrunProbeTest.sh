#!/bin/bash
# The slot-coater tutorial's Allrun (at test size, tests/cases/slotCoater/
# testSizeCase.sh) tried with the faults and mistakes a user makes: each
# probe must end with the exit status, the message and the files it
# promises, never an exit 0 that did not run.
#
#   runAllrunProbeTest.sh probe workDir
#
# probes:
#   nuZero            nu 0 in system/slotCoaterParameters: stops before any
#                     step, naming the file, keyword, value and range
#   cutoffFormTypo    colloidCutoffForm fade (a typo of faded): stops
#                     before any step, naming the file, keyword, value and
#                     the two forms allowed
#   lubricationFormTypo  lubricationForm twoSpheres (for twoSphere): stops
#                     likewise, naming the two forms allowed
#   explicitRatioTooLarge  lubricationExplicitRatio 0.3: stops likewise,
#                     naming the closed range 0 to 0.25
#   notConverged      20 iterations of the steady flow (endTime of
#                     system/controlDict.steadyFlow): it does not converge;
#                     stops saying so, no particle run
#   fillTooDense      solidsFraction 0.5: the fill reaches less; stops
#                     with the reached fraction, no fill.data, no run
#   rerunAfterFailure a misspelt DEM command: stops with LIGGGHTS' error;
#                     after the fix, ./Allrun runs the particles again
#   shortEndTimeParallel  -parallel -endTime 2.5e-7 (not a write time):
#                     exit 0, the end time written and reconstructed
#   demStepTooLong    DEM { timeStep } above the plugin's contact limit:
#                     the stop advises the setting that applies (seconds)
#   resumeAfterKill   ./Allrun killed (SIGKILL, its whole session) after
#                     the write at 2e-7; ./Allrun -resume continues from
#                     2e-7 to the end time 6e-7, keeping the killed run's
#                     log beside that of an earlier part resumed from the
#                     same write; -resume with nothing to resume from
#                     stops saying so
set -u
probe=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/testEnvironment.sh"

# The test-size copy of the tutorial in work (cd there)
( here="$here/../slotCoater"; source "$here/testSizeCase.sh" ) || exit 1
cd "$work"

# The terminal output of ./Allrun, outside the case (Allrun cleans log.*)
out="$work.Allrun.out"

status=0
fail() { echo "FAIL: $*"; status=1; }

# expectFailure 'message regex' [Allrun args]: non-zero exit, message on
# the terminal
expectFailure()
{
    local expect=$1
    shift
    ./Allrun "$@" > "$out" 2>&1
    local rc=$?
    [ $rc -ne 0 ] || fail "./Allrun $* exited 0"
    grep -E -q "$expect" "$out" || fail "no message matching: $expect"
    echo "./Allrun $*: exit $rc; $(grep -E -m1 "$expect" "$out")"
}

# noParticleRun: nothing of a particle run was made
noParticleRun()
{
    [ ! -e log.colloidDEMFoam ] || fail "colloidDEMFoam was run"
    local t
    t=$(ls -d [0-9]* 2>/dev/null | grep -E '^[-+.0-9eE]+$' | grep -v '^0$' || true)
    [ -z "$t" ] || fail "time folders written: $t"
}

setParam()
{
    sed -i "s/^$1 .*/$1 $2;/" system/slotCoaterParameters
}

case "$probe" in
nuZero)
    setParam nu 0
    expectFailure "system/slotCoaterParameters: keyword 'nu' is 0; allowed range: 0 < nu"
    [ ! -e log.blockMesh ] || fail "blockMesh was run"
    noParticleRun ;;

cutoffFormTypo)
    setParam colloidCutoffForm fade
    expectFailure "system/slotCoaterParameters: keyword 'colloidCutoffForm' is 'fade'; allowed: faded or shifted"
    [ ! -e log.blockMesh ] || fail "blockMesh was run"
    noParticleRun ;;

lubricationFormTypo)
    setParam lubricationForm twoSpheres
    expectFailure "system/slotCoaterParameters: keyword 'lubricationForm' is 'twoSpheres'; allowed: nearField or twoSphere"
    [ ! -e log.blockMesh ] || fail "blockMesh was run"
    noParticleRun ;;

explicitRatioTooLarge)
    setParam lubricationExplicitRatio 0.3
    expectFailure "system/slotCoaterParameters: keyword 'lubricationExplicitRatio' is 0.3; allowed range: 0 <= lubricationExplicitRatio <= 0.25"
    [ ! -e log.blockMesh ] || fail "blockMesh was run"
    noParticleRun ;;

notConverged)
    # 20 iterations: too few for the residual control (the flow converges
    # in about 400)
    sed -i "s/^endTime .*/endTime         20;/" system/controlDict.steadyFlow
    grep -q "^endTime         20;" system/controlDict.steadyFlow || exit 1
    expectFailure "The steady flow did not converge within 20 iterations"
    noParticleRun ;;

fillTooDense)
    setParam solidsFraction 0.5
    expectFailure "The initial fill holds [0-9]+ particles of the [0-9]+ that solidsFraction 0.5"
    [ ! -e DEM/fill.data ] || fail "DEM/fill.data left behind"
    noParticleRun ;;

rerunAfterFailure)
    sed -i 's/^pair_coeff /pair_coef /' constant/DEM/in.liggghts
    expectFailure "ERROR: Unknown command: pair_coef" -endTime 4e-7
    sed -i 's/^pair_coef /pair_coeff /' constant/DEM/in.liggghts
    ./Allrun -endTime 4e-7 > "$out" 2>&1 || fail "the re-run failed"
    grep -q "^End" log.colloidDEMFoam || fail "the re-run did not run colloidDEMFoam"
    [ -f 4e-07/lagrangian/particles/positions ] || fail "no particles at 4e-07"
    echo "re-run after the fix: exit 0, $(grep '^Particles:' log.colloidDEMFoam | tail -1)" ;;

shortEndTimeParallel)
    ./Allrun -parallel -endTime 2.5e-7 > "$out" 2>&1 || fail "exit status $?"
    [ -f 2.5e-07/lagrangian/particles/positions ] \
        || fail "end time 2.5e-07 not written/reconstructed"
    [ -f 2.5e-07/U ] || fail "no fluid at 2.5e-07"
    echo "-parallel -endTime 2.5e-7: exit 0, last times $(ls -d [0-9]* | grep -E '^[-+.0-9eE]+$' | sort -g | tail -2 | tr '\n' ' ')" ;;

resumeAfterKill)
    expectFailure "no write time with a complete DEM state" -resume
    setsid ./Allrun -endTime 6e-7 > "$out.killed" 2>&1 &
    pid=$!
    for _ in $(seq 1 6000)
    do
        [ -f 2e-07/uniform/colloidCoupling ] && break
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.01
    done
    pkill -9 -s "$pid" || true
    wait "$pid" 2>/dev/null
    [ -f 2e-07/uniform/colloidCoupling ] || fail "the write at 2e-07 did not complete"
    [ ! -e 6e-07 ] || fail "the run was not killed before its end"
    # as if resumed from 2e-07 once before: that part's log stays, the
    # killed run's is kept beside it
    echo "an earlier part" > log.colloidDEMFoam.to2e-07
    ./Allrun -resume > "$out" 2>&1 || fail "./Allrun -resume: exit $?"
    grep -q "^Resuming from time 2e-07:" log.colloidDEMFoam \
        || fail "not resumed from 2e-07: $(grep -m1 '^Resuming' log.colloidDEMFoam)"
    [ "$(cat log.colloidDEMFoam.to2e-07)" = "an earlier part" ] \
        || fail "the log of an earlier part (log.colloidDEMFoam.to2e-07) was overwritten"
    grep -q "^Time = 2e-07" log.colloidDEMFoam.to2e-07.2 \
        || fail "the killed run's log was not kept as log.colloidDEMFoam.to2e-07.2"
    [ -f 6e-07/lagrangian/particles/positions ] || fail "end time 6e-07 not written"
    later=$(ls -d [0-9]* | grep -E '^[-+.0-9eE]+$' | awk '$1 > 6.000001e-07')
    [ -z "$later" ] || fail "ran past the end time 6e-07 of the run resumed: $later"
    echo "killed after 2e-07, ./Allrun -resume: $(grep -m1 '^Resuming' log.colloidDEMFoam)" ;;

demStepTooLong)
    # 1e-9 s passes the coupling's own check (the Stokes time, 1.25e-8 s)
    # but not the plugin's contact limit: its stop names the setting that
    # applies, in seconds, at 0.05 x the contact duration it prints (100
    # DEM steps a coupling step of 1e-7 s, whatever the tutorial's)
    sed -i -e 's/^\( *timeStep *\)[^;]*;/\11e-9;/' \
        -e 's/^\( *couplingInterval *\)[^;]*;/\1100;/' constant/couplingProperties
    sed -i 's/^deltaT .*/deltaT          1e-7;/' system/controlDict
    expectFailure "set DEM \{ timeStep [0-9.e+-]+; \} \(seconds\) or less in constant/couplingProperties" -endTime 4e-7
    line=$(grep -a -m1 "set DEM { timeStep" "$out")
    awk -v l="$line" 'BEGIN {
        if (!match(l, /contact duration[^(]*\(([0-9.e+-]+) s\)/)) exit 1
        split(substr(l, RSTART, RLENGTH), a, "(")
        duration = a[2] + 0
        if (!match(l, /timeStep [0-9.e+-]+;/)) exit 1
        advised = substr(l, RSTART + 9, RLENGTH - 10) + 0
        exit !(advised > 0 && (advised - 0.05*duration)^2 < (1e-5*advised)^2) }' \
        || fail "the advised timeStep is not 0.05 x the contact duration: $line" ;;

*)  echo "unknown probe $probe"; exit 2 ;;
esac

[ $status -eq 0 ] && echo PASS || { echo "--- $out:"; tail -20 "$out"; }
exit $status
