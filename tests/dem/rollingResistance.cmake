# Rolling resistance (LIGGGHTS' epsd2) with the plugin's van der Waals
# cohesion, against rigid-body mechanics of a sphere on a wall:
# rollingResistanceTest.cpp
add_executable(rollingResistanceTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/rollingResistanceTest.cpp)
target_include_directories(rollingResistanceTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(rollingResistanceTests PRIVATE liggghtsColloid GTest::gtest GTest::gtest_main)

dem_gtest_cases(rollingResistanceTests dem. *
    TIMEOUT 60 LABELS "dem;filtration"
    CASES rollingResistanceHoldsAdheredSphere rollingResistanceSlowsRollingSphere)
