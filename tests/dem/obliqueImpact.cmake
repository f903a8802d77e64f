# Oblique impacts on a wall for each tangential law (Walton-Braun,
# Di Renzo-Di Maio) against the law integrated in the test, rigid-body
# sliding and the experiments of Kharaz et al. (2001): obliqueImpactTest.cpp
add_executable(obliqueImpactTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/obliqueImpactTest.cpp)
target_include_directories(obliqueImpactTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(obliqueImpactTests PRIVATE liggghtsColloid GTest::gtest GTest::gtest_main)

dem_gtest_cases(obliqueImpactTests dem. *
    TIMEOUT 120 LABELS "dem;stiff"
    CASES obliqueImpactWaltonBraun obliqueImpactDiRenzoDiMaio)
