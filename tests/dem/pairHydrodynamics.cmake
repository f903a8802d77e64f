# The two-sphere form of the lubrication (lubricationFarField 1):
# force- and flow-driven approach of a pair, pairHydrodynamicsTest.cpp
add_executable(pairHydrodynamicsTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/pairHydrodynamicsTest.cpp)
target_include_directories(pairHydrodynamicsTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(pairHydrodynamicsTests PRIVATE liggghtsColloid colloidModels GTest::gtest GTest::gtest_main)

dem_gtest_cases(pairHydrodynamicsTests dem.pairHydrodynamics. pairHydrodynamics
    TIMEOUT 120 LABELS "dem;agglomeration;errorVsCost"
    CASES forceDrivenApproach flowDrivenApproach
          forceDrivenApproachExplicit flowDrivenApproachExplicit)

# The flow factor across a processor boundary: the stock liggghts with the
# plugin preloaded, serial against 2 ranks (runPairFlowParallelTest.sh)
dem_liggghts_script_test(dem.pairHydrodynamics.flowAcrossRanks
    ${CMAKE_CURRENT_LIST_DIR}/runPairFlowParallelTest.sh ${CMAKE_CURRENT_BINARY_DIR}/pairFlowParallel
    LABELS "dem;agglomeration;errorVsCost")

# the same with the weak pairs damped explicitly (lubricationExplicitRatio)
dem_liggghts_script_test(dem.pairHydrodynamics.flowAcrossRanksExplicit
    ${CMAKE_CURRENT_LIST_DIR}/runPairFlowParallelTest.sh ${CMAKE_CURRENT_BINARY_DIR}/pairFlowParallelExplicit
    EXTRA_ARGS 0.25 LABELS "dem;agglomeration;errorVsCost;stiff")
