# Runs that are never lost and never lie (label reliability).  They reuse
# the slot-coater test runs (slotCoater.cmake) as fixtures: about 2000
# particles with Walton-Braun contact, the colloid forces, mesh walls, a
# feed (insert/stream) and an outflow (massflow/mesh).
#
# reliability.resume.<serial|parallel>: the run again from time 0, killed
#   with SIGKILL right after its write at 1.2 us, resumed from latestTime
#   to 3 us: the same particles as the uninterrupted run, at least 95 %
#   identical to every written digit and none further than 1e-3 d
#   (compareClouds.py).
# reliability.particleReaders.<serial|parallel>: the last write's particles
#   (lagrangian/particles) read by ParaView's OpenFOAM reader
#   (reconstructed, and decomposed for the parallel run), by foamToVTK and
#   by particleCloud.py: the count of the solver's log, the same ids and
#   positions, every field present.
# coupling.badInput.resumeIncomplete (coupling.cmake, also labelled here):
#   a later time folder without the DEM state stops the run, naming it.

set(reliabilityDir ${CMAKE_CURRENT_SOURCE_DIR}/reliability)
set(reliabilityWork ${CMAKE_CURRENT_BINARY_DIR}/reliability)
set(reliabilityFixtures ${CMAKE_CURRENT_BINARY_DIR}/slotCoater)

foreach(mode serial parallel)
    add_test(NAME case.reliability.resume.${mode}
        COMMAND ${reliabilityDir}/runResumeTest.sh ${mode}
                ${reliabilityFixtures}/${mode} ${reliabilityWork}/resume_${mode})
    set_tests_properties(case.reliability.resume.${mode} PROPERTIES
        TIMEOUT 300 LABELS "case;reliability"
        FIXTURES_REQUIRED slotCoater_${mode})

    add_test(NAME case.reliability.particleReaders.${mode}
        COMMAND ${reliabilityDir}/runParticleReadersTest.sh
                ${reliabilityFixtures}/${mode} ${reliabilityWork}/readers_${mode})
    set_tests_properties(case.reliability.particleReaders.${mode} PROPERTIES
        TIMEOUT 120 LABELS "case;reliability"
        FIXTURES_REQUIRED slotCoater_${mode})
endforeach()
set_tests_properties(case.reliability.resume.parallel PROPERTIES PROCESSORS 2)
