# Many-body stiff cases and the large-step approach of the implicit update
# of lubrication and drag: stiffTest.cpp (label stiff)
add_executable(stiffTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/stiffTest.cpp)
target_include_directories(stiffTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(stiffTests PRIVATE liggghtsColloid GTest::gtest GTest::gtest_main)

foreach(name lubricatedCluster13 lubricatedClusterAcrossPeriodicFace lubricatedSmallGroups
        lubricatedBlock108OnWall vdwCluster13 vdwBlock108OnWall
        compressedRandomPacking pinnedBetweenWalls approachAtStokesTime
        dragRelaxation movingWallLubrication)
    add_test(NAME dem.stiff.${name} COMMAND stiffTests --gtest_filter=stiff.${name})
    set_tests_properties(dem.stiff.${name} PROPERTIES
        TIMEOUT 120 LABELS "dem;stiff"
        PASS_REGULAR_EXPRESSION "\\[  PASSED  \\] 1 test\\."
        WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endforeach()
