# Contact and agglomerate analysis on hand-built arrangements:
# contactAnalysisTest.cpp (label agglomeration)
add_executable(contactAnalysisTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/contactAnalysisTest.cpp)
target_include_directories(contactAnalysisTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(contactAnalysisTests PRIVATE liggghtsColloid GTest::gtest GTest::gtest_main)

foreach(name arrangements passingContactDuration durationAcrossRestart waveringContact)
    add_test(NAME dem.contactAnalysis.${name} COMMAND contactAnalysisTests --gtest_filter=contactAnalysis.${name})
    set_tests_properties(dem.contactAnalysis.${name} PROPERTIES
        TIMEOUT 120 LABELS "dem;agglomeration"
        PASS_REGULAR_EXPRESSION "\\[  PASSED  \\] 1 test\\."
        WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endforeach()
