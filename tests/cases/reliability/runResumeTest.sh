#!/bin/bash
# Kill and resume: the slot-coater test run (tests/cases/slotCoater, a
# fixture that ran uninterrupted to 3 us) is run again from time 0 in a
# copy, killed with SIGKILL as soon as the write at KILLTIME is complete,
# and resumed from latestTime to the end.  At the end time the resumed run
# must hold the same particles as the uninterrupted one, at the same
# positions and velocities (compareClouds.py).
#
#   runResumeTest.sh serial|parallel fixtureDir workDir [killTime]
set -e
mode=$1
fixture=$2
work=$3
killTime=${4:-1.2e-06}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/copyFixture.sh"

# Back to the state before the particle run: only the time 0 (in the case
# and its processor folders, if any: an unmatched processor* is skipped)
removeLaterTimes()
{
    local dir
    for dir in "$@"
    do
        [ -d "$dir" ] || continue
        find "$dir" -mindepth 1 -maxdepth 1 -type d -regex '.*/[-+.0-9eE]+' \
            ! -name 0 -exec rm -rf {} +
    done
}
removeLaterTimes . processor*
rm -f log.colloidDEMFoam log.liggghts log.liggghts.screen log.reconstructPar

case "$mode" in
serial)
    run() { colloidDEMFoam > "$1" 2>&1; }
    start() { setsid colloidDEMFoam > "$1" 2>&1 & }
    markers=("$killTime/uniform/colloidCoupling") ;;
parallel)
    run() { mpirun -np 2 colloidDEMFoam -parallel > "$1" 2>&1; }
    start() { setsid mpirun -np 2 colloidDEMFoam -parallel > "$1" 2>&1 & }
    markers=("processor0/$killTime/uniform/colloidCoupling"
             "processor1/$killTime/uniform/colloidCoupling") ;;
*)  echo "usage: $0 serial|parallel fixtureDir workDir [killTime]" 1>&2; exit 1 ;;
esac

# 1. Run, and kill it (SIGKILL, every rank) right after the write at
#    killTime: the marker is the last file of a write.  The run starts its
#    own session (setsid); every process of that session is killed at once
#    (mpirun puts each rank in its own process group, but not in its own
#    session): no other solver on the machine (tests run side by side) is
#    touched.
start log.colloidDEMFoam.killed
pid=$!
complete=false
for _ in $(seq 1 6000)
do
    complete=true
    for m in "${markers[@]}"
    do
        [ -f "$m" ] || complete=false
    done
    $complete && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.01
done
pkill -9 -s "$pid" || true
wait "$pid" 2>/dev/null || true
$complete || { echo "FAIL: the write at $killTime did not complete"; tail -20 log.colloidDEMFoam.killed; exit 1; }
# The kill comes within a poll (10 ms) of the write; on a loaded machine the
# run may have gone on to start or finish a later write (a write every 0.2
# us of a few hundred DEM steps): cut those back, as if the kill had come
# right after the write at killTime
for dir in . processor*
do
    [ -d "$dir" ] || continue
    for t in $(find "$dir" -mindepth 1 -maxdepth 1 -type d -regex '.*/[-+.0-9eE]+' -printf '%f\n')
    do
        if awk -v t="$t" -v k="$killTime" 'BEGIN { exit !(t + 0 > k*(1 + 1e-9)) }'
        then
            echo "removed the later write $dir/$t (the run went on before the kill)"
            rm -rf "${dir:?}/$t"
        fi
    done
done
echo "killed after the write at $killTime s; last time in its log:" \
    "$(grep '^Time = ' log.colloidDEMFoam.killed | tail -1)"
latest=$(foamListTimes -latestTime -processor 2>/dev/null | tail -1)
[ "$mode" = serial ] && latest=$(foamListTimes -latestTime | tail -1)
echo "latest time folder: $latest"

# 2. Resume from the latest time
sed -i 's/^startFrom .*/startFrom       latestTime;/' system/controlDict
run log.colloidDEMFoam || { echo "FAIL: the resumed run failed"; tail -30 log.colloidDEMFoam; exit 1; }
grep -m1 "^Resuming from time $killTime:" log.colloidDEMFoam \
    || { echo "FAIL: the run did not resume from $killTime"; grep -m1 "^Resuming" log.colloidDEMFoam; exit 1; }
# The contact analysis' histories were written with the state (one file
# per rank) and read back: contacts open at the kill keep their start
for dir in "${markers[@]}"
do
    history="${dir%uniform/colloidCoupling}DEM/contactHistory"
    head -1 "$history" | grep -q "^colloidContactHistories 1 " \
        || { echo "FAIL: no contact histories in $history"; exit 1; }
done
grep -m1 "^Contact analysis: contact histories of time $killTime s read back" log.colloidDEMFoam \
    || { echo "FAIL: the resumed run did not read the contact histories back"; exit 1; }

# 3. The same particles at the end as the uninterrupted run (parallel:
#    both reconstructed, as the fixture was)
endTime=$(foamListTimes -latestTime -case "$fixture" | tail -1)
if [ "$mode" = parallel ]
then
    reconstructPar -time "$endTime" > log.reconstructPar 2>&1 \
        || { echo "FAIL: reconstructPar"; tail -20 log.reconstructPar; exit 1; }
fi
python3 "$here/compareClouds.py" "$fixture/$endTime" "$work/$endTime"
