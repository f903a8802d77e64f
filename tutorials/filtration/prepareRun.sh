#!/bin/bash
# Prepare one filtration run in the current case folder (Allrun runs it in
# each runs/<variant>/; the tests too), from system/filtrationParameters:
#   DEM/filtration.liggghts   the DEM's values in its units (um, us, pg)
#   DEM/suspension.data       the suspension at t = 0, the same for the
#                             same sizes: stable, single spheres at random
#                             (makeSuspension.py); flocculated, flocs of
#                             flocSize spheres (makeFlocs.py), or these
#                             joined into one network (flocculatedSuspension
#                             gel); spheres not in one floc (not joined by
#                             the gel) at least 5 % of the smaller one's
#                             diameter apart; with fineVolumeFraction > 0
#                             that share of the solids volume in fines of
#                             fineDiameter (and constant/couplingProperties'
#                             particles/diameterRange set to both sizes)
#   log.timeStep              seed 002's critical step (eq. 12) against
#                             the DEM step
#
#   prepareRun.sh [-testSize]
#   -testSize: first shrink the model to the tests' size, 58 um across
#   (10 diameters, 5 cells) with 185.6 um of suspension (794 particles):
#   a cake of about 7 layers, enough for t/V against V to be straight;
#   end time 1.2 ms (the filtration ends at about 0.9 ms)
set -e
tutorial=$(cd "$(dirname "$0")" && pwd)
mkdir -p DEM/contacts

case "${1:-}" in
    "") ;;
    -testSize)
        sed -i -e "s/^width .*/width 58;/" -e "s/^nWidth .*/nWidth 5;/" \
            -e "s/^nUpper .*/nUpper 15;/" system/filtrationParameters
        foamDictionary system/controlDict -entry endTime -set 1.2e-3 > /dev/null
        ;;
    *) echo "usage: $0 [-testSize]" 1>&2; exit 1 ;;
esac

param()
{
    local value
    value=$(foamDictionary -entry "$1" -value system/filtrationParameters) \
        && [ -n "$value" ] \
        || { echo "$0: no '$1' in system/filtrationParameters" 1>&2; exit 1; }
    echo "$value"
}
# The physical settings, where they are set (the plugin checks the
# contact and surface-force values again, in its units)
. "$COLLOIDFOAM_DIR"/etc/AllrunFunctions
params=system/filtrationParameters
for key in width cellSize mediumThickness filtrationPressure \
    mediumResistance rho mu particleDiameter particleDensity youngsModulus \
    saltConcentration
do
    checkParameter $params $key 0 -
done
checkParameter $params solidsFraction 0 0.64
# the outer cut-offs beyond the plugin's inner ones (van der Waals and
# double layer 0.4 nm, lubrication lubricationInnerCutoff)
checkParameter $params vdwOuterCutoff 0.4e-9 1e-3
checkParameter $params doubleLayerOuterCutoff 0.4e-9 1e-3
checkParameter $params lubricationInnerCutoff 0 1e-6
checkParameter $params lubricationOuterCutoff "$(param lubricationInnerCutoff)" 1e-3
checkParameter $params neighbourSkin 0 -
skin=$(param neighbourSkin)
checkParameter $params poissonsRatio -1 0.5
# A value from 0 (off: so not checkParameter's open range) below 1
fromZeroBelowOne()
{
    local value
    value=$(param "$1")
    awk -v v="$value" 'BEGIN {
        exit !(v ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ && v + 0 >= 0 && v + 0 < 1) }' \
        || { echo "$params: keyword '$1' is $value; allowed range:" \
            "0 <= $1 < 1" 1>&2; exit 1; }
    echo "$value"
}
rollingFriction=$(fromZeroBelowOne rollingFriction)
# fines: that share of the solids volume, of a smaller size
fineFraction=$(fromZeroBelowOne fineVolumeFraction)
checkParameter $params fineDiameter 0 "$(param particleDiameter)"
fineDiameter=$(param fineDiameter)
flocculatedSuspension=$(param flocculatedSuspension)
case "$flocculatedSuspension" in
    flocs|gel) ;;
    *) echo "$params: keyword 'flocculatedSuspension' is" \
           "$flocculatedSuspension; allowed: flocs or gel" 1>&2; exit 1 ;;
esac

# The DEM's values in its units (um, nN/um^2 = 1e3 Pa, fJ)
width=$(param width); height=$(param slurryHeight)
d=$(param particleDiameter); phi=$(param solidsFraction)
E=$(param youngsModulus); nu=$(param poissonsRatio)
e=$(param restitution); mu=$(param friction)
A=$(param hamakerConstant); zeta=$(param zetaPotential)
salt=$(param saltConcentration); rhop=$(param particleDensity)
vdwOut=$(param vdwOuterCutoff); dlOut=$(param doubleLayerOuterCutoff)
lubIn=$(param lubricationInnerCutoff); lubOut=$(param lubricationOuterCutoff)
dt=$(foamDictionary -entry DEM/timeStep -value constant/couplingProperties)
nc=$(foamDictionary -entry DEM/couplingInterval -value constant/couplingProperties)
nw=$(foamDictionary -entry writeInterval -value system/controlDict)
awk -v L="$width" -v H="$height" -v E="$E" -v nu="$nu" -v e="$e" \
    -v mu="$mu" -v mur="$rollingFriction" -v A="$A" -v zeta="$zeta" -v salt="$salt" \
    -v vdwOut="$vdwOut" -v dlOut="$dlOut" -v lubIn="$lubIn" -v lubOut="$lubOut" \
    -v skin="$skin" -v variant="$(param variant)" -v writeSteps=$((nc*nw)) '
