# Sourced by the script tests that run the stock liggghts with the plugin
# preloaded (run*ParallelTest.sh): $liggghts and $plugin set by the script.
#
#   twoSphereLubricationScript data K1 hOut ratio skin
# prints the head of a LIGGGHTS input for spheres read from data, split
# along x over ${ranks} ranks: Walton-Braun contacts (K1 [N/m]),
# lubrication alone in the two-sphere form faded at hOut [um],
# lubricationExplicitRatio ratio (a number or a LIGGGHTS variable), the
# neighbour skin [um], integrated by nve/sphere at the step ${dt}
#
#   runLiggghts ranks input tag [-var name value ...]
# runs input on 1 rank or on 2 (mpirun), writing log.<tag>.<ranks> and
# screen.<tag>.<ranks>, with -var ranks <ranks> and the variables given;
# on failure prints FAIL with the screen's end and exits.
runLiggghts()
{
    local ranks=$1 input=$2 tag=$3
    shift 3
    local args=(-in "$input" -var ranks "$ranks" "$@" -log "log.$tag.$ranks")
    if [ "$ranks" = 1 ]
    then
        LD_PRELOAD="$plugin" "$liggghts" "${args[@]}" > "screen.$tag.$ranks" 2>&1
    else
        LD_PRELOAD="$plugin" mpirun -np 2 -x LD_PRELOAD "$liggghts" "${args[@]}" > "screen.$tag.$ranks" 2>&1
    fi || { echo "FAIL: the run $tag on $ranks rank(s)"; tail -20 "screen.$tag.$ranks"; exit 1; }
}

twoSphereLubricationScript()
{
    local data=$1 K1=$2 hOut=$3 ratio=$4 skin=$5
    cat <<SCRIPT
units           micro
atom_modify     map array sort 0 0.0
boundary        f f f
newton          off
communicate     single vel yes
processors      \${ranks} 1 1
atom_style      sphere
read_data       $data
fix m1 all property/global loadingStiffness peratomtypepair 2 $K1 $K1 $K1 $K1
fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5
fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3
fix l1 all property/global liquidViscosity scalar 1.0
fix l2 all property/global lubricationInnerCutoff scalar 0.001
fix l3 all property/global lubricationOuterCutoff scalar $hOut
fix l4 all property/global lubricationFade scalar 1
fix l5 all property/global lubricationFarField scalar 1
fix l6 all property/global lubricationExplicitRatio scalar $ratio
neighbor        $skin bin
neigh_modify    delay 0
pair_style      gran model walton_braun tangential history cohesion colloid/lub timeStepCheck off
pair_coeff      * *
timestep        \${dt}
fix integrate all nve/sphere
SCRIPT
}
