#!/bin/bash
# Brownian motion in the coupled solver (couplingProperties brownian):
# 2000 free glass spheres (d = 1 um, 1 um apart or more) in quiescent water
# without gravity, T = 293.15 K, DEM step tau/69, run to 10 relaxation
# times, serial or on 2 ranks.  checkBrownian.py compares the mean square
# displacement with the Langevin closed form, and (parallel) the positions
# with the serial run's: the random forces are drawn per particle and step,
# so the ranks do not change them.
#
# usage: runBrownianTest.sh serial|parallel workDir
set -e
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
mode=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

source "$here/channelCase.sh"
newChannelCase
runLength 1.4e-06 70
sed -i 's/^value .*/value (0 0 0);/' constant/g
cat >> constant/couplingProperties <<'DICT'

brownian
{
    temperature     293.15;
    seed            7;
}
DICT
# in 1 < x < 99, 1 < z < 49: away from the box's faces (not periodic here)
python3 "$here/makeShearParticles.py" 2000 0.5 25 75 98 48 1.0 \
    | awk '{ $4 += 1; $6 += 1; print }' > particles.liggghts
includeParticles particles.liggghts
meshAndQuiescentFluid
runChannelSolver "$mode"
grep "^Brownian motion" log.colloidDEMFoam \
    || { echo "FAIL: no 'Brownian motion' line in log.colloidDEMFoam"; exit 1; }
python3 "$here/checkBrownian.py" . $( [ "$mode" = parallel ] && echo "$(dirname "$work")/brownian_serial" )
