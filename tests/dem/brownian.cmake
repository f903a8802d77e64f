# Brownian motion of the implicit drag update: brownianTest.cpp (label
# agglomeration)
add_executable(brownianTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/brownianTest.cpp)
target_include_directories(brownianTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(brownianTests PRIVATE liggghtsColloid GTest::gtest GTest::gtest_main)

foreach(name meanSquareDisplacement equipartition reproducible lubricatedPairDiffusion
        lubricatedWallDiffusion)
    add_test(NAME dem.brownian.${name} COMMAND brownianTests --gtest_filter=brownian.${name})
    set_tests_properties(dem.brownian.${name} PROPERTIES
        TIMEOUT 300 LABELS "dem;agglomeration"
        PASS_REGULAR_EXPRESSION "\\[  PASSED  \\] 1 test\\."
        WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endforeach()

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
