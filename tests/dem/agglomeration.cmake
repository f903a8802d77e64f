# Contact and agglomerate analysis on hand-built arrangements:
# contactAnalysisTest.cpp (label agglomeration)
add_executable(contactAnalysisTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/contactAnalysisTest.cpp)
target_include_directories(contactAnalysisTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(contactAnalysisTests PRIVATE liggghtsColloid GTest::gtest GTest::gtest_main)

dem_gtest_cases(contactAnalysisTests dem.contactAnalysis. contactAnalysis
    TIMEOUT 120 LABELS "dem;agglomeration"
    CASES arrangements passingContactDuration durationAcrossRestart waveringContact)
