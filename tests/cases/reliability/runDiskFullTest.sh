#!/bin/bash
# Disk full: the slot-coater test run (fixture) from time 0 in a 7 MB tmpfs,
# which fills up at its third particle write (each write time holds about
# 2 MB, the DEM state most of it).  The run must stop with a non-zero exit
# and the file system's reason, leave no incomplete time folder (every
# time folder left holds its complete DEM state), and, once space is
# freed (the tmpfs grown to 64 MB), resume from the last complete write to
# the end time.
#
# Needs root (mount); without it, or where tmpfs cannot be mounted, exits
# 77 (skipped) saying why.
#
#   runDiskFullTest.sh fixtureDir workDir
set -e
fixture=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/testEnvironment.sh"

if [ "$(id -u)" -ne 0 ]
then
    echo "SKIPPED: mounting a small tmpfs needs root (this test runs as $(id -un))"
    exit 77
fi
[ -d "$fixture" ] || { echo "no fixture run $fixture" 1>&2; exit 1; }
umount "$work/mnt" 2>/dev/null || true
rm -rf "$work"
mkdir -p "$work/mnt"
if ! mount -t tmpfs -o size=7m tmpfs "$work/mnt" 2> "$work/mount.err"
then
    echo "SKIPPED: cannot mount a tmpfs: $(cat "$work/mount.err")"
    exit 77
fi
# (an MPI helper of the last run may still hold the folder for a moment:
# a lazy unmount then detaches it at once and frees it when released)
trap 'cd /; umount "$work/mnt" 2>/dev/null || umount -l "$work/mnt"' EXIT

# The prepared case (mesh, flow, DEM surfaces and fill), no particle run
case=$work/mnt/case
mkdir -p "$case/DEM"
cp -r "$fixture"/system "$fixture"/constant "$fixture"/0 "$case"/
cp -r "$fixture"/DEM/meshes "$fixture"/DEM/fill.data \
    "$fixture"/DEM/slotCoater.liggghts "$case"/DEM/
echo "endTime 1.2e-6;" > "$case"/system/runOverrides
cd "$case"
echo "case: $(du -sh . | cut -f1) in a tmpfs of $(df -h . | awk 'NR == 2 { print $2 }')"

status=0
fail() { echo "FAIL: $*"; status=1; }

# 1. The run fills the disk
set +e
colloidDEMFoam > "$work/log.full" 2>&1
rc=$?
set -e
[ $rc -ne 0 ] || fail "exit status 0 on a full disk"
message=$(grep -a -A3 "FOAM FATAL ERROR" "$work/log.full" | grep -a -m1 "Writing time" || true)
echo "exit status $rc: $message"
echo "$message" | grep -q "No space left on device" \
    || fail "no 'Writing time ... failed' message with the file system's reason"

# 2. No incomplete time folder: each one left (but 0) has its DEM state
complete=
for t in $(ls -d [0-9]* | grep -E '^[-+.0-9eE]+$' | grep -v '^0$' | sort -g)
do
    if [ -f "$t/uniform/colloidCoupling" ] && [ -f "$t/DEM/restart.base" ] \
        && [ -f "$t/lagrangian/particles/positions" ] && [ -f "$t/U" ]
    then
        complete=$t
    else
        fail "time folder $t is incomplete: $(ls "$t" | tr '\n' ' ')"
    fi
done
[ -n "$complete" ] || fail "no complete write time left"
[ -z "$(ls -d DEM.tmp */DEM.tmp 2>/dev/null)" ] || fail "DEM.tmp left behind"
echo "complete write times left, the latest: $complete"

# 3. Space freed: resumed from the last complete write to the end
mount -o remount,size=64m "$work/mnt"
sed -i 's/^startFrom .*/startFrom       latestTime;/' system/controlDict
colloidDEMFoam > "$work/log.resumed" 2>&1 || fail "the resumed run failed: $(tail -5 "$work/log.resumed")"
grep -q "^Resuming from time $complete:" "$work/log.resumed" \
    || fail "not resumed from $complete: $(grep -m1 '^Resuming' "$work/log.resumed")"
[ -f 1.2e-06/uniform/colloidCoupling ] || fail "the end time 1.2e-06 was not written"
echo "resumed from $complete, end time 1.2e-06 written"

[ $status -eq 0 ] && echo PASS
exit $status
