# Sourced by the benchmarks that run the slot coater's DEM script in the
# stock liggghts binary without the fluid (slotCoaterCost, colloidTermCost,
# throughputScaling).  Run the functions in the case folder.
#
#   demOnlyInput script steps [command ...]
#
# prints a LIGGGHTS input that defines the variables colloidDEMFoam would
# define (micro units: um, us, pg), with the particles, the fluid and the
# DEM step of the case's constant/couplingProperties (one source: the
# values the coupled run uses), includes the script, runs any extra
# commands (e.g. a velocity command), one step, then the timed run of the
# given steps.
#
#   demCaseParameter key scale
#
# prints system/slotCoaterParameters' value of key times scale (e.g.
# gap 1e6 for micrometres).
#
#   demPlainHertz script > out       the script with plain Hertz contact
#                                    and no colloid terms
#   demRate log, demAtoms log        particle-steps per second per core,
#                                    and atoms, of a LIGGGHTS log's last loop
#   coupledRate log                  from colloidDEMFoam's log (master, after
#                                    the start-up): particle-steps per second
#                                    per rank, DEM and coupling seconds
#   demBreakdown log                 LIGGGHTS' own breakdown of a serial
#                                    log's last loop in ns per particle-step: pair,
#                                    neighbour lists, communication, the rest
#                                    (fixes, integration, output); and the
#                                    pairs listed per particle (half list; with
#                                    colloid models, after the plugin's trim)

# The case's couplingProperties with its #include and $ expanded, read
# once per input
demCouplingEntry()
{
    foamDictionary -entry "$1" -value constant/couplingProperties.expanded
}

demOnlyInput()
{
    local script=$1 steps=$2
    shift 2
    foamDictionary -case . -expand constant/couplingProperties \
        > constant/couplingProperties.expanded \
        || { echo "demOnlyInput: cannot read constant/couplingProperties" 1>&2; return 1; }
    # SI -> micro units: m -> um; kg/m^3 -> pg/um^3 (1e-3); Pa s -> pg/(um us) (1e3)
    # (the fluid's viscosity as mu [Pa s] or nu [m^2/s], as the solver takes it)
    local d rhoP rhoF mu dt
    d=$(demCouplingEntry particles/diameter)
    rhoP=$(demCouplingEntry particles/density)
    rhoF=$(demCouplingEntry fluid/rho)
    mu=$(demCouplingEntry fluid/mu 2> /dev/null) \
        || mu=$(awk -v rf="$rhoF" -v nu="$(demCouplingEntry fluid/nu)" 'BEGIN { printf "%.10g", rf*nu }')
    dt=$(demCouplingEntry DEM/timeStep)
    rm -f constant/couplingProperties.expanded
    awk -v d="$d" -v rp="$rhoP" -v rf="$rhoF" -v mu="$mu" -v dt="$dt" -v casedir="$PWD" 'BEGIN {
        print "units           micro"
        print "atom_modify     map array"
        printf "variable        colloid_case string %s\n", casedir
        printf "variable        colloid_diameter equal %.10g\n", d*1e6
        printf "variable        colloid_radius equal %.10g\n", d*0.5e6
        printf "variable        colloid_density equal %.10g\n", rp*1e-3
        printf "variable        colloid_fluid_density equal %.10g\n", rf*1e-3
        printf "variable        colloid_fluid_viscosity equal %.10g\n", mu*1e3
        printf "variable        colloid_timestep equal %.10g\n", dt*1e6
        print "variable        colloid_restart equal 0"
        print "variable        colloid_restart_file string none"
    }'
    echo "include         $script"
    echo "timestep        \${colloid_timestep}"
    local line
    for line in "$@"
    do
        echo "$line"
    done
    echo "run             1"
    echo "run             $steps"
}

demCaseParameter()
{
    awk -v k="$1" -v s="$2" '$1 == k { sub(";", "", $2); print $2*s; exit }' \
        system/slotCoaterParameters
}

demPlainHertz()
{
    sed -e 's#model walton_braun tangential walton_braun#model hertz tangential history#' \
        -e 's#model walton_braun tangential history#model hertz tangential history#' \
        -e 's#cohesion colloid/vdw/dl/lub##' \
        -e 's#groundedWall on diRenzoDiMaio on##' \
        "$1"
}

demRate()
{
    grep '^Loop time of' "$1" | tail -1 | awk '{ printf "%.4g", $12*$9/($4*$6) }'
}

demAtoms()
{
    grep '^Loop time of' "$1" | tail -1 | awk '{ print $12 }'
}

demBreakdown()
{
    awk '/^Loop time of/ { t = $4; p = $6; s = $9; n = $12 }
         /^Pair  time/ { pair = $5 }
         /^Neigh time/ { neigh = $5 }
         /^Comm  time/ { comm = $5 }
         /^Ave neighs\/atom/ { nb = $4 }
         END { if (n == 0) exit 1; f = 1e9*p/(s*n)
               printf "%.4g %.4g %.4g %.4g %.4g\n", pair*f, neigh*f, comm*f, (t - pair - neigh - comm)*f, nb }' "$1"
}

coupledRate()
{
    grep '^Timing (master, wall clock): DEM' "$1" | tail -1 \
        | sed 's/.*DEM \([^ ]*\) s, coupling \([^ ]*\) s; \([^ ]*\) .*/\3 \1 \2/'
}
