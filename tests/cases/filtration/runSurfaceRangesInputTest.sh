#!/bin/bash
# The surface forces' cut-offs and the neighbour skin of
# system/filtrationParameters reach the DEM, and bad values stop
# prepareRun.sh before anything is written:
#  - each cut-off out of its range (the outer ones not beyond the inner
#    ones: the plugin's 0.4 nm, lubricationInnerCutoff) and a skin not
#    above 0 are refused with a message naming the file, the keyword, the
#    value and the allowed range, and no DEM files;
#  - good values are written to DEM/filtration.liggghts in micrometres,
#    and the DEM scripts use them (no literal cut-off or skin left);
#  - LIGGGHTS with the plugin, given the case's contacts.liggghts and the
#    written values: flocculated, with van der Waals to 0.3 um, two glass
#    spheres 0.15 um apart (beyond the default 0.1 um) pull each other
#    with the shifted Derjaguin force A R*/6 (1/h^2 - 1/h_out^2) within
#    1e-6; stable, the plugin reports the double layer's cut-off it was
#    given and lists its pairs to the lubrication's outer cut-off (made
#    the longest, 0.4 um) and the skin.
# (Values as foamDictionary prints them: the message quotes them so.)
#
# usage: runSurfaceRangesInputTest.sh workDir
set -e
source "$(dirname "$0")/prepareRunInput.sh" "$1"
set_() { sed -i "s/^$1 .*/$1 $2;/" $params; }

refused vdwOuterCutoff 1e-10 "0.4e-9 < vdwOuterCutoff < 1e-3"
set_ vdwOuterCutoff 0.1e-6
refused doubleLayerOuterCutoff 0.01 "0.4e-9 < doubleLayerOuterCutoff < 1e-3"
set_ doubleLayerOuterCutoff 0.05e-6
refused lubricationInnerCutoff 2e-06 "0 < lubricationInnerCutoff < 1e-6"
set_ lubricationInnerCutoff 0.01e-6
refused lubricationOuterCutoff 5e-09 "1e-08 < lubricationOuterCutoff < 1e-3"
set_ lubricationOuterCutoff 0.1e-6
refused neighbourSkin 0 "0 < neighbourSkin < inf"

# Good values reach DEM/filtration.liggghts [um]
set_ vdwOuterCutoff 0.3e-6
set_ doubleLayerOuterCutoff 0.06e-6
set_ lubricationInnerCutoff 0.02e-6
set_ lubricationOuterCutoff 0.11e-6
set_ neighbourSkin 0.6e-6
set_ variant flocculated
rm -rf DEM
"$COLLOIDFOAM_TUTORIALS/filtration/prepareRun.sh" -testSize > log.prepareRun \
    || fail "good values: prepareRun.sh failed"
for pair in vdwOuterCutoff:0.3 doubleLayerOuterCutoff:0.06 \
    lubricationInnerCutoff:0.02 lubricationOuterCutoff:0.11 neighbourSkin:0.6
do
    key=${pair%%:*} want=${pair#*:}
    awk -v k="$key" -v v="$want" '$1 == "variable" && $2 == k && $3 == "equal" {
            found = 1; if ($4 + 0 != v + 0) bad = 1 }
        END { exit !found || bad }' DEM/filtration.liggghts \
        || fail "$key: DEM/filtration.liggghts does not hold $want um"
done
echo "good values: written in um"
for script in in.liggghts in.consolidation
do
    grep -q '^neighbor  *${neighbourSkin} bin$' constant/DEM/$script \
        || fail "constant/DEM/$script: no 'neighbor \${neighbourSkin} bin'"
done
! grep -n 'Cutoff scalar [0-9.]' constant/DEM/surfaceForces.* \
    || fail "a literal cut-off in constant/DEM/surfaceForces.*"

# The plugin uses them: two spheres at a gap of 0.15 um on the x axis,
# at rest (no contact, no lubrication), the force on each after run 0
d=$(foamDictionary -entry particleDiameter -value $params)
A=$(foamDictionary -entry hamakerConstant -value $params)
cat > in.ranges <<'EOI'
units           micro
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
include         ${colloid_case}/DEM/filtration.liggghts
region          box block -10 10 -10 10 -10 10 units box
create_box      1 box
neighbor        ${neighbourSkin} bin
neigh_modify    delay 0
include         ${colloid_case}/constant/DEM/contacts.liggghts
create_atoms    1 single ${x1} 0 0 units box
create_atoms    1 single ${x2} 0 0 units box
set             group all diameter ${diameter}
set             group all density 2.5
timestep        1e-4
fix             integrate all nve/sphere
run             0
variable        f1 equal fx[1]
variable        f2 equal fx[2]
print           "force on 1 ${f1} nN, on 2 ${f2} nN"
EOI
runRanges() {
    env LD_PRELOAD="$FOAM_USER_LIBBIN/libliggghtsColloid.so" liggghts \
        -in in.ranges -log "$1" -echo none -var colloid_case "$PWD" \
        -var colloid_fluid_viscosity 1 \
        -var diameter "$(awk -v d="$d" 'BEGIN { printf "%.10g", d*1e6 }')" \
        -var x1 "$(awk -v d="$d" 'BEGIN { printf "%.10g", -(d*1e6 + 0.15)/2 }')" \
        -var x2 "$(awk -v d="$d" 'BEGIN { printf "%.10g", (d*1e6 + 0.15)/2 }')" \
        > "$1.screen" 2>&1 || { tail -5 "$1.screen"; fail "liggghts ($1) failed"; }
}
runRanges log.flocculated
# the closed form: Derjaguin, R* = d/4, shifted at the cut-off 0.3 um [nN]
expected=$(awk -v A="$A" -v d="$d" 'BEGIN {
    h = 0.15e-6; hOut = 0.3e-6
    printf "%.10g", A*(d/4)/6*(1/h^2 - 1/hOut^2)*1e9 }')
forces=$(sed -n 's/^force on 1 \(.*\) nN, on 2 \(.*\) nN$/\1 \2/p' log.flocculated 2> /dev/null || true)
awk -v f="$forces" -v e="$expected" 'BEGIN {
    split(f, F, " ")
    exit !(e > 0 && F[1] > 0 && (F[1] - e)/e < 1e-6 && (e - F[1])/e < 1e-6 && F[2] + F[1] == 0) }' \
    || fail "van der Waals at 0.15 um: forces '$forces' nN, expected +-$expected nN"
echo "van der Waals at a gap of 0.15 um with the cut-off 0.3 um: $forces nN (closed form $expected)"

set_ variant stable
set_ lubricationOuterCutoff 0.4e-6
rm -rf DEM
"$COLLOIDFOAM_TUTORIALS/filtration/prepareRun.sh" -testSize > log.prepareRun \
    || fail "stable: prepareRun.sh failed"
runRanges log.stable
grep -q "doubleLayerOuterCutoff 6e-08 m is" log.stable \
    || fail "stable: the plugin does not report doubleLayerOuterCutoff 6e-08 m ($(grep -m1 doubleLayerOuterCutoff log.stable))"
echo "stable: $(grep -m1 'doubleLayerOuterCutoff' log.stable)"
grep -q "the colloid range 0.4 or half the skin, the larger, plus the skin 0.6)" log.stable \
    || fail "stable: the pairs not listed to the lubrication's 0.4 um plus the skin 0.6 um ($(grep -m1 'colloid pair list' log.stable))"
echo "stable: $(grep -m1 'colloid pair list' log.stable)"

[ "$failures" -eq 0 ] || { echo "$failures failures"; exit 1; }
echo "surface ranges input: all checks passed"
