# Sourced by the benchmarks that run the slot coater's DEM script in the
# stock liggghts binary without the fluid (slotCoaterCost, colloidTermCost).
#
#   demOnlyInput script steps timestep [command ...]
#
# prints a LIGGGHTS input that defines the variables colloidDEMFoam would
# define for the tutorial's particles (micro units: um, us, pg), includes
# the case's script, runs any extra commands (e.g. a velocity command),
# one step, then the timed run of the given steps.  Run it in the case
# folder (colloid_case is the working directory).
demOnlyInput()
{
    local script=$1 steps=$2 timestep=$3
    shift 3
    cat << EOI
units           micro
atom_modify     map array
variable        colloid_case string $PWD
variable        colloid_diameter equal 0.3
variable        colloid_radius equal 0.15
variable        colloid_density equal 2.5
variable        colloid_fluid_density equal 1.0
variable        colloid_fluid_viscosity equal 1.0
variable        colloid_timestep equal $timestep
variable        colloid_restart equal 0
variable        colloid_restart_file string none
include         $script
timestep        \${colloid_timestep}
EOI
    local line
    for line in "$@"
    do
        echo "$line"
    done
    echo "run             1"
    echo "run             $steps"
}
