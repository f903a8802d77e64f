# Many-body stiff cases and the large-step approach of the implicit update
# of lubrication and drag: stiffTest.cpp (label stiff)
add_executable(stiffTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/stiffTest.cpp)
target_include_directories(stiffTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(stiffTests PRIVATE liggghtsColloid GTest::gtest GTest::gtest_main)

dem_gtest_cases(stiffTests dem.stiff. stiff
    TIMEOUT 120 LABELS "dem;stiff"
    CASES lubricatedCluster13 lubricatedClusterAcrossPeriodicFace lubricatedSmallGroups
          lubricatedBlock108OnWall vdwCluster13 vdwBlock108OnWall
          compressedRandomPacking pinnedBetweenWalls approachAtStokesTime
          dragRelaxation movingWallLubrication
          weakPairsExplicitOpenBlock weakPairsExplicitMixedBlock weakPairsExplicitDenseBlock
          weakPairsExplicitUnequalMasses)

# The weak pairs damped explicitly across a processor boundary: the stock
# liggghts with the plugin preloaded, serial against 2 ranks
# (runWeakPairsParallelTest.sh)
dem_liggghts_script_test(dem.stiff.weakPairsAcrossRanks
    ${CMAKE_CURRENT_LIST_DIR}/runWeakPairsParallelTest.sh ${CMAKE_CURRENT_BINARY_DIR}/weakPairsParallel
    LABELS "dem;stiff")
