# Filtration (seed 002; tutorials/filtration; label filtration).
#
# filtration.darcy: liquid driven by pressure down through the two-way
#   tests' fixed packed bed (twoWay.pack) inside the filtration case
#   (cyclic sides, pressure inlet, filter medium, outlet flux) gives the
#   bed the permeability that the packed-bed case gives it, within 3 %.

set(filtrationDir ${CMAKE_CURRENT_SOURCE_DIR}/filtration)
set(filtrationWork ${CMAKE_CURRENT_BINARY_DIR}/filtration)

add_test(NAME case.filtration.darcy
    COMMAND ${filtrationDir}/runDarcyTest.sh ${CMAKE_CURRENT_BINARY_DIR}/twoWay/pack
            ${filtrationWork}/darcy)
set_tests_properties(case.filtration.darcy PROPERTIES
    TIMEOUT 300 LABELS "case;filtration" FIXTURES_REQUIRED twoWayPack
    ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)

# filtration.medium: the filtration case with one particle: the clean
#   filter medium (a Darcy zone of two cells, constant/fvOptions) passes
#   the liquid at q = dp/(mu R_FM) within 0.1 %.
add_test(NAME case.filtration.medium
    COMMAND ${filtrationDir}/runMediumTest.sh ${filtrationWork}/medium)
set_tests_properties(case.filtration.medium PROPERTIES
    TIMEOUT 120 LABELS "case;filtration"
    ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)

