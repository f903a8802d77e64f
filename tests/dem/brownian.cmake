# Brownian motion of the implicit drag update: brownianTest.cpp (label
# agglomeration)
add_executable(brownianTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/brownianTest.cpp)
target_include_directories(brownianTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(brownianTests PRIVATE liggghtsColloid GTest::gtest GTest::gtest_main)

dem_gtest_cases(brownianTests dem.brownian. brownian
    TIMEOUT 300 LABELS "dem;agglomeration"
    CASES meanSquareDisplacement equipartition reproducible lubricatedPairDiffusion
          lubricatedPairDiffusionExplicit lubricatedPairVelocities
          lubricatedPairVelocitiesExplicit lubricatedWallDiffusion)

# Lubrication noise across a processor boundary: the stock liggghts with
# the plugin preloaded, serial against 2 ranks (runBrownianParallelTest.sh)
dem_liggghts_script_test(dem.brownian.lubricatedPairsParallel
    ${CMAKE_CURRENT_LIST_DIR}/runBrownianParallelTest.sh ${CMAKE_CURRENT_BINARY_DIR}/brownianParallel
    LABELS "dem;agglomeration")
