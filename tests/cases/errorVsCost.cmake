# Error against run time (issue 10): colloidErrorStudy (bin/) and the
# convergence analysis it uses (src/python/convergence.py).
#
# errorVsCost.convergence: Richardson's order, extrapolation and the
#   asymptotic-range check on ladders with a closed-form answer.
# errorVsCost.settlingStudy: the tool on the coupled settling particle in
#   quiescent water over a DEM-step ladder: observed order within 0.2 of
#   the drag's 2, Richardson's error estimates within a factor 2 of the
#   true errors against the closed form (checkSettlingStudy.py).
# errorVsCost.badInput.*: a bad study stops with a message naming the
#   keyword and the allowed values, a non-zero exit, no output.

set(errorVsCostDir ${CMAKE_CURRENT_SOURCE_DIR}/errorVsCost)
set(errorVsCostWork ${CMAKE_CURRENT_BINARY_DIR}/errorVsCost)

add_test(NAME errorVsCost.convergence
    COMMAND python3 ${errorVsCostDir}/testConvergence.py)
set_tests_properties(errorVsCost.convergence PROPERTIES
    TIMEOUT 30 LABELS "unit;errorVsCost" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)

add_test(NAME case.errorVsCost.settlingStudy
    COMMAND ${errorVsCostDir}/runSettlingStudy.sh ${errorVsCostWork}/settling)
set_tests_properties(case.errorVsCost.settlingStudy PROPERTIES
    TIMEOUT 300 LABELS "case;errorVsCost" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)

# errorVsCost.startupReport: colloidDEMFoam prints at start-up the error
#   the settling study measured at the case's DEM step, its run time and
#   the cheapest rung within 1 % and 5 %, as errorStudy.csv gives them;
#   "not measured" off the ladder, "none measured" without a study and
#   where the case is not the study's context (another particle density,
#   another drag law, a context entry the case lacks: the entry and both
#   values named) (checkStartupReport.py).
set_tests_properties(case.errorVsCost.settlingStudy PROPERTIES
    FIXTURES_SETUP errorVsCostSettlingStudy)
add_test(NAME case.errorVsCost.startupReport
    COMMAND ${errorVsCostDir}/runStartupReport.sh ${errorVsCostWork}/settling
            ${errorVsCostWork}/startupReport)
set_tests_properties(case.errorVsCost.startupReport PROPERTIES
    TIMEOUT 120 LABELS "case;errorVsCost" FIXTURES_REQUIRED errorVsCostSettlingStudy
    ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)

foreach(variant shortLadder badLimit missingEntry variableEntry badExpression missingQuantity
        badContext missingContext variableContext changedContext)
    add_test(NAME case.errorVsCost.badInput.${variant}
        COMMAND ${errorVsCostDir}/runStudyBadInput.sh ${variant} ${errorVsCostWork}/badInput_${variant})
    set_tests_properties(case.errorVsCost.badInput.${variant} PROPERTIES
        TIMEOUT 30 LABELS "case;errorVsCost" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endforeach()

# A rung that runs but prints a quantity that is not finite (nan): a failed
# rung in the report, the study goes on (runStudyNotFinite.sh)
add_test(NAME case.errorVsCost.notFiniteRung
    COMMAND ${errorVsCostDir}/runStudyNotFinite.sh ${errorVsCostWork}/notFiniteRung)
set_tests_properties(case.errorVsCost.notFiniteRung PROPERTIES
    TIMEOUT 30 LABELS "case;errorVsCost" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)

# errorVsCost.slotCoaterStudy: the slot-coater tutorial's own study
#   (tutorials/slotCoater/system/errorStudyDict) at test size to 2 us, for
#   the DEM step, coupling step, colloid range, cell size and flow
#   tolerance: every rung runs, the default is on each ladder, and every
#   quantity the tool calls converging does so monotonically
#   (checkSlotCoaterStudy.py).
add_test(NAME case.errorVsCost.slotCoaterStudy
    COMMAND ${errorVsCostDir}/runSlotCoaterStudy.sh ${errorVsCostWork}/slotCoater 2e-6
            demTimeStep,couplingStep,colloidRange,cellSize,flowTolerance)
set_tests_properties(case.errorVsCost.slotCoaterStudy PROPERTIES
    TIMEOUT 1200 LABELS "case;errorVsCost;slotCoater" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
