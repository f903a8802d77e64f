# Runs that are never lost and never lie (label reliability).  They reuse
# the slot-coater test runs (slotCoater.cmake) as fixtures: about 2000
# particles with Walton-Braun contact, the colloid forces, mesh walls, a
# feed (the coupling's, particleFeed) and an outflow (massflow/mesh).
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
# reliability.diskFull: the serial fixture run again in a 7 MB tmpfs that
#   fills at the third write: a clear stop with the file system's reason,
#   no incomplete time folder, and once the tmpfs is grown, a resume from
#   the last complete write to the end (skipped, exit 77, without root).
# reliability.allrun.<probe>: the slot-coater Allrun at test size with a
#   user's faults and mistakes (runAllrunProbeTest.sh): nu 0, a steady
#   flow that does not converge, a fill that cannot reach its solids
#   fraction, a re-run after a failed run, -parallel with an end time that
#   is no write time, a killed run resumed with ./Allrun -resume, a DEM
#   step above the plugin's contact limit (the stop advises DEM timeStep).  Each
#   must give its exit status, message and files.
# reliability.overlaps.<serial|parallel>: four overlapping pairs of initial
#   particles, across the three mid-planes (one is the processor boundary
#   on 2 ranks) and a periodic face, all found and named before LIGGGHTS'
#   set-up (runOverlapTest.sh); reliability.overlaps.warning: a pair
#   overlapping by 5 % only warns, naming it, and the run goes on.
# reliability.overlaps.inserted.<serial|parallel>: the same check for a
#   particle the script inserts during the run, 3 um from one present
#   from the start (across LIGGGHTS' processor boundary on 2 ranks): the
#   log's smallest gap names the pair and gives 3 um within 0.02 um, and
#   a closer pair of particles present from the start does not count.
# reliability.outsideFluid: a particle outside the fluid mesh at the start
#   is counted and named (id, position) in a warning; the run goes on.
# coupling.badInput.<resumeIncomplete, misspeltKeyword, misspeltTopKeyword,
#   diameterMismatch, lostParticle, particleOutsideBox, coincidentParticles,
#   purgeWrite> (coupling.cmake, also labelled here): each stops the run
#   with a message naming the setting or the particles.

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

add_test(NAME case.reliability.diskFull
    COMMAND ${reliabilityDir}/runDiskFullTest.sh
            ${reliabilityFixtures}/serial ${reliabilityWork}/diskFull)
set_tests_properties(case.reliability.diskFull PROPERTIES
    TIMEOUT 180 LABELS "case;reliability" SKIP_RETURN_CODE 77
    FIXTURES_REQUIRED slotCoater_serial)

foreach(probe nuZero cutoffFormTypo lubricationFormTypo explicitRatioTooLarge notConverged fillTooDense rerunAfterFailure
              shortEndTimeParallel resumeAfterKill demStepTooLong)
    add_test(NAME case.reliability.allrun.${probe}
        COMMAND ${reliabilityDir}/runAllrunProbeTest.sh ${probe}
                ${reliabilityWork}/allrun_${probe})
    set_tests_properties(case.reliability.allrun.${probe} PROPERTIES
        TIMEOUT 180 LABELS "case;reliability")
endforeach()
set_tests_properties(case.reliability.allrun.shortEndTimeParallel PROPERTIES
    PROCESSORS 2)

foreach(nProcs 1 2)
    set(name case.reliability.overlaps.serial)
    if(nProcs EQUAL 2)
        set(name case.reliability.overlaps.parallel)
    endif()
    add_test(NAME ${name}
        COMMAND ${reliabilityDir}/runOverlapTest.sh ${nProcs}
                ${reliabilityWork}/overlaps_${nProcs})
    set_tests_properties(${name} PROPERTIES
        TIMEOUT 60 LABELS "case;reliability" PROCESSORS ${nProcs})
endforeach()

# reliability.outflowResume[AtEnd].<serial|parallel>: a particle an outflow
#   (massflow/mesh, delete_atoms) counted 2.5 DEM steps before a write
#   within the run (AtEnd: before the end time, written although not a
#   write time),
#   not yet deleted by LIGGGHTS (it deletes at the next rebuild of the
#   neighbour lists): the rebuild the coupling asks for before each write
#   deletes it, so that a run resumed from that write does not lose it
#   (runOutflowResumeTest.sh).
foreach(mode serial parallel)
    foreach(at write end)
        if(at STREQUAL write)
            set(name case.reliability.outflowResume.${mode})
        else()
            set(name case.reliability.outflowResumeAtEnd.${mode})
        endif()
        add_test(NAME ${name}
            COMMAND ${reliabilityDir}/runOutflowResumeTest.sh ${mode} ${at}
                    ${reliabilityWork}/outflowResume_${mode}_${at})
        if(mode STREQUAL parallel)
            set(nProcs 2)
        else()
            set(nProcs 1)
        endif()
        set_tests_properties(${name} PROPERTIES
            TIMEOUT 120 LABELS "case;reliability" PROCESSORS ${nProcs}
            PASS_REGULAR_EXPRESSION "PASS")
    endforeach()
endforeach()

add_test(NAME case.reliability.outsideFluid
    COMMAND ${reliabilityDir}/runOutsideFluidTest.sh ${reliabilityWork}/outsideFluid)
set_tests_properties(case.reliability.outsideFluid PROPERTIES
    TIMEOUT 60 LABELS "case;reliability")

foreach(nProcs 1 2)
    set(name case.reliability.overlaps.inserted.serial)
    if(nProcs EQUAL 2)
        set(name case.reliability.overlaps.inserted.parallel)
    endif()
    add_test(NAME ${name}
        COMMAND ${reliabilityDir}/runOverlapTest.sh ${nProcs}
                ${reliabilityWork}/overlapsInserted_${nProcs} inserted)
    set_tests_properties(${name} PROPERTIES
        TIMEOUT 60 LABELS "case;reliability" PROCESSORS ${nProcs})
endforeach()

add_test(NAME case.reliability.overlaps.warning
    COMMAND ${reliabilityDir}/runOverlapTest.sh 1
            ${reliabilityWork}/overlaps_warning warn)
set_tests_properties(case.reliability.overlaps.warning PROPERTIES
    TIMEOUT 60 LABELS "case;reliability")
