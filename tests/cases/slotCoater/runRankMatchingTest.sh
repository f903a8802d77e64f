#!/bin/bash
# DEM subdomains put on the ranks that hold their fluid cells (2 ranks).
# The slot-coater test run (the fixture of runSlotCoaterRun.sh parallel)
# again from time 0, the fluid decomposed as METIS did it but with its two
# parts swapped (method manual): in LIGGGHTS' own order each DEM subdomain
# is then on the rank that holds the fewest of its cells, and the coupling
# must open LIGGGHTS with its ranks in the other order.
#
#   runRankMatchingTest.sh fixtureDir workDir
#
# Asserted:
#   - the log reports the reorder and opens LIGGGHTS again; the DEM
#     script's own grid (processors * * 1) is kept: no other grid is tried;
#   - the share of particles whose records go to another rank (the log's
#     Records line) is at most 53 %: of the two ways to pair two DEM
#     subdomains with two fluid parts, one puts at least half of the fluid
#     volume on its subdomain's rank (+3 points: the particles' density is
#     not uniform over the fluid); and it is within 3 points of 100 % less
#     the matched volume share the log gives;
#   - the contact analysis, gathered on the solver's master although that
#     is no longer LIGGGHTS' rank 0, counts every particle present, in all
#     and by their numbers of contacts (last row of contacts.csv: particles
#     and with0 + with1 + with2 + with3orMore = the log's present count);
#   - the run resumed from its write at 0.6 us (each rank's DEM restart
#     file is that of its rank in LIGGGHTS, now not its own rank) ends at
#     1.2 us with the particles of the uninterrupted run (compareClouds.py).
set -e
fixture=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
reliability="$here/../reliability"
set +u
source "$here/../../../etc/bashrc" || exit 1

[ -d "$fixture" ] || { echo "no fixture run $fixture" 1>&2; exit 1; }
rm -rf "$work"
mkdir -p "$work"
cp -r "$fixture"/. "$work/full"
cd "$work/full"

# Back to time 0, the fill's state (no particles of a run at time 0)
rm -rf processor* 0/lagrangian 0/uniform 0/DEM postProcessing log.colloidDEMFoam
foamListTimes -rm > /dev/null
echo "endTime 1.2e-6;" > system/runOverrides

# METIS' decomposition, its two parts swapped
decomposePar -cellDist -force > log.decomposePar.metis 2>&1
python3 - <<'PY'
import re
s = open('constant/cellDecomposition').read()
i = s.index('(', s.index('\n', s.index('}')))
j = s.rindex(')')
cells = s[i + 1:j].split()
assert set(cells) <= {'0', '1'}, 'expected 2 parts'
swapped = ['1' if c == '0' else '0' for c in cells]
open('constant/cellDecompositionSwapped', 'w').write(
    s[:i + 1] + '\n' + '\n'.join(swapped) + '\n' + s[j:])
PY
foamDictionary system/decomposeParDict -entry method -set manual > /dev/null
foamDictionary system/decomposeParDict -entry manualCoeffs -set '{ dataFile "cellDecompositionSwapped"; }' > /dev/null
decomposePar -force > log.decomposePar 2>&1
rm -f 0/cellDist

mpirun -np 2 colloidDEMFoam -parallel > log.colloidDEMFoam 2>&1 \
    || { echo "FAIL: the run failed"; tail -20 log.colloidDEMFoam; exit 1; }

python3 - log.colloidDEMFoam postProcessing/contactAnalysis/0/contacts.csv <<'PY'
import re, sys
log = open(sys.argv[1]).read()
m = re.search(r"DEM subdomains and fluid parts: (\S+) % of the fluid volume in the DEM box is on"
              r" the rank of its DEM subdomain in LIGGGHTS' order \(grid \d+ \d+ \d+\),"
              r" (\S+) % with each subdomain", log)
if not m or 'Opening LIGGGHTS again with these subdomains' not in log:
    sys.exit('FAIL: no reorder of the DEM ranks in the log')
own, matched = float(m.group(1)), float(m.group(2))
if not re.search(r"DEM subdomains: the DEM script .* asks for a grid of 0 0 1 \(0: any\): kept", log) \
        or 'DEM subdomains: a grid of' in log:
    sys.exit('FAIL: the DEM script\'s processors grid (* * 1) was not kept')
records = [float(x) for x in re.findall(r'Records: (\S+) % of the particles', log)]
if not records:
    sys.exit('FAIL: no Records line')
away = records[-1]
print('fluid volume on its subdomain\'s rank: %.2f %% in LIGGGHTS\' order, %.2f %% matched;'
      ' particles on another rank: %.2f %%' % (own, matched, away))
if not away <= 53:
    sys.exit('FAIL: %.2f %% of the particles on another rank: more than 53 %%' % away)
if abs(away - (100 - matched)) > 3:
    sys.exit('FAIL: %.2f %% of the particles on another rank, %.2f %% of the volume: more than'
             ' 3 points apart' % (away, 100 - matched))
present = int(re.findall(r'Particles: present (\d+)', log)[-1])
lines = open(sys.argv[2]).read().splitlines()
header = [l for l in lines if l.startswith('time,')][0].split(',')
rows = [dict(zip(header, l.split(','))) for l in lines if l[:1].isdigit()]
counted = int(rows[-1]['particles'])
byContacts = sum(int(rows[-1][k]) for k in ('with0', 'with1', 'with2', 'with3orMore'))
print('contact analysis: %d particles, %d by their contacts; present: %d'
      % (counted, byContacts, present))
if counted != present:
    sys.exit('FAIL: the contact analysis counted %d particles, %d present' % (counted, present))
if byContacts != present:
    sys.exit('FAIL: the contact analysis counted %d particles by their contacts, %d present'
             % (byContacts, present))
PY

# Resumed from the write at 0.6 us: the same particles at 1.2 us
cp -r "$work/full" "$work/resumed"
cd "$work/resumed"
for dir in processor*
do
    find "$dir" -mindepth 1 -maxdepth 1 -type d -regex '.*/[-+.0-9eE]+' \
        ! -name 0 ! -name 6e-07 -exec rm -rf {} +
done
[ -f processor0/6e-07/DEM/restart.1 ] && [ -f processor1/6e-07/DEM/restart.0 ] \
    || { echo "FAIL: the write at 0.6 us does not hold the DEM files of the swapped ranks"; ls processor*/6e-07/DEM; exit 1; }
sed -i 's/^startFrom .*/startFrom       latestTime;/' system/controlDict
mpirun -np 2 colloidDEMFoam -parallel > log.colloidDEMFoam 2>&1 \
    || { echo "FAIL: the resumed run failed"; tail -20 log.colloidDEMFoam; exit 1; }
grep -m1 "^Resuming from time 6e-07:" log.colloidDEMFoam \
    || { echo "FAIL: the run did not resume from 6e-07"; exit 1; }
for dir in "$work/full" "$work/resumed"
do
    (cd "$dir" && reconstructPar -time 1.2e-06 > log.reconstructPar 2>&1) \
        || { echo "FAIL: reconstructPar in $dir"; exit 1; }
done
python3 "$reliability/compareClouds.py" "$work/full/1.2e-06" "$work/resumed/1.2e-06"
