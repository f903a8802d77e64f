#!/bin/bash
# Bad input must stop colloidDEMFoam before anything is written, with a
# non-zero exit and a message naming the file and the keyword.
#
# usage: runBadInputTest.sh variant workDir
#   variants: missingKeyword negativeDiameter negativeDensity
#             unknownDragModel inconsistentDeltaT demStepTooLong
#             gravityInScript demScriptError resumeIncomplete
#             misspeltKeyword misspeltTopKeyword diameterMismatch lostParticle
#             particleOutsideBox coincidentParticles purgeWrite
#             feedUnknownPatch feedSolidsFraction feedInterval feedNoInflow
#             releaseBelowTouching releaseBeyondSkin
set -e
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
variant=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

rm -rf "$work"
mkdir -p "$(dirname "$work")"
cp -r "$here/case" "$work"
cd "$work"
blockMesh > log.blockMesh 2>&1
mkdir -p 0
postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
python3 "$here/setPoiseuilleU.py" . 1e-4 1e-3

props=constant/couplingProperties
case $variant in
    missingKeyword)
        foamDictionary $props -entry fluid/mu -remove > /dev/null
        expect="Missing keyword 'mu' in .*couplingProperties" ;;
    negativeDiameter)
        foamDictionary $props -entry particles/diameter -set -1e-6 > /dev/null
        expect="Keyword 'diameter' in .*couplingProperties.* is -1e-06; allowed range: > 0" ;;
    negativeDensity)
        foamDictionary $props -entry fluid/rho -set -1000 > /dev/null
        expect="Keyword 'rho' in .*couplingProperties.* is -1000; allowed range: > 0" ;;
    unknownDragModel)
        foamDictionary $props -entry dragModel -set noSuchDrag > /dev/null
        expect="Unknown dragModel 'noSuchDrag' \(keyword 'dragModel' in .*couplingProperties\"?\)" ;;
    inconsistentDeltaT)
        foamDictionary system/controlDict -entry deltaT -set 3e-08 > /dev/null
        expect="Keyword 'deltaT' in .*controlDict\"? is 3e-08 s but must equal" ;;
    demStepTooLong)
        # relaxation time 1.39e-7 s; 2e-7 s x 10 with deltaT to match
        foamDictionary $props -entry DEM/timeStep -set 2e-07 > /dev/null
        foamDictionary system/controlDict -entry deltaT -set 2e-06 > /dev/null
        expect="Keyword 'timeStep' in .*couplingProperties.DEM\"? is 2e-07 s, longer than the relaxation time" ;;
    feedUnknownPatch|feedSolidsFraction|feedInterval|feedNoInflow)
        # the feed's settings (particleFeed): through the x = 0 side
        patch=sides; fraction=0.05; interval=2e-7
        case $variant in
            feedUnknownPatch)
                patch=noSuchPatch
                expect="Keyword 'patch' in .*couplingProperties.feed\"? is noSuchPatch; allowed: a patch of the mesh" ;;
            feedSolidsFraction)
                fraction=0.7
                expect="Keyword 'solidsFraction' in .*couplingProperties.feed\"? is 0.7; allowed range: \(0, 0.5\]" ;;
            feedInterval)
                interval=3e-8
                expect="Keyword 'interval' in .*couplingProperties.feed\"? is 3e-08 s; allowed: a whole number \(1 or more\) of coupling steps of 2e-08 s" ;;
            feedNoInflow)
                patch=walls
                expect="Keyword 'patch' in .*couplingProperties.feed\"? is walls: the liquid does not flow in through it" ;;
        esac
        printf 'feed\n{\n    patch %s;\n    solidsFraction %s;\n    minimumGap 1e-7;\n    interval %s;\n    seed 1;\n}\n' \
            "$patch" "$fraction" "$interval" >> $props ;;
    gravityInScript)
        echo "fix gravity all gravity 9.81e-6 vector 0 -1 0" >> constant/DEM/in.liggghts
        expect="defines a 'fix gravity'" ;;
    demScriptError)
        # LIGGGHTS exits by itself; its error must reach the solver's output
        echo "fix oops all noSuchFixStyle" >> constant/DEM/in.liggghts
        expect="ERROR: Invalid fix style: \"noSuchFixStyle\"" ;;
    misspeltKeyword)
        # an optional keyword misspelt: not silently ignored
        foamDictionary $props -entry DEM/scren -add yes > /dev/null
        expect="Unknown keyword 'scren' in .*couplingProperties.DEM\"?; did you mean 'screen'\?" ;;
    misspeltTopKeyword)
        foamDictionary $props -entry forceModel -add "(gravityBuoyancy)" > /dev/null
        expect="Unknown keyword 'forceModel' in .*couplingProperties\"?; did you mean 'forceModels'\?" ;;
    diameterMismatch)
        # the DEM's particles are not those of the settings
        echo "set group all diameter 2.0" >> constant/DEM/in.liggghts
        expect="1 particles of the DEM \(e.g. diameter 2e-06 m, density .*\) are not those of .*particles" ;;
    purgeWrite)
        foamDictionary system/controlDict -entry purgeWrite -set 2 > /dev/null
        expect="Keyword 'purgeWrite' in .*controlDict\"? is 2; colloidDEMFoam needs 0" ;;
    coincidentParticles)
        # two particles at one place: named, before LIGGGHTS meets them
        sed -i 's/^create_atoms .*/&\n&/' constant/DEM/in.liggghts
        expect="1 pairs of the DEM's initial particles .* overlap by more than 10 % .*" ;;
    particleOutsideBox)
        # a particle of the data file outside the DEM box: named as such
        printf '%s\n' "LIGGGHTS data file" "" "1 atoms" "1 atom types" "" \
            "0 100 xlo xhi" "0 100 ylo yhi" "0 50 zlo zhi" "" "Atoms" "" \
            "1 1 1.0 2.5 150.0 31.7 23.9" > constant/DEM/outside.data
        sed -i '/^region /d; /^create_box /d; /^create_atoms /d' constant/DEM/in.liggghts
        sed -i 's|^communicate .*|&\nread_data ${colloid_case}/constant/DEM/outside.data|' constant/DEM/in.liggghts
        expect="That is: some particles of the DEM's data file lie outside its simulation box" ;;
    lostParticle)
        # a particle thrown out of the DEM box, LIGGGHTS told to ignore it:
        # the first write stops the run (its fields are written: allowed)
        printf 'thermo_modify lost ignore\nvelocity all set 1e4 0 0\n' >> constant/DEM/in.liggghts
        filesAllowed=yes
        expect="1 particles were lost by the DEM .*allowLostParticles yes" ;;
    releaseBelowTouching)
        # a contact that would end before it forms
        printf 'contactAnalysis\n{\n    touchingGap 0.02;\n    releaseGap 0.01;\n}\n' >> $props
        expect="Keyword 'releaseGap' in .*couplingProperties.contactAnalysis\"? is 0.01; allowed range: \[0.02, 1\) \(a gap as a fraction of the smaller radius; not below touchingGap\)" ;;
    releaseBeyondSkin)
        # a held contact the neighbour list may no longer hold: 0.5 x 0.5 um
        # against half the DEM script's skin of 0.1 um
        printf 'contactAnalysis\n{\n    touchingGap 0.01;\n    releaseGap 0.5;\n}\n' >> $props
        expect="the release or agglomerate gap \(0.5 of the largest radius 0.5: 0.25\) exceeds half the neighbour skin \(0.05\)" ;;
    resumeIncomplete)
        # a later time folder without the DEM state (as one killed while
        # it was written) and startFrom latestTime: not resumed from
        cp -r 0 1e-07
        foamDictionary system/controlDict -entry startFrom -set latestTime > /dev/null
        expect="The start time 1e-07 has no DEM state .*its write did not complete" ;;
    *)  echo "unknown variant $variant"; exit 2 ;;
esac

source "$here/../common/expectBadInput.sh"
