# Wet restitution of a sphere driven at a wall through a liquid (lubrication
# + Walton-Braun) against the Stokes number: reboundStokesTest.cpp
add_executable(reboundStokesTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/reboundStokesTest.cpp)
target_include_directories(reboundStokesTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(reboundStokesTests PRIVATE liggghtsColloid GTest::gtest GTest::gtest_main)

foreach(name reboundStokesModel reboundStokesPrimitiveWall reboundStokesExperiments
             reboundStokesRupturedModel reboundStokesRupturedPrimitiveWall
             reboundStokesRupturedPair reboundStokesRupturedExperiments)
    add_test(NAME dem.${name} COMMAND reboundStokesTests --gtest_filter=*.${name})
    set_tests_properties(dem.${name} PROPERTIES
        TIMEOUT 60 LABELS dem
        PASS_REGULAR_EXPRESSION "\\[  PASSED  \\] 1 test\\."
        WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endforeach()
