# Fluid cases: OpenFOAM's own simpleFoam on small blockMesh gaps, each
# profile checked against its closed form (max error / max velocity < 1 %).
# Cases run in the build tree; the source tree is never written to.

foreach(gap poiseuille couettePoiseuille)
    add_test(NAME case.fluid.${gap}
        COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/fluidGap/runGapTest.sh
                ${CMAKE_CURRENT_SOURCE_DIR}/fluidGap/${gap}.params
                ${CMAKE_CURRENT_BINARY_DIR}/fluid/${gap})
    set_tests_properties(case.fluid.${gap} PROPERTIES TIMEOUT 120 LABELS "case;fluid")
endforeach()

# The slot-coater tutorial's steady flow (default size), serial and 2 ranks:
# mass conservation and the Couette-Poiseuille profile under the lip.
foreach(mode serial parallel)
    add_test(NAME case.fluid.slotCoater.${mode}
        COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/fluidSlotCoater/runSlotCoaterTest.sh
                ${mode} ${CMAKE_CURRENT_BINARY_DIR}/fluid/slotCoater-${mode})
    set_tests_properties(case.fluid.slotCoater.${mode} PROPERTIES TIMEOUT 180 LABELS "case;fluid")
endforeach()