BEGIN {
    print "# Written by prepareRun.sh from system/filtrationParameters (units micro)"
    printf "variable variant string %s\n", variant
    printf "variable boxWidth equal %.10g\n", L
    printf "variable boxHeight equal %.10g\n", H
    printf "variable youngsModulus equal %.10g\n", E*1e-3
    printf "variable poissonsRatio equal %.10g\n", nu
    printf "variable restitution equal %.10g\n", e
    printf "variable friction equal %.10g\n", mu
    printf "variable rollingFriction equal %.10g\n", mur
    printf "variable rollingModel string %s\n", (mur > 0 ? "epsd2" : "off")
    printf "variable hamakerConstant equal %.10g\n", A*1e15
    printf "variable zetaPotential equal %.10g\n", zeta
    printf "variable saltConcentration equal %.10g\n", salt
    printf "variable vdwOuterCutoff equal %.10g\n", vdwOut*1e6
    printf "variable doubleLayerOuterCutoff equal %.10g\n", dlOut*1e6
    printf "variable lubricationInnerCutoff equal %.10g\n", lubIn*1e6
    printf "variable lubricationOuterCutoff equal %.10g\n", lubOut*1e6
    printf "variable neighbourSkin equal %.10g\n", skin*1e6
    printf "variable writeSteps equal %d\n", writeSteps
}' > DEM/filtration.liggghts

# Time-step limits: seed 002 eq. 12, sqrt(m/k) with k the Hertz
# contact's stiffness (6 E*^2 R* F)^(1/3) at the paper's mean
# contact force F = 3.06 uN, for the smallest spheres (two fines, with
# fines); the plugin prints its own limits (surface forces, lubrication)
# in log.liggghts
dSmall=$(awk -v x="$fineFraction" -v d="$d" -v f="$fineDiameter" \
    'BEGIN { print (x > 0 ? f : d) }')
awk -v d="$dSmall" -v rho="$rhop" -v E="$E" -v nu="$nu" -v dt="$dt" 'BEGIN {
    pi = 3.14159265358979; m = rho*pi/6*d^3
    Es = E/(2*(1 - nu^2)); Rs = d/4; F = 3.06e-6
    k = (6*Es^2*Rs*F)^(1/3)
    printf "Critical step (seed 002 eq. 12) sqrt(m/k) = %.3g s " \
        "(spheres of %g m, k = %.3g N/m at 3.06 uN); DEM step %g s = 1/%.0f of it\n", \
        sqrt(m/k), d, k, dt, sqrt(m/k)/dt
}' | tee log.timeStep

# The suspension at t = 0: solids fraction of the column, the share
# fineVolumeFraction of it in fines
n=$(awk -v L="$width" -v H="$height" -v d="$d" -v phi="$phi" -v x="$fineFraction" \
    'BEGIN { printf "%d", (1 - x)*phi*L*L*H/(3.14159265358979/6*(d*1e6)^3) + 0.5 }')
nFine=$(awk -v L="$width" -v H="$height" -v d="$fineDiameter" -v phi="$phi" -v x="$fineFraction" \
    'BEGIN { printf "%d", x*phi*L*L*H/(3.14159265358979/6*(d*1e6)^3) + 0.5 }')
diameter=$(awk -v d="$d" 'BEGIN { printf "%.10g", d*1e6 }')
fines=()
if [ "$nFine" -gt 0 ]
then
    fines=(--fines "$nFine" "$(awk -v d="$fineDiameter" 'BEGIN { printf "%.10g", d*1e6 }')")
fi
# A suspension that cannot be made (no room for a floc, no gel) leaves
# neither it, the DEM's values nor log.timeStep behind
trap 'rm -f DEM/filtration.liggghts DEM/suspension.data log.timeStep' ERR
if [ "$(param variant)" = flocculated ]
then
    # At the isoelectric point the suspension has flocculated for minutes
    # before it reaches the filter (makeFlocs.py says why): flocs, or
    # flocs joined into one network (gel)
    gel=
    [ "$flocculatedSuspension" = gel ] && gel=gel
    python3 "$tutorial"/makeFlocs.py DEM/suspension.data "$n" "$diameter" \
        "$width" "$height" "$width" 2718 "$(param flocSize)" $gel "${fines[@]}"
else
    python3 "${COLLOIDFOAM_TUTORIALS:-$tutorial/..}"/twoWay/makeSuspension.py \
        DEM/suspension.data \
        "$n" "$diameter" "$width" "$height" "$width" 2718 column "${fines[@]}"
fi
trap - ERR
# the coupling's start-up checks for both sizes: a line of the particles
# dictionary, after its density (a folder prepared again without fines
# keeps no range); the file keeps its #include, macros and comments
sed -i '/^    diameterRange /d' constant/couplingProperties
if [ "$nFine" -gt 0 ]
then
    sed -i "/^particles/,/^}/ s|^\(    density .*\)\$|\1\n    diameterRange   ($fineDiameter $d); // [m] prepareRun.sh: fines|" \
        constant/couplingProperties
    grep -q "^    diameterRange   ($fineDiameter $d);" constant/couplingProperties \
        || { echo "$0: could not set particles/diameterRange in" \
                  "constant/couplingProperties (no 'density' line in 'particles')" 1>&2; exit 1; }
fi
echo "$n particles${fines:+ and $nFine fines of $fineDiameter m} at solids fraction $phi in $width x $height x $width um"

