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
