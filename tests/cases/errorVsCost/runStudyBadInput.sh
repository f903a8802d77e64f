#!/bin/bash
# colloidErrorStudy on bad input: a made-up case (a parameter file and a
# study whose run and quantities are shell one-liners) with one fault per
# variant.  Requires a non-zero exit, a message naming the keyword and the
# allowed values, and no output written (missingQuantity: no rung marked
# done, so a rerun does not take the rung as finished).
#
# usage: runStudyBadInput.sh variant workDir
set -e
variant=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
tool="$here/../../../bin/colloidErrorStudy"
rm -rf "$work"
mkdir -p "$work/system"
cd "$work"
cat > system/parameters <<'DICT'
dt          1e-3;       // [s]
ratio       $dt;
DICT

values="(4e-3 2e-3 1e-3)"; limit=zero; entry=dt; expression=value
names="(q)"; expect=
case $variant in
    shortLadder)     values="(1e-3)"; expect="settings/dt/values.*at least two" ;;
    badLimit)        limit=sideways; expect="settings/dt/limit.*sideways.*zero.*infinity" ;;
    missingEntry)    entry=dT; expect="settings/dt/set: .*dT.* in system/parameters" ;;
    variableEntry)   entry=ratio; expect="settings/dt/set: entry 'ratio' is \\\$dt, a variable" ;;
    badExpression)   expression="value/0"; expect="settings/dt/set: expression \"value/0\".*division by zero" ;;
    missingQuantity) names="(q r)"; expect="printed no value for r" ;;
    *) echo "unknown variant $variant"; exit 2 ;;
esac
cat > system/errorStudyDict <<DICT
run         "true";
quantities  { command "echo q 1.5"; names $names; }
settings
{
    dt
    {
        values  $values;
        limit   $limit;
        set     ((system/parameters $entry "$expression"));
    }
}
DICT

set +e
/usr/bin/python3 "$tool" > log.errorStudy 2>&1
rc=$?
set -e
cat log.errorStudy
status=0
[ $rc -ne 0 ] || { echo "FAIL: exit status 0 for bad input ($variant)"; status=1; }
grep -E -q "$expect" log.errorStudy || { echo "FAIL: no message matching: $expect"; status=1; }
if [ "$variant" = missingQuantity ]
then
    [ -z "$(find errorStudy -name quantities.dat)" ] || { echo "FAIL: a rung marked done"; status=1; }
else
    [ ! -e errorStudy ] || { echo "FAIL: output written"; status=1; }
fi
[ $status -eq 0 ] && echo PASS
exit $status
