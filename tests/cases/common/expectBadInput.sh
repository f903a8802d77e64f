# Sourced by the bad-input tests: run colloidDEMFoam in the current case
# and require a non-zero exit, a message matching $expect in its log, and
# no file written but logs (unless filesAllowed=yes: a fault found at a
# write time).  Exits with the verdict.
#
# usage (after setting variant and expect): source expectBadInput.sh

before=$(ls | grep -v '^log\.')
set +e
colloidDEMFoam > log.colloidDEMFoam 2>&1
rc=$?
set -e

status=0
if [ $rc -eq 0 ]
then
    echo "FAIL: exit status 0 for bad input ($variant)"; status=1
fi
if ! grep -E -q "$expect" log.colloidDEMFoam
then
    echo "FAIL: no message matching: $expect"; status=1
    grep -A4 "FATAL" log.colloidDEMFoam || true
fi
if [ "${filesAllowed:-no}" != yes ] && [ "$(ls | grep -v '^log\.')" != "$before" ]
then
    echo "FAIL: files written: $(ls)"; status=1
fi
grep -E -m1 "$expect" log.colloidDEMFoam || true
echo "exit status $rc"
[ $status -eq 0 ] && echo PASS
exit $status
