# Stiff and extreme cases: each either runs stably, checked against closed
# forms (demExtremeTests, in process), or stops at start-up with a message
# naming the limit; and bad input stops with a message naming the property,
# value and range (demProcessTests: the stock liggghts program with the
# plugin preloaded, since LIGGGHTS' errors end the process). ctest names
# dem.<test case>, as in CMakeLists.txt.
add_executable(demExtremeTests
    liggghtsRun.cpp
    extremePairTest.cpp
    extremeWallTest.cpp
    extremeSaltTest.cpp)
target_include_directories(demExtremeTests PRIVATE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(demExtremeTests PRIVATE liggghtsColloid GTest::gtest GTest::gtest_main)

dem_gtest_cases(demExtremeTests dem. *
    TIMEOUT 60 LABELS dem
    CASES extremeSmallParticles extremeLargeHamaker extremeTinyGap
          extremeTinyGapLubricated extremeOverlapping extremeHighSalt
          extremeWallImpact extremeWallImpactLubricated
          extremeLowSaltForce extremeHighSaltForce)

if(LIGGGHTS_EXECUTABLE)
    add_executable(demProcessTests
        liggghtsProcess.cpp
        badInputTest.cpp
        startupLimitTest.cpp)
    target_compile_definitions(demProcessTests PRIVATE
        LIGGGHTS_EXECUTABLE="${LIGGGHTS_EXECUTABLE}"
        COLLOID_PLUGIN_LIBRARY="$<TARGET_FILE:liggghtsColloid>")
    target_link_libraries(demProcessTests PRIVATE GTest::gtest GTest::gtest_main)
    add_dependencies(demProcessTests liggghtsColloid)

    dem_gtest_cases(demProcessTests dem. *
        TIMEOUT 60 LABELS dem
        CASES badInputValidScriptRuns badInputNegativeStiffness
              badInputRestitutionAboveOne badInputZetaAbove300mV
              badInputHamakerTooLarge badInputNoSalt badInputMissingRestitution
              badInputMisspeltOptionalProperty
              startupLimitSmallParticles startupLimitSmallParticlesOverride
              startupLimitLargeHamaker startupLimitStiffWall
              startupLimitSoftContact startupLimitSoftWall
              startupLimitStiffTangential)
    # the limits of the stiff terms (label stiff too)
    dem_gtest_cases(demProcessTests dem. *
        TIMEOUT 60 LABELS "dem;stiff"
        CASES startupLimitDoubleLayerSpring startupLimitViscousFix
              startupLimitDiRenzoDiMaioWall)
else()
    message(WARNING "liggghts program not found: the bad-input and start-up limit tests are not built")
endif()
