# Wet restitution of a sphere driven at a wall through a liquid (lubrication
# + Walton-Braun) against the Stokes number: reboundStokesTest.cpp
add_executable(reboundStokesTests
    ${CMAKE_CURRENT_LIST_DIR}/liggghtsRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/reboundStokesTest.cpp)
target_include_directories(reboundStokesTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(reboundStokesTests PRIVATE liggghtsColloid GTest::gtest GTest::gtest_main)

dem_gtest_cases(reboundStokesTests dem. *
    TIMEOUT 60 LABELS dem
    CASES reboundStokesModel reboundStokesPrimitiveWall reboundStokesExperiments
          reboundStokesRupturedModel reboundStokesRupturedPrimitiveWall
          reboundStokesRupturedPair reboundStokesRupturedExperiments)
