# The two-sphere form of the lubrication (lubricationFarField 1):
# force- and flow-driven approach of a pair, pairHydrodynamicsTest.cpp
add_executable(pairHydrodynamicsTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/pairHydrodynamicsTest.cpp)
target_include_directories(pairHydrodynamicsTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(pairHydrodynamicsTests PRIVATE liggghtsColloid colloidModels GTest::gtest GTest::gtest_main)

dem_gtest_cases(pairHydrodynamicsTests dem.pairHydrodynamics. pairHydrodynamics
    TIMEOUT 120 LABELS "dem;agglomeration;errorVsCost"
    CASES forceDrivenApproach flowDrivenApproach)

# The flow factor across a processor boundary: the stock liggghts with the
# plugin preloaded, serial against 2 ranks (runPairFlowParallelTest.sh)
find_program(LIGGGHTS_EXECUTABLE liggghts)
if(LIGGGHTS_EXECUTABLE)
    add_test(NAME dem.pairHydrodynamics.flowAcrossRanks
        COMMAND ${CMAKE_CURRENT_LIST_DIR}/runPairFlowParallelTest.sh ${LIGGGHTS_EXECUTABLE}
                $<TARGET_FILE:liggghtsColloid> ${CMAKE_CURRENT_BINARY_DIR}/pairFlowParallel)
    set_tests_properties(dem.pairHydrodynamics.flowAcrossRanks PROPERTIES
        TIMEOUT 120 LABELS "dem;agglomeration;errorVsCost" PROCESSORS 2
        PASS_REGULAR_EXPRESSION "PASS")
endif()
