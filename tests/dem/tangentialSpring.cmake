# The tangential contact spring (Walton-Braun, Di Renzo-Di Maio) against
# the closed-form oscillation of a sphere held on a wall:
# tangentialSpringTest.cpp
add_executable(tangentialSpringTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/tangentialSpringTest.cpp)
target_include_directories(tangentialSpringTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(tangentialSpringTests PRIVATE liggghtsColloid GTest::gtest GTest::gtest_main)

dem_gtest_cases(tangentialSpringTests dem. *
    TIMEOUT 60 LABELS "dem;stiff"
    CASES tangentialSpringWaltonBraun tangentialSpringDiRenzoDiMaio)
