#!/bin/bash
# colloidErrorStudy with a rung that runs but gives no answer: a made-up
# case (a parameter file, a run that does nothing, a quantity q = 1.5 + dt
# printed by awk) whose quantity is "nan" at the coarsest rung (as the
# filtration's coordination number at a coupling step outside the usable
# range).  Required: exit 0; in errorStudy.csv that rung failed and the
# three others ok; errorStudy.md names the rung as failed with "no finite
# value: q nan"; the other rungs' q as printed and the observed order of
# convergence within 0.2 of 1 (q is linear in dt).
#
# usage: runStudyNotFinite.sh workDir
set -e
work=$1
here=$(cd "$(dirname "$0")" && pwd)
tool="$here/../../../bin/colloidErrorStudy"
rm -rf "$work"
mkdir -p "$work/system"
cd "$work"
cat > system/parameters <<'DICT'
dt          1e-3;       // [s]
DICT
cat > quantities.sh <<'SH'
awk '$1 == "dt" { v = $2 + 0; if (v > 3e-3) print "q nan"; else printf "q %.15g\n", 1.5 + v }' system/parameters
SH
cat > system/errorStudyDict <<'DICT'
run         "true";
quantities
{
    command "bash quantities.sh";
    names   (q);
}
settings
{
    dt
    {
        values  (4e-3 2e-3 1e-3 5e-4);
        limit   zero;
        order   1;
        set     ((system/parameters dt "value"));
    }
}
DICT

status=0
/usr/bin/python3 "$tool" > log.errorStudy 2>&1 || { echo "FAIL: exit status non-zero"; status=1; }
cat log.errorStudy
/usr/bin/python3 - <<'PY' || status=1
import csv, sys
rows = list(csv.DictReader(open('errorStudy/errorStudy.csv')))
ok = True
for r in rows:
    v = float(r['value'])
    want = 'failed' if v > 3e-3 else 'ok'
    print('dt %g: %s, q %s' % (v, r['status'], r['q']))
    ok &= r['status'] == want
    if want == 'ok':
        ok &= abs(float(r['q']) - (1.5 + v)) < 1e-12
ok &= sorted(float(r['value']) for r in rows) == [5e-4, 1e-3, 2e-3, 4e-3]
orders = list(csv.DictReader(open('errorStudy/errorStudyOrders.csv')))
order = float(orders[0]['observedOrder'])
print('observed order %g' % order)
ok &= abs(order - 1) <= 0.2
md = open('errorStudy/errorStudy.md').read()
ok &= 'failed' in md and 'no finite value: q nan' in md
print('PASS' if ok else 'FAIL')
sys.exit(0 if ok else 1)
PY
exit $status
