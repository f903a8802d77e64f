#!/bin/bash
# The particles of a slot-coater test run (fixture: serial, or parallel
# reconstructed by Allrun) read by OpenFOAM's and ParaView's tools:
# foamListTimes lists the write time, foamToVTK converts its cloud, and
# checkParticleReaders.py compares what each reader finds with the
# solver's log.  Works on a copy (foamToVTK writes into the case).
#
#   runParticleReadersTest.sh fixtureDir workDir
set -e
fixture=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/copyFixture.sh"
rm -rf VTK

latest=$(foamListTimes -latestTime | tail -1)
echo "foamListTimes: latest time $latest"
[ -d "$latest/lagrangian/particles" ] \
    || { echo "FAIL: no $latest/lagrangian/particles"; exit 1; }
foamToVTK -time "$latest" -no-internal -no-boundary \
    > log.foamToVTK 2>&1 || { echo "FAIL: foamToVTK"; tail -20 log.foamToVTK; exit 1; }

decomposed=
[ -d processor0/"$latest"/lagrangian ] && decomposed=decomposed
/usr/bin/python3 "$here/checkParticleReaders.py" . "$latest" $decomposed
