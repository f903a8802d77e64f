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
          lubricatedWallDiffusion)

# Lubrication noise across a processor boundary: the stock liggghts with
# the plugin preloaded, serial against 2 ranks (runBrownianParallelTest.sh)
find_program(LIGGGHTS_EXECUTABLE liggghts)
if(LIGGGHTS_EXECUTABLE)
    add_test(NAME dem.brownian.lubricatedPairsParallel
        COMMAND ${CMAKE_CURRENT_LIST_DIR}/runBrownianParallelTest.sh ${LIGGGHTS_EXECUTABLE}
                $<TARGET_FILE:liggghtsColloid> ${CMAKE_CURRENT_BINARY_DIR}/brownianParallel)
    set_tests_properties(dem.brownian.lubricatedPairsParallel PROPERTIES
        TIMEOUT 120 LABELS "dem;agglomeration" PROCESSORS 2
        PASS_REGULAR_EXPRESSION "PASS")
endif()
