#!/bin/bash
# Disk full: the slot-coater test run (fixture) from time 0 in a 7 MB tmpfs,
# which fills up at its third particle write (each write time holds about
# 2 MB, the DEM state most of it).  The run must stop with a non-zero exit
# and the file system's reason, leave no incomplete time folder (every
# time folder left holds its complete DEM state), and, once space is
# freed (the tmpfs grown to 64 MB), resume from the last complete write to
# the end time.  Then the disk is filled before a write (a ballast file):
# the run must stop naming the file that did not fit and leave nothing of
# that write time.
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

# 4. A disk already full when the time is written (a ballast file takes
#    the rest of the space): the first of the fluid fields or the
#    particles' files that does not fit stops the run, named, and nothing
#    of the time folder is left (OpenFOAM's files are written under
#    temporary names)
sed -i 's/^startFrom .*/startFrom       latestTime;/' system/controlDict
echo "endTime 1.6e-6;" > system/runOverrides
dd if=/dev/zero of=ballast bs=4k > /dev/null 2>&1 || true
set +e
colloidDEMFoam > "$work/log.ballast" 2>&1
rc=$?
set -e
rm -f ballast
message=$(grep -a -A3 "FOAM FATAL ERROR" "$work/log.ballast" | grep -a -m1 "Writing time" || true)
echo "full before the write: exit status $rc: $message"
[ $rc -ne 0 ] || fail "exit status 0 on a full disk"
echo "$message" | grep -E -q "Writing time 1.4e-06 failed: the (fluid fields|particles \(lagrangian/particles\)) could not be written: .*/1.4e-06/.*No space left on device" \
    || fail "no message naming the file of 1.4e-06 that could not be written and why"
[ ! -e 1.4e-06 ] || fail "the time folder 1.4e-06 was left: $(ls 1.4e-06)"
[ -z "$(find . -name '*.tmp')" ] || fail "temporary files left: $(find . -name '*.tmp')"

[ $status -eq 0 ] && echo PASS
exit $status
