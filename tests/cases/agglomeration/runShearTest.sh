#!/bin/bash
# Orthokinetic (shear) collisions counted by the contact analysis, against
# Smoluchowski's rectilinear kernel.  One-way coupled spheres (R = 0.5 um,
# glass, Hertz contact only: no surface forces, no lubrication) in the
# simple shear U_x = G (y - H/2), G = 1e4 1/s, of the coupling tests'
# channel (100 x 100 x 50 um, the DEM periodic in x and z), 3 % solids in
# the band 25 < y < 75 um (five cells from the walls), run to a strain of
# 2 (2e-4 s; Stokes number G tau = 1.4e-3: the spheres follow the flow).
# checkShearCollisions.py compares the contacts formed with the kernel
# integrated over the band.
#
# usage: runShearTest.sh workDir
set -e
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
work=$1
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

H=100; G=1e4; R=0.5; y0=25; y1=75; Lx=100; Lz=50; N=14324   # um, 1/s; 3 % of the band
endTime=2e-4

source "$here/channelCase.sh"
newChannelCase
cat > system/shear <<DICT
G       $G;     // shear rate [1/s]
H       ${H}e-6;    // channel height [m]
R       ${R}e-6;    // particle radius [m]
y0      ${y0}e-6;   // the particles' band [m]
y1      ${y1}e-6;
Lx      ${Lx}e-6;   // periodic lengths [m]
Lz      ${Lz}e-6;
DICT
sed -i -e "s/^endTime .*/endTime $endTime;/" -e "s/^deltaT .*/deltaT 1e-07;/" \
    -e "s/^writeInterval .*/writeInterval 2000;/" system/controlDict
sed -i -e "s/^\( *timeStep *\).*/\1 2e-8;/" -e "s/^\( *couplingInterval *\).*/\1 5;/" \
    constant/couplingProperties
cat >> constant/couplingProperties <<'DICT'

contactAnalysis
{
    interval        1;
    touchingGap     0.01;
    agglomerateGap  0.01;
}
DICT
python3 "$here/makeShearParticles.py" $N $R $y0 $y1 $Lx $Lz 0.02 > particles.liggghts
# Soft glass (E = 1e6 Pa: a Rayleigh time of 1.4e-7 s, 7 DEM steps), the
# box periodic in x and z, the particles of particles.liggghts
sed -i -e 's/^boundary .*/boundary        p f p/' \
    -e 's/youngsModulus peratomtype .*/youngsModulus peratomtype 1e3/' constant/DEM/in.liggghts
grep -q "youngsModulus peratomtype 1e3" constant/DEM/in.liggghts
includeParticles particles.liggghts
blockMesh > log.blockMesh 2>&1
mkdir -p 0
postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
python3 "$here/setShearU.py" . ${H}e-6 $G
colloidDEMFoam > log.colloidDEMFoam 2>&1 || { tail -30 log.colloidDEMFoam; exit 1; }
grep "^Contacts:" log.colloidDEMFoam | tail -1
python3 "$here/checkShearCollisions.py" .
