#!/bin/bash
# The grid of DEM subdomains chosen to fit the fluid's decomposition.  The
# closed periodic box of the momentum test (a 1 mm cube, 200 spheres
# settling).  LIGGGHTS gives a cube the first of its grids with the least
# surface: 1 1 2 on 2 ranks, 1 2 2 on 4.  The fluid is cut where LIGGGHTS
# would not: in x on 2 ranks (method simple, n (2 1 1)); in x and y on 4
# (simple, n (2 2 1), its parts renumbered p -> (p + 1) mod 4 through
# method manual, so that the subdomains' ranks in the grid asked, i + Px j
# with 'map xyz', are not the fluid's own numbers: a wrong map or a lost
# rank order puts half of the fluid on other ranks).  In LIGGGHTS' own grid
# half of the fluid volume is on another rank than its DEM subdomain,
# whatever the ranks' order; the coupling must open LIGGGHTS again with a
# grid of 2 1 1 (2 2 1).
#
#   runDemGridTest.sh workDir [nProcs]     nProcs 2 (default) or 4
#
# Asserted:
#   - the log shows LIGGGHTS' own grid 1 1 2 (1 2 2) (else the case no
#     longer tests the choice), the grid 2 1 1 (2 2 1) chosen and made, at
#     least 95 % of the
#     fluid volume on the rank of its DEM subdomain, and at most 5 % of the
#     particles' records going to another rank (particles near the cut
#     move between the DEM's and the fluid's exchange);
#   - the run's momentum balance (checkMomentum.py, as the serial test);
#   - the run resumed from its write at 2 ms asks for the same grid (the
#     written DEM state holds it; LIGGGHTS' own grid would read the
#     particles as well, but half of their records would then go to
#     another rank: at most 5 % do) and ends at 4 ms with the particles of the
#     uninterrupted run (compareClouds.py: positions within 1e-3 d,
#     velocities within 1e-9 of the largest speed: the fluid resumes from
#     its fields written with 15 digits).
set -e
work=$1
nProcs=${2:-2}
here=$(cd "$(dirname "$0")" && pwd)
case $nProcs in
    2) own="1 1 2"; grid="2 1 1" ;;
    4) own="1 2 2"; grid="2 2 1" ;;
    *) echo "nProcs 2 or 4"; exit 2 ;;
esac
source "$here/caseFunctions.sh"
rm -rf "$work"
copyCase "$here/periodicBox" "$work/full"
python3 "$COLLOIDFOAM_TUTORIALS/twoWay/makeSuspension.py" constant/DEM/suspension.data 200 50 1000 1000 1000 12345 periodic
setModel A
setKernel "${COLLOIDFOAM_KERNEL:-}"
checkTranspose
foamDictionary system/decomposeParDict -entry numberOfSubdomains -set "$nProcs" > /dev/null
foamDictionary system/decomposeParDict -entry method -set simple > /dev/null
foamDictionary system/decomposeParDict -entry simpleCoeffs \
    -set "{ n ($grid); delta 0.001; }" > /dev/null
blockMesh > log.blockMesh 2>&1
if [ "$nProcs" = 4 ]
then
    decomposePar -cellDist -force > log.decomposePar.simple 2>&1
    python3 - <<'PY'
s = open('constant/cellDecomposition').read()
i = s.index('(', s.index('\n', s.index('}')))
j = s.rindex(')')
parts = [str((int(c) + 1) % 4) for c in s[i + 1:j].split()]
open('constant/cellDecompositionRenumbered', 'w').write(
    s[:i + 1] + '\n' + '\n'.join(parts) + '\n' + s[j:])
PY
    foamDictionary system/decomposeParDict -entry method -set manual > /dev/null
    foamDictionary system/decomposeParDict -entry manualCoeffs \
        -set '{ dataFile "cellDecompositionRenumbered"; }' > /dev/null
    rm -f 0/cellDist
