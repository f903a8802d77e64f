#!/bin/bash
# colloidErrorStudy on bad input: a made-up case (a parameter file and a
# study whose run and quantities are shell one-liners) with one fault per
# variant.  Requires a non-zero exit, a message naming the keyword and the
# allowed values, and no output written (missingQuantity: no rung marked
# done, so a rerun does not take the rung as finished; changedContext: a
# study done, the context entry changed, then the study again without
# -rerun: its done rungs are refused and its measuredErrors left as it
# was).
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
form        faded;
DICT

values="(4e-3 2e-3 1e-3)"; limit=zero; entry=dt; expression=value
names="(q)"; context="()"; expect=
case $variant in
    shortLadder)     values="(1e-3)"; expect="settings/dt/values.*at least two" ;;
    badLimit)        limit=sideways; expect="settings/dt/limit.*sideways.*zero.*infinity" ;;
    missingEntry)    entry=dT; expect="settings/dt/set: .*dT.* in system/parameters" ;;
    variableEntry)   entry=ratio; expect="settings/dt/set: entry 'ratio' is \\\$dt, a variable" ;;
    badExpression)   expression="value/0"; expect="settings/dt/set: expression \"value/0\".*division by zero" ;;
    missingQuantity) names="(q r)"; expect="printed no value for r" ;;
    badContext)      context="(dt)"; expect="keyword 'context'.*\(file entry\) pairs" ;;
    missingContext)  context="((system/parameters shape))"; expect="context: no entry 'shape' in system/parameters" ;;
    changedContext)  context="((system/parameters form))"; expect="context: .* ran with system/parameters form = faded, the case has shifted: run the study with -rerun" ;;
    variableContext) context="((system/parameters ratio))"; expect="keyword 'context'.*ratio is \\\$dt: name the entry that holds it" ;;
    *) echo "unknown variant $variant"; exit 2 ;;
esac
cat > system/errorStudyDict <<DICT
run         "true";
quantities  { command "echo q 1.5"; names $names; }
context     $context;
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

if [ "$variant" = changedContext ]
then
    /usr/bin/python3 "$tool" > log.firstStudy 2>&1 || { cat log.firstStudy; echo "FAIL: the first study"; exit 1; }
    cp errorStudy/measuredErrors measuredErrors.first
    sed -i "s/^form .*/form        shifted;/" system/parameters
fi
set +e
/usr/bin/python3 "$tool" > log.errorStudy 2>&1
rc=$?
set -e
cat log.errorStudy
status=0
[ $rc -ne 0 ] || { echo "FAIL: exit status 0 for bad input ($variant)"; status=1; }
grep -E -q "$expect" log.errorStudy || { echo "FAIL: no message matching: $expect"; status=1; }
if [ "$variant" = changedContext ]
then
    cmp -s measuredErrors.first errorStudy/measuredErrors || { echo "FAIL: measuredErrors changed"; status=1; }
elif [ "$variant" = missingQuantity ]
then
    [ -z "$(find errorStudy -name quantities.dat)" ] || { echo "FAIL: a rung marked done"; status=1; }
else
    [ ! -e errorStudy ] || { echo "FAIL: output written"; status=1; }
fi
[ $status -eq 0 ] && echo PASS
exit $status
