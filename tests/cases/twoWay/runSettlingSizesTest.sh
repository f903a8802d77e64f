#!/bin/bash
# Spheres of two sizes settling side by side in one two-way run
# (particles/diameterRange): d = 100 um and 50 um, 20 mm (200 large
# diameters) apart across the centre of the closed box (x = 22.31 and
# 42.31 mm, -9.69 and +10.31 mm from the centre; walls 21.7 mm from the
# nearer), in a centre block of 24^3 cells of 10 large diameters; each at
# its own terminal velocity (checkSettlingVelocity.py, the spheres' sizes
# checked).  Bad settings stop the solver at start-up, naming file,
# keyword and value (common/expectBadInput.sh): tooSmall, a range whose
# smallest sphere relaxes faster than the DEM step; excludesDiameter, a
# range without the particles' 'diameter'; outsideRange, a sphere of the
# DEM script below the range.
#
# usage: runSettlingSizesTest.sh workDir tolerance [tooSmall|excludesDiameter|outsideRange]
set -e
work=$1
tol=$2
variant=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/caseFunctions.sh"
copyCase "$here/settling" "$work"

delta=1e-3                      # [m] centre cells: 10 large diameters
python3 "$here/makeSettlingMesh.py" . "$delta" 24
blockMesh > log.blockMesh 2>&1
# the spheres [um] at +-10 mm from the box centre in x, off the cell
# centres as the one-sphere test's (0.57 and 0.43 of a cell in y and z)
y=$(python3 -c "print('%.6f' % (32000 + 0.57*$delta*1e6))")
z=$(python3 -c "print('%.6f' % (32000 + 0.43*$delta*1e6))")
sed -i -e "s/^create_atoms .*/create_atoms    1 single 22310 $y $z units box\ncreate_atoms    1 single 42310 $y $z units box/" \
    -e "s/^set .*/set             atom 1 diameter 100 density \${colloid_density}\nset             atom 2 diameter 50 density \${colloid_density}/" \
    constant/DEM/in.liggghts
grep -q "^set             atom 2 diameter 50" constant/DEM/in.liggghts
props=constant/couplingProperties
foamDictionary $props -entry twoWay/kernelRadius -set "$(python3 -c "print(2*$delta)")" > /dev/null
foamDictionary $props -entry twoWay/selfInducedVelocity -set yes > /dev/null

case $variant in
    tooSmall)
        # 20 um spheres relax in rho d^2/(18 mu) = 5.6e-7 s, below the DEM
        # step of 2e-6 s
        foamDictionary $props -entry particles/diameterRange -add "(2e-05 0.0001)" > /dev/null
        expect="Keyword 'timeStep' in .*couplingProperties.DEM\"? is 2e-06 s, longer than the relaxation time m/K = 5.55[0-9]*e-07 s of particles of diameter 2e-05 m"
        source "$here/../common/expectBadInput.sh" ;;
    excludesDiameter)
        foamDictionary $props -entry particles/diameterRange -add "(2e-05 5e-05)" > /dev/null
        expect="Keyword 'diameterRange' in .*couplingProperties.particles\"? is \(2e-05 5e-05\) m; allowed: \(smallest largest\) with 0 < smallest <= diameter \(0.0001 m\) <= largest"
        source "$here/../common/expectBadInput.sh" ;;
    outsideRange)
        foamDictionary $props -entry particles/diameterRange -add "(5e-05 0.0001)" > /dev/null
        sed -i "s/^set             atom 2 diameter 50 /set             atom 2 diameter 40 /" constant/DEM/in.liggghts
        expect="1 particles of the DEM \(e.g. diameter 4e-05 m, density .*\) are not those of .*particles\"? \(diameterRange \(5e-05 0.0001\) m, density 2500 kg/m\^3\)"
        source "$here/../common/expectBadInput.sh" ;;
esac
foamDictionary $props -entry particles/diameterRange -add "(5e-05 0.0001)" > /dev/null

runSolver 1

python3 "$here/checkSettlingVelocity.py" "$work" "$tol" --diameters 1e-4,5e-5
