# Contacts and agglomerates during a coupled run (issue 12): the analysis
# of colloidDEMFoam (couplingProperties contactAnalysis) on a hand-built
# arrangement with clusters across the DEM's rank boundary and its
# periodic face, serial and 2 ranks (runArrangementTest.sh,
# checkArrangement.py): counts and sizes known by construction.
set(agglomerationDir ${CMAKE_CURRENT_SOURCE_DIR}/agglomeration)
set(agglomerationWork ${CMAKE_CURRENT_BINARY_DIR}/agglomeration)

foreach(mode serial parallel)
    add_test(NAME case.agglomeration.arrangement.${mode}
        COMMAND ${agglomerationDir}/runArrangementTest.sh ${mode} ${agglomerationWork}/arrangement_${mode})
    set_tests_properties(case.agglomeration.arrangement.${mode} PROPERTIES
        TIMEOUT 120 LABELS "case;agglomeration" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endforeach()
set_tests_properties(case.agglomeration.arrangement.parallel PROPERTIES PROCESSORS 2)

# agglomeration.slotCoaterSerialVsParallel: the slot-coater tutorial's
# contact analysis at test size (the fixtures of case.slotCoater.*): both
# runs write the time series and the plot, the fill has no contact, and
# serial and 2 ranks agree (compareSlotCoaterContacts.py).
add_test(NAME case.agglomeration.slotCoaterSerialVsParallel
    COMMAND python3 ${agglomerationDir}/compareSlotCoaterContacts.py
            ${CMAKE_CURRENT_BINARY_DIR}/slotCoater/serial ${CMAKE_CURRENT_BINARY_DIR}/slotCoater/parallel)
set_tests_properties(case.agglomeration.slotCoaterSerialVsParallel PROPERTIES
    TIMEOUT 30 LABELS "case;agglomeration;slotCoater" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1
    FIXTURES_REQUIRED "slotCoater_serial;slotCoater_parallel")

# agglomeration.shearCollisions: spheres (contact only) following a simple
# shear collide at Smoluchowski's rate (4/3) G (2a)^3 n^2/2, integrated
# over the band that holds them, within 3 Poisson standard deviations
# (runShearTest.sh, checkShearCollisions.py; about 1100 collisions).
add_test(NAME case.agglomeration.shearCollisions
    COMMAND ${agglomerationDir}/runShearTest.sh ${agglomerationWork}/shear)
set_tests_properties(case.agglomeration.shearCollisions PROPERTIES
    TIMEOUT 600 LABELS "case;agglomeration" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)

# agglomeration.brownian.serial / .parallel: Brownian motion in the coupled
# solver (couplingProperties brownian): 2000 free spheres against the
# Langevin mean square displacement (4 standard errors), and the 2-rank
# run's positions those of the serial run (runBrownianTest.sh,
# checkBrownian.py).
foreach(mode serial parallel)
    add_test(NAME case.agglomeration.brownian.${mode}
        COMMAND ${agglomerationDir}/runBrownianTest.sh ${mode} ${agglomerationWork}/brownian_${mode})
    set_tests_properties(case.agglomeration.brownian.${mode} PROPERTIES
        TIMEOUT 300 LABELS "case;agglomeration" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endforeach()
set_tests_properties(case.agglomeration.brownian.serial PROPERTIES FIXTURES_SETUP brownianSerial)
set_tests_properties(case.agglomeration.brownian.parallel PROPERTIES
    PROCESSORS 2 FIXTURES_REQUIRED brownianSerial)

# agglomeration.periodicCrossing.serial / .parallel: a touching pair
# carried over the DEM's periodic face (on 2 ranks also the ranks'
# boundary) keeps its one contact, never broken or formed again, and both
# particles keep moving with the flow (runPeriodicCrossingTest.sh,
# checkPeriodicCrossing.py).
foreach(mode serial parallel)
    add_test(NAME case.agglomeration.periodicCrossing.${mode}
        COMMAND ${agglomerationDir}/runPeriodicCrossingTest.sh ${mode} ${agglomerationWork}/periodicCrossing_${mode})
    set_tests_properties(case.agglomeration.periodicCrossing.${mode} PROPERTIES
        TIMEOUT 120 LABELS "case;agglomeration" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endforeach()
set_tests_properties(case.agglomeration.periodicCrossing.parallel PROPERTIES PROCESSORS 2)

# agglomeration.releaseGap: a pair contact across the DEM's ranks' boundary
# and a wall contact, their gaps wavering between 1 and 13 nm, last from the
# touching gap (5 nm) to the release gap (10 nm), each as long as the
# closed form within one analysis interval, both ranks counting the pair's
# contact and agglomerate while held (runReleaseGapTest.sh,
# checkReleaseGap.py).  releaseGapResumed: the same, stopped at 5 us, while
# both contacts are held (gap 7 nm), and resumed from that write.
foreach(mode serial parallel)
    add_test(NAME case.agglomeration.releaseGap.${mode}
        COMMAND ${agglomerationDir}/runReleaseGapTest.sh ${mode} ${agglomerationWork}/releaseGap_${mode})
    add_test(NAME case.agglomeration.releaseGapResumed.${mode}
        COMMAND ${agglomerationDir}/runReleaseGapTest.sh ${mode}
                ${agglomerationWork}/releaseGapResumed_${mode} 5e-06)
    set_tests_properties(case.agglomeration.releaseGap.${mode} case.agglomeration.releaseGapResumed.${mode}
        PROPERTIES TIMEOUT 120 LABELS "case;agglomeration" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endforeach()
set_tests_properties(case.agglomeration.releaseGap.parallel case.agglomeration.releaseGapResumed.parallel
    PROPERTIES PROCESSORS 2)

# agglomeration.slotCoaterPeriodicFill: the slot coater's DEM box is
# periodic in z, and its fill keeps fillMinimumGap between every two
# particles (across the periodic face too) and from the walls, with no
# empty band at the periodic face; its feed places no particle closer
# than the gap to another (the solver's "Inserted particles" line)
# (checkSlotCoaterFill.py, on the serial fixture of case.slotCoater).
add_test(NAME case.agglomeration.slotCoaterPeriodicFill
    COMMAND python3 ${agglomerationDir}/checkSlotCoaterFill.py ${CMAKE_CURRENT_BINARY_DIR}/slotCoater/serial)
set_tests_properties(case.agglomeration.slotCoaterPeriodicFill PROPERTIES
    TIMEOUT 60 LABELS "case;agglomeration;slotCoater" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1
    FIXTURES_REQUIRED slotCoater_serial)

# agglomeration.barrier: colloidBarrier (the DLVO barrier, the salt and the
# zeta potential at which it vanishes; Fuchs' stability ratio and the
# Brownian collision rate with the DEM's lubrication) against the closed
# forms of the model (checkBarrier.py)
add_test(NAME case.agglomeration.barrier
    COMMAND python3 ${agglomerationDir}/checkBarrier.py $<TARGET_FILE:colloidBarrier>)
set_tests_properties(case.agglomeration.barrier PROPERTIES
    TIMEOUT 60 LABELS "case;agglomeration" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1
    PASS_REGULAR_EXPRESSION "PASS")

# The study report's parts on hand-built input (Debian's python3: numpy
# and matplotlib): agglomeration.<name>, <script> colloidFoamDir workDir,
# passing on "PASS"
function(add_study_report_test name script timeout)
    add_test(NAME agglomeration.${name}
        COMMAND /usr/bin/python3 ${agglomerationDir}/${script} ${CMAKE_SOURCE_DIR}
                ${agglomerationWork}/${name})
    set_tests_properties(agglomeration.${name} PROPERTIES
        TIMEOUT ${timeout} LABELS "unit;agglomeration" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1
        PASS_REGULAR_EXPRESSION "PASS")
endfunction()

# agglomeration.studyWhere: where the study's report finds agglomerates,
# on a hand-built cloud (testStudyWhere.py): members across the periodic
# span, the touching gap, centres and the parts of the die, the pairs held
# near contact and their counts kept in the case
add_study_report_test(studyWhere testStudyWhere.py 30)

# agglomeration.pairGaps: the close pairs of a cloud that the study's
# report counts (src/python/pairGaps.py, a grid of cells with the periodic
# span) against all pairs checked one by one (testPairGaps.py; its work
# folder is not used)
add_study_report_test(pairGaps testPairGaps.py 60)

# agglomeration.studyVariants: the study report's comparison of a case with
# its numerical variant (results/variants.md) on hand-built study folders
# (testStudyVariants.py, figures by hand)
add_study_report_test(studyVariants testStudyVariants.py 30)

# agglomeration.studyMilestones: the study report's contacts and
# agglomerates at the seeds' times and on to the residence time
# (results/milestones.md; a resumed analysis, times with round-off) and
# its agglomerates by part of the die and size (where.md's first table),
# on hand-built input (testStudyMilestones.py, figures by hand)
add_study_report_test(studyMilestones testStudyMilestones.py 30)

# agglomeration.studyCost: the run time and rate the study's report gives
# a resumed run: its parts' logs summed (testStudyCost.py, figures by hand)
add_study_report_test(studyCost testStudyCost.py 30)

# agglomeration.study: the study's driver on a copy of the slot coater (one
# case, two coupling steps at the study's size, and its variants, one
# coupling step each: SoftContacts, ShortRange, TwoSphere, Explicit) and
# its report (runStudyTest.sh); about 4 minutes on 2 cores
add_test(NAME case.agglomeration.study
    COMMAND ${agglomerationDir}/runStudyTest.sh ${agglomerationWork}/study)
set_tests_properties(case.agglomeration.study PROPERTIES
    TIMEOUT 600 LABELS "case;agglomeration" PASS_REGULAR_EXPRESSION "PASS")

# agglomeration.feed.serial / .parallel: the coupling's feed (particleFeed)
# through the inlet of the channel in plane Poiseuille flow: every
# insertion's count (closed form of the inflow), the flux profile across
# the inlet (chi-square), the placement in the region the liquid swept
# (entry times uniform: Kolmogorov-Smirnov), the gaps to particles and
# walls (runFeedTest.sh, checkFeed.py); .plug: the same in plug flow with
# the walls moving along (inflow up to the walls: the gap to the walls
# tested); .serialVsParallel: both runs hold the same particles, ids and
# positions (the fluid split across the inlet on 2 ranks).
foreach(mode serial parallel plug)
    add_test(NAME case.agglomeration.feed.${mode}
        COMMAND ${agglomerationDir}/runFeedTest.sh ${mode} ${agglomerationWork}/feed_${mode})
    set_tests_properties(case.agglomeration.feed.${mode} PROPERTIES
        TIMEOUT 120 LABELS "case;agglomeration" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1
        FIXTURES_SETUP feed_${mode})
endforeach()
set_tests_properties(case.agglomeration.feed.parallel PROPERTIES PROCESSORS 2)
add_test(NAME case.agglomeration.feed.serialVsParallel
    COMMAND python3 ${agglomerationDir}/checkFeed.py
            ${agglomerationWork}/feed_serial ${agglomerationWork}/feed_parallel)
set_tests_properties(case.agglomeration.feed.serialVsParallel PROPERTIES
    TIMEOUT 30 LABELS "case;agglomeration" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1
    FIXTURES_REQUIRED "feed_serial;feed_parallel")
