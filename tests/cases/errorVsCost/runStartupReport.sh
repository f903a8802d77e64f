#!/bin/bash
# What colloidDEMFoam prints at start-up as the error to expect, from the
# settling study's errorStudy/measuredErrors (case.errorVsCost.settlingStudy,
# the fixture): three runs of the settling case, one coupling step each,
#   onRung     DEM step 1e-8 s, a rung of the study's ladder
#   offLadder  DEM step 4e-9 s, on no rung
#   noStudy    no errorStudy folder
#   missingEntry  the study names an entry this case does not have
#   corrupt    the study file cut in the middle (a run never stops for it)
#   otherDensity  the particle density, part of the study's context, 2600
#              here against the study's 2500 kg/m^3
#   otherDrag  the study's context says another drag law (a word)
#   contextEntryMissing  the study's context names an entry the case lacks
# then checkStartupReport.py compares the printed lines with the study's
# errorStudy.csv.
#
# usage: runStartupReport.sh settlingStudyDir workDir
set -e
study=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc"
set -u

rm -rf "$work"
mkdir -p "$work"
for variant in onRung offLadder noStudy missingEntry corrupt otherDensity otherDrag \
    contextEntryMissing
do
    dir=$work/$variant
    cp -r "$study/errorStudy/demTimeStep/1_1e-08" "$dir"
    sed -i "s/^endTime .*/endTime 2e-08;/" "$dir/system/controlDict"
    case $variant in
        onRung|offLadder|missingEntry|corrupt|otherDensity|otherDrag|contextEntryMissing)
            mkdir "$dir/errorStudy"
            cp "$study/errorStudy/measuredErrors" "$dir/errorStudy/" ;;
    esac
    case $variant in
        missingEntry)
            sed -i 's#entry "DEM/couplingInterval"#entry "DEM/noSuchEntry"#' \
                "$dir/errorStudy/measuredErrors" ;;
        corrupt)
            head -c 600 "$study/errorStudy/measuredErrors" > "$dir/errorStudy/measuredErrors" ;;
        otherDensity)
            sed -i "s/^\( *density \+\)[^;]*;/\12600;/" "$dir/constant/couplingProperties" ;;
        contextEntryMissing)
            sed -i 's#entry "particles/density"#entry "particles/noSuchEntry"#' \
                "$dir/errorStudy/measuredErrors" ;;
        otherDrag)
            sed -i 's#entry "dragModel"; value "stokes"#entry "dragModel"; value "schillerNaumann"#' \
                "$dir/errorStudy/measuredErrors" ;;
    esac
    if [ "$variant" = offLadder ]
    then
        sed -i -e "s/^\( *timeStep \+\)[^;]*;/\14e-09;/" \
               -e "s/^\( *couplingInterval \+\)[^;]*;/\15;/" \
            "$dir/constant/couplingProperties"
    fi
    (cd "$dir" && colloidDEMFoam > log.colloidDEMFoam 2>&1) \
        || { tail -30 "$dir/log.colloidDEMFoam"; echo "FAIL: $variant run"; exit 1; }
done
/usr/bin/python3 "$here/checkStartupReport.py" "$study/errorStudy" "$work"
