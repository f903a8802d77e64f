#!/bin/bash
# The viscousStress force model: a neutrally buoyant sphere of d = 20 um at
# the centre of a cell near the middle of the one-way plane Poiseuille
# channel (tests/cases/coupling/case, H = 100 um) reaches
#     v_x = U_x(y) + V mu U_x''/(3 pi mu d) = U_x(y) - (4/9) (d/H)^2 Umax
# (Stokes drag plus V div(tau); checkViscousStress.py).  Without the force
# v_x = U_x(y): the test tells the two apart by 1.8 % of Umax.
#
# usage: runViscousStressTest.sh workDir
set -e
work=$1
here=$(cd "$(dirname "$0")" && pwd)
source "$here/caseFunctions.sh"
copyCase "$here/../coupling/case" "$work"

H=1e-4      # channel height [m]
Umax=1e-3   # centre-line velocity [m/s]
blockMesh > log.blockMesh 2>&1
mkdir -p 0
postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
python3 "$here/../coupling/setPoiseuilleU.py" . $H $Umax

props=constant/couplingProperties
foamDictionary $props -entry forceModels -set "(gravityBuoyancy viscousStress)" > /dev/null
foamDictionary $props -entry particles/diameter -set 2e-5 > /dev/null
foamDictionary $props -entry particles/density -set 1000 > /dev/null
# relaxation time rho_p d^2/(18 mu) = 2.2e-5 s: DEM step 1e-7 s, 10 per
# coupling step, 20 relaxation times
foamDictionary $props -entry DEM/timeStep -set 1e-7 > /dev/null
foamDictionary system/controlDict -entry deltaT -set 1e-6 > /dev/null
foamDictionary system/controlDict -entry endTime -set 4.4e-4 > /dev/null
foamDictionary system/controlDict -entry writeInterval -set 40 > /dev/null
foamDictionary system/fvSchemes -entry divSchemes/"div(T(grad(U)))" \
    -add "Gauss linear" > /dev/null
# at the centre of the cell (45, 52.5, 25) um
sed -i "s/^create_atoms .*/create_atoms    1 single 45 52.5 25 units box/" \
    constant/DEM/in.liggghts

runSolver 1
python3 "$here/checkViscousStress.py" "$work" $H $Umax
