# The slot-coater tutorial end to end (tutorials/slotCoater/Allrun: mesh,
# steady flow, DEM surfaces, coupled particle run with Walton-Braun contact
# and van der Waals, double layer and lubrication) at test size.
#
# slotCoater.serial / .parallel: the run reaches its end time; present =
#   inserted - removed at every write, each write time's cloud holding the
#   particles present inside the fluid; the initial fill and the feed hold the numbers of
#   particles the solids fraction implies; particles were removed
#   (checkBookkeeping.py).
# slotCoater.serialVsParallel: from the same initial fill, the two runs
#   insert, hold and remove the same particles and agree on their mean
#   velocity within 1 %.
# slotCoater.rankMatching (label throughput too: issue 11): the parallel
#   run again with METIS' two parts swapped: the DEM's ranks are reordered
#   so that each subdomain is on the rank of its cells, the records that
#   cross ranks are those of the unmatched fluid volume, the contact
#   analysis still counts every particle, and a resume gives the particles
#   of the uninterrupted run (runRankMatchingTest.sh).
# slotCoater.inletBackflow.serial / .parallel (label agglomeration too:
#   issue 12, Brownian runs lost fed particles this way): a particle
#   leaving the fluid back up through the inlet next to the slot's wall is
#   removed and counted by the tutorial's inlet outflow, not lost
#   (runInletBackflowTest.sh).

set(slotCoaterDir ${CMAKE_CURRENT_SOURCE_DIR}/slotCoater)
set(slotCoaterWork ${CMAKE_CURRENT_BINARY_DIR}/slotCoater)

foreach(mode serial parallel)
    add_test(NAME case.slotCoater.${mode}
        COMMAND ${slotCoaterDir}/runSlotCoaterRun.sh ${mode} ${slotCoaterWork}/${mode})
    set_tests_properties(case.slotCoater.${mode} PROPERTIES
        TIMEOUT 300 LABELS "case;slotCoater"
        ENVIRONMENT PYTHONDONTWRITEBYTECODE=1
        FIXTURES_SETUP slotCoater_${mode})
endforeach()
set_tests_properties(case.slotCoater.parallel PROPERTIES PROCESSORS 2)

add_test(NAME case.slotCoater.serialVsParallel
    COMMAND python3 ${slotCoaterDir}/compareBookkeeping.py
            ${slotCoaterWork}/serial ${slotCoaterWork}/parallel)
set_tests_properties(case.slotCoater.serialVsParallel PROPERTIES
    TIMEOUT 30 LABELS "case;slotCoater"
    FIXTURES_REQUIRED "slotCoater_serial;slotCoater_parallel")

add_test(NAME case.slotCoater.rankMatching
    COMMAND ${slotCoaterDir}/runRankMatchingTest.sh
            ${slotCoaterWork}/parallel ${slotCoaterWork}/rankMatching)
set_tests_properties(case.slotCoater.rankMatching PROPERTIES
    TIMEOUT 300 LABELS "case;slotCoater;throughput" PROCESSORS 2
    ENVIRONMENT PYTHONDONTWRITEBYTECODE=1
    FIXTURES_REQUIRED slotCoater_parallel)

foreach(mode serial parallel)
    add_test(NAME case.slotCoater.inletBackflow.${mode}
        COMMAND ${slotCoaterDir}/runInletBackflowTest.sh ${mode}
                ${slotCoaterWork}/inletBackflow_${mode})
    set_tests_properties(case.slotCoater.inletBackflow.${mode} PROPERTIES
        TIMEOUT 300 LABELS "case;slotCoater;agglomeration"
        PASS_REGULAR_EXPRESSION "PASS")
endforeach()
set_tests_properties(case.slotCoater.inletBackflow.parallel PROPERTIES PROCESSORS 2)
