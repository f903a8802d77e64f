# Oblique impacts on a wall for each tangential law (Walton-Braun,
# Di Renzo-Di Maio) against the law integrated in the test, rigid-body
# sliding and the experiments of Kharaz et al. (2001): obliqueImpactTest.cpp
add_executable(obliqueImpactTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/obliqueImpactTest.cpp)
target_include_directories(obliqueImpactTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(obliqueImpactTests PRIVATE liggghtsColloid GTest::gtest GTest::gtest_main)

foreach(name obliqueImpactWaltonBraun obliqueImpactDiRenzoDiMaio)
    add_test(NAME dem.${name} COMMAND obliqueImpactTests --gtest_filter=*.${name})
    set_tests_properties(dem.${name} PROPERTIES
        TIMEOUT 120 LABELS "dem;stiff"
        PASS_REGULAR_EXPRESSION "\\[  PASSED  \\] 1 test\\."
        WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endforeach()