# filtration.<variant>: the tutorial at test size (795 particles, 1.2 ms)
#   from its Allrun: the filtrate flows out at every step, the filtration
#   ends, t/V against V is straight (Ruth, R^2 >= 0.98), no particle
#   passes the medium.
foreach(variant stable flocculated)
    add_test(NAME case.filtration.${variant}
        COMMAND ${filtrationDir}/runFiltrationTest.sh ${variant}
                ${filtrationWork}/${variant})
    set_tests_properties(case.filtration.${variant} PROPERTIES
        TIMEOUT 900 LABELS "case;filtration"
        FIXTURES_SETUP filtration_${variant}
        ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endforeach()

# filtration.variants: flocculation shortens the filtration (the looser
# cake of seed 002 is not asserted: checkVariants.py says why).
add_test(NAME case.filtration.variants
    COMMAND python3 ${filtrationDir}/checkVariants.py
            ${filtrationWork}/stable/runs/stable
            ${filtrationWork}/flocculated/runs/flocculated)
set_tests_properties(case.filtration.variants PROPERTIES
    TIMEOUT 60 LABELS "case;filtration"
    FIXTURES_REQUIRED "filtration_stable;filtration_flocculated"
    ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)

# filtration.bondStrength: flocs held by bonds of about 30 % of the
#   contact loads (the flocculated variant with 30 times seed 002's
#   Hamaker constant, rolling resistance 0.1) build a cake looser than the
#   stable one by at least rolling resistance's own 0.010 plus ten
#   run-to-run standard deviations, at least 1.2 times as permeable, with
#   a Ruth slope at most 0.79 times the stable one's (checkBondStrength.py:
#   with seed 002's constant, or 30 times it without rolling resistance,
#   the checks fail).
add_test(NAME case.filtration.bondStrength
    COMMAND ${filtrationDir}/runBondStrengthTest.sh
            ${filtrationWork}/bondStrength
            ${filtrationWork}/stable/runs/stable)
set_tests_properties(case.filtration.bondStrength PROPERTIES
    TIMEOUT 1500 LABELS "case;filtration"
    FIXTURES_REQUIRED filtration_stable
    PASS_REGULAR_EXPRESSION "bond strength: all checks passed"
    ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)

# filtration.parallel: the stable variant on 2 ranks (METIS): the flow
#   rate of the serial run at every step up to 20 us within 1e-9 (the same
#   run until round-off grows), the filtrate volume at the end time within
#   3 % (2.5 standard deviations of the difference of two runs, measured
#   over four random suspensions; see checkFiltration.py).
add_test(NAME case.filtration.parallel
    COMMAND ${filtrationDir}/runFiltrationTest.sh stable
            ${filtrationWork}/stable_parallel -parallel ${filtrationWork}/stable)
set_tests_properties(case.filtration.parallel PROPERTIES
    TIMEOUT 900 LABELS "case;filtration" PROCESSORS 2
    FIXTURES_REQUIRED filtration_stable
    ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)

# filtration.exchangeLimit: the start-up limit of the explicit two-way
#   exchange on the fluid step (exchangeStability.H; 3.4e-7 s for the
#   tutorial's particles) against the cake it was made for, stable variant
#   at test size to 1 ms: at 3e-7 s the cake holds (the net drag on the
#   particles down at every fluid step after 0.3 ms, at most 3 times its
#   median); 6e-7 s is refused at start-up (couplingInterval and its
#   allowed range named, nothing but logs written), and run anyway with
#   twoWay/freeFluidFraction 0.8 the cake is blown apart (the drag up at 5
#   fluid steps or more, bursts of 20 times its median or more).
add_test(NAME case.filtration.exchangeLimit
    COMMAND ${filtrationDir}/runExchangeLimitTest.sh ${filtrationWork}/exchangeLimit)
set_tests_properties(case.filtration.exchangeLimit PROPERTIES
    TIMEOUT 1200 LABELS "case;filtration;twoWay"
    ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)

# filtration.consolidation: the stable test-size cake under a piston at
#   200, 400, 600, 800, 1000 kPa (DEM alone: the drained equilibrium):
#   at rest at every step with the piston force within 2 % of pressure x
#   area, and the packing density rising from step to step.
add_test(NAME case.filtration.consolidation
    COMMAND ${filtrationDir}/runConsolidationTest.sh
            ${filtrationWork}/stable/runs/stable ${filtrationWork}/consolidation)
set_tests_properties(case.filtration.consolidation PROPERTIES
    TIMEOUT 900 LABELS "case;filtration"
    FIXTURES_REQUIRED filtration_stable
    FIXTURES_SETUP filtration_consolidation
    ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)

# The same cake consolidated again, against the serial consolidation:
#   consolidationParallel: on 2 ranks (METIS's rank count of the case,
#     LIGGGHTS' subdomains side by side), the packing densities as the
#     serial ones (0.001);
#   consolidationRolling: with rolling resistance (rollingFriction 0.1,
#     LIGGGHTS' epsd2 with the stable variant's colloid model and at the
#     walls), looser than without it by at least 0.005
foreach(mode Parallel Rolling)
    string(TOLOWER ${mode} flag)
    add_test(NAME case.filtration.consolidation${mode}
        COMMAND ${filtrationDir}/runConsolidationTest.sh
                ${filtrationWork}/stable/runs/stable ${filtrationWork}/consolidation_${flag}
                -${flag} ${filtrationWork}/consolidation)
    set_tests_properties(case.filtration.consolidation${mode} PROPERTIES
        TIMEOUT 900 LABELS "case;filtration"
        FIXTURES_REQUIRED "filtration_stable;filtration_consolidation"
        ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endforeach()
set_tests_properties(case.filtration.consolidationParallel PROPERTIES PROCESSORS 2)

# A quick test without a solver run: its name, the line it prints when
# every check passed, and its command line (the work folder
# filtrationWork/name is appended; Python scripts by Debian's python3,
# /usr/bin/python3, which has numpy and matplotlib)
function(add_filtration_check name passed)
    add_test(NAME case.filtration.${name}
        COMMAND ${ARGN} ${filtrationWork}/${name})
    set_tests_properties(case.filtration.${name} PROPERTIES
        TIMEOUT 120 LABELS "case;filtration"
        PASS_REGULAR_EXPRESSION "${passed}"
        ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endfunction()

add_filtration_check(rollingFrictionInput
    "rollingFriction input: all checks passed"
    ${filtrationDir}/runRollingFrictionInputTest.sh)

# filtration.surfaceRangesInput: the surface forces' cut-offs and the
#   neighbour skin of system/filtrationParameters checked by prepareRun.sh
#   (each out of range refused), written for the DEM, and used by the
#   plugin (van der Waals between two spheres beyond the default cut-off
#   against the closed form; the double layer's cut-off and the pairs'
#   reach, lubrication's outer cut-off plus the skin, in its log)
add_filtration_check(surfaceRangesInput
    "surface ranges input: all checks passed"
    ${filtrationDir}/runSurfaceRangesInputTest.sh)

# filtration.gelSuspension: the flocculated suspension as one network
#   (makeFlocs.py ... gel) at the tests' size against the same seed's
#   flocs: one cluster, a tree of contacts, no overlap, the walls' margin,
#   the flocs moved rigidly, a bad argument refused
#   (checkGelSuspension.py)
add_filtration_check(gelSuspension "gel suspension: all checks passed"
    /usr/bin/python3 ${filtrationDir}/checkGelSuspension.py
    ${CMAKE_SOURCE_DIR}/tutorials/filtration/makeFlocs.py)

# filtration.finesSuspension: suspensions with fines (--fines of
#   makeSuspension.py and makeFlocs.py, what fineVolumeFraction asks for):
#   the counts of both sizes, no overlap, the random suspension's gaps and
#   wall margins, the flocs' clusters of touching spheres with the fines
#   mixed in, the gel one tree, a fines' size not below the spheres'
#   refused (checkFinesSuspension.py)
add_filtration_check(finesSuspension "fines suspension: all checks passed"
    /usr/bin/python3 ${filtrationDir}/checkFinesSuspension.py
    ${CMAKE_SOURCE_DIR}/tutorials)

# filtration.finesInput: fineVolumeFraction and fineDiameter reach the
#   suspension's counts and the coupling's diameterRange; bad values stop
#   prepareRun.sh with a message and no DEM files (runFinesInputTest.sh)
add_filtration_check(finesInput "fines input: all checks passed"
    ${filtrationDir}/runFinesInputTest.sh)

# filtration.flocculatedSuspensionInput: flocculatedSuspension flocs|gel
#   reaches makeFlocs.py; a bad value stops prepareRun.sh with a message
#   and no DEM files
add_filtration_check(flocculatedSuspensionInput
    "flocculatedSuspension input: all checks passed"
    ${filtrationDir}/runFlocculatedSuspensionInputTest.sh)

# filtration.compare: filtrationCompare.py's flocculation rows, the
#   filtration time's reduction and the Ruth slopes' ratio (the time's
#   reduction where the cake dominates), on hand-built run pairs that
#   follow Ruth's law, with a medium and without one; and the
#   Ergun-equivalent diameter of each cake, the hand-built ones' and
#   Table 2's, against Ergun's law written forwards (checkCompare.py)
add_filtration_check(compare "filtration comparison: all checks passed"
    /usr/bin/python3 ${filtrationDir}/checkCompare.py
    ${CMAKE_SOURCE_DIR}/tutorials/filtration)

# filtration.resultsDefinitions: filtrationResults.py's cake fraction,
#   which ends the filtration, is the solids volume's share below the
#   cake's top, not the particles' count (hand-built arrangements of 5.8
#   and 2.9 um spheres); a run ending between two contact dumps reports
#   the contacts of the last one; the filtration ends at 99 %, or where
#   the cake has stopped growing over two writes, not at a pause
#   (checkResultsDefinitions.py)
add_filtration_check(resultsDefinitions "results definitions: all checks passed"
    /usr/bin/python3 ${filtrationDir}/checkResultsDefinitions.py
    ${CMAKE_SOURCE_DIR}/tutorials/filtration)

# consolidationResults.py without a DEM run (checkConsolidation<check>.py):
#   Incomplete: a consolidation that stopped after 2 of its 5 pressures
#     exits non-zero, names DEM/consolidation.dat, the count and
#     consolidationPressures, and writes none of its outputs; on all 5 it
#     writes them; a pressure that stopped on the case's
#     consolidationStepLimit is reported not at rest;
#   Fit: eq. 14 fitted to its own densities, p0 free and held at
#     consolidationCommonP0, and a bad p0
foreach(check Incomplete Fit)
    add_test(NAME case.filtration.consolidation${check}
        COMMAND python3 ${filtrationDir}/checkConsolidation${check}.py
                ${CMAKE_SOURCE_DIR}/tutorials/filtration
                ${filtrationWork}/consolidation${check})
    set_tests_properties(case.filtration.consolidation${check} PROPERTIES
        TIMEOUT 60 LABELS "case;filtration"
        ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endforeach()
