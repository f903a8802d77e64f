# Brownian motion of the implicit drag update: brownianTest.cpp (label
# agglomeration)
add_executable(brownianTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/brownianTest.cpp)
target_include_directories(brownianTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(brownianTests PRIVATE liggghtsColloid GTest::gtest GTest::gtest_main)

foreach(name meanSquareDisplacement equipartition reproducible)
    add_test(NAME dem.brownian.${name} COMMAND brownianTests --gtest_filter=brownian.${name})
    set_tests_properties(dem.brownian.${name} PROPERTIES
        TIMEOUT 300 LABELS "dem;agglomeration"
        PASS_REGULAR_EXPRESSION "\\[  PASSED  \\] 1 test\\."
        WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endforeach()