fi
decomposePar -force > log.decomposePar 2>&1
mpirun -np "$nProcs" colloidDEMFoam -parallel > log.colloidDEMFoam 2>&1 \
    || { echo "FAIL: the run failed"; tail -30 log.colloidDEMFoam; exit 1; }

python3 - log.colloidDEMFoam "$own" "$grid" <<'PY'
import re, sys
log = open(sys.argv[1]).read()
own_grid, grid = tuple(sys.argv[2].split()), tuple(sys.argv[3].split())
own = re.search(r"DEM subdomains and fluid parts: (\S+) % .* in LIGGGHTS' order \(grid (\d) (\d) (\d)\)", log)
chosen = re.search(r"DEM subdomains: a grid of \((\d) (\d) (\d)\) equal subdomains puts (\S+) %", log)
made = re.search(r"DEM subdomains: grid (\d) (\d) (\d), (\S+) % of the fluid volume", log)
records = [float(x) for x in re.findall(r'Records: (\S+) % of the particles', log)]
if not own or own.group(2, 3, 4) != own_grid:
    sys.exit('FAIL (precondition): LIGGGHTS\' own grid is not %s: %s'
             % (' '.join(own_grid), own.group(0) if own else 'no line'))
if not chosen or chosen.group(1, 2, 3) != grid:
    sys.exit('FAIL: the grid %s was not chosen' % ' '.join(grid))
if not made or made.group(1, 2, 3) != grid:
    sys.exit('FAIL: LIGGGHTS did not make the grid %s' % ' '.join(grid))
if 'Opening LIGGGHTS again with these subdomains' not in log:
    sys.exit('FAIL: LIGGGHTS was not opened again')
share = float(made.group(4))
print('LIGGGHTS\' own grid %s: %s %% of the fluid on its subdomain\'s rank;'
      ' grid %s: %.2f %%; records to another rank: %.2f %%'
      % (' '.join(own_grid), own.group(1), ' '.join(grid), share,
         records[-1] if records else -1))
if share < 95:
    sys.exit('FAIL: %.2f %% of the fluid volume on its subdomain\'s rank: less than 95 %%' % share)
if not records or records[-1] > 5:
    sys.exit('FAIL: more than 5 %% of the particles\' records go to another rank')
PY
reconstructPar > log.reconstructPar 2>&1
python3 "$here/checkMomentum.py" "$work/full"

# Resumed from the write at 2 ms: the same particles at 4 ms
cp -r "$work/full" "$work/resumed"
cd "$work/resumed"
for dir in . processor*
do
    find "$dir" -mindepth 1 -maxdepth 1 -type d -regex '.*/[-+.0-9eE]+' \
        ! -name 0 ! -name 0.002 -exec rm -rf {} +
done
grep -q "demGrid" processor0/0.002/uniform/colloidCoupling \
    || { echo "FAIL: the write at 2 ms does not hold the DEM grid"; exit 1; }
sed -i 's/^startFrom .*/startFrom       latestTime;/' system/controlDict
mpirun -np "$nProcs" colloidDEMFoam -parallel > log.colloidDEMFoam 2>&1 \
    || { echo "FAIL: the resumed run failed"; tail -20 log.colloidDEMFoam; exit 1; }
grep -m1 "^Resuming from time 0.002:" log.colloidDEMFoam \
    || { echo "FAIL: the run did not resume from 0.002"; exit 1; }
grep -m1 "^DEM subdomains: a grid of ($grid), as the written run asked" log.colloidDEMFoam \
    || { echo "FAIL: the resumed run did not ask for the grid $grid"; exit 1; }
away=$(grep "^Records:" log.colloidDEMFoam | tail -1 | awk '{print $2}')
echo "resumed run: records to another rank: $away %"
python3 -c "import sys; sys.exit(0 if float('$away') <= 5 else 1)" \
    || { echo "FAIL: more than 5 % of the resumed run's records go to another rank"; exit 1; }
reconstructPar -time 0.004 > log.reconstructPar 2>&1
python3 "$here/../reliability/compareClouds.py" "$work/full/0.004" "$work/resumed/0.004" 1e-9
