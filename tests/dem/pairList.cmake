# The colloid pair style's neighbour list trimmed to the colloid range
# (pairListTest.cpp; label agglomeration: issue 12's run times); own
# main, so that the list test also runs on 2 ranks
add_executable(pairListTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/pairListTest.cpp)
target_include_directories(pairListTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(pairListTests PRIVATE liggghtsColloid GTest::gtest)

dem_gtest_cases(pairListTests dem.pairList. pairList
    TIMEOUT 300 LABELS "dem;agglomeration"
    CASES trimKeepsHistoryWithItsPair listHoldsEveryPairInRange untrimmedWithDelay
          contactHistorySurvivesTrim)

# both ranks check their own list (the check's counts are summed over the
# ranks, so both pass or fail together); passed only if mpiexec and both
# ranks exit cleanly
add_test(NAME dem.pairList.listHoldsEveryPairInRange.2ranks
    COMMAND sh -c "\"$0\" ${MPIEXEC_NUMPROC_FLAG} 2 ${MPIEXEC_PREFLAGS} \"$1\" --gtest_filter=pairList.listHoldsEveryPairInRange --gtest_color=no && echo 'both ranks passed'"
            ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:pairListTests>)
set_tests_properties(dem.pairList.listHoldsEveryPairInRange.2ranks PROPERTIES
    TIMEOUT 300 LABELS "dem;agglomeration" PROCESSORS 2
    PASS_REGULAR_EXPRESSION "\\[  PASSED  \\] 1 test\\..*both ranks passed"
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
