# Coupled solver colloidDEMFoam (src/coupling, applications/solvers/
# colloidDEMFoam; needs ./Allwmake).  Cases are built in the build tree at
# test time (only wmake's object folder of coupling/locate, Make/<platform>,
# lands in the source tree, as for every wmake target).
#
# settling.hex / .tet / .polyDual: one particle released in a prescribed
#   plane Poiseuille flow follows v(t) = (U_x(y_p), -v_s, 0)(1 - exp(-t/tau))
#   within 1 % at t = 1, 2, ... 11 relaxation times (closed form: checks
#   the interpolated U, the drag coefficient against the particle mass, and
#   gravity and buoyancy), on a blockMesh hex mesh, a tet mesh and a
#   polyhedral mesh (dual of the tet mesh) of the same channel;
#   settling.meshesAgree: tet and polyhedral runs within 1 % of the hex run.
# badInput.*: bad settings stop the solver with a message naming file and
#   keyword, a non-zero exit and nothing written.

set(couplingDir ${CMAKE_CURRENT_SOURCE_DIR}/coupling)
set(couplingWork ${CMAKE_CURRENT_BINARY_DIR}/coupling)

foreach(mesh hex tet polyDual)
    add_test(NAME case.coupling.settling.${mesh}
        COMMAND ${couplingDir}/runSettlingTest.sh ${mesh} ${couplingWork}/settling_${mesh})
    set_tests_properties(case.coupling.settling.${mesh} PROPERTIES
        TIMEOUT 120 LABELS "case;coupling" FIXTURES_SETUP couplingSettling_${mesh})
endforeach()

add_test(NAME case.coupling.settling.meshesAgree
    COMMAND python3 ${couplingDir}/compareRuns.py ${couplingWork}/settling_hex
            ${couplingWork}/settling_tet ${couplingWork}/settling_polyDual)
set_tests_properties(case.coupling.settling.meshesAgree PROPERTIES
    TIMEOUT 30 LABELS "case;coupling" ENVIRONMENT PYTHONDONTWRITEBYTECODE=1
    FIXTURES_REQUIRED "couplingSettling_hex;couplingSettling_tet;couplingSettling_polyDual")

foreach(variant missingKeyword negativeDiameter negativeDensity unknownDragModel
                inconsistentDeltaT demStepTooLong gravityInScript demScriptError
                resumeIncomplete misspeltKeyword misspeltTopKeyword
                diameterMismatch lostParticle particleOutsideBox
                coincidentParticles purgeWrite
                feedUnknownPatch feedSolidsFraction feedInterval feedNoInflow
                releaseBelowTouching releaseBeyondSkin)
    add_test(NAME case.coupling.badInput.${variant}
        COMMAND ${couplingDir}/runBadInputTest.sh ${variant} ${couplingWork}/badInput_${variant})
    set_tests_properties(case.coupling.badInput.${variant} PROPERTIES
        TIMEOUT 60 LABELS "case;coupling")
endforeach()
foreach(variant resumeIncomplete misspeltKeyword misspeltTopKeyword
                diameterMismatch lostParticle particleOutsideBox
                coincidentParticles purgeWrite)
    set_tests_properties(case.coupling.badInput.${variant} PROPERTIES
        LABELS "case;coupling;reliability")
endforeach()

# parallel: 2 ranks, fluid split in x (simple), LIGGGHTS split in y: the
#   particle crosses the fluid's processor boundary, stays located (at most
#   3 global searches), matches the closed form within 1 % and the serial
#   run within 1e-6.
add_test(NAME case.coupling.parallel
    COMMAND ${couplingDir}/runParallelTest.sh ${couplingWork}/parallel)
set_tests_properties(case.coupling.parallel PROPERTIES
    TIMEOUT 120 LABELS "case;coupling" PROCESSORS 2)

# insertedDrag.serial / .parallel: four particles inserted at rest by
#   insert/pack halfway through a coupling interval feel drag, gravity and
#   buoyancy from their first DEM step (the plugin's drag callback):
#   v_y within 0.1 % of the closed form from velocity Verlet's insertion
#   time (without the callback: 7.4 %), v_x within 1 %; parallel: 2 ranks,
#   the inserted particles on both DEM ranks, their fluid on one.
foreach(mode serial parallel)
    add_test(NAME case.coupling.insertedDrag.${mode}
        COMMAND ${couplingDir}/runInsertedDragTest.sh ${mode} ${couplingWork}/insertedDrag_${mode})
    set_tests_properties(case.coupling.insertedDrag.${mode} PROPERTIES
        TIMEOUT 120 LABELS "case;coupling;stiff")
endforeach()
set_tests_properties(case.coupling.insertedDrag.parallel PROPERTIES PROCESSORS 2)

# contactFlags: touchingParticle / touchingWall in the particle file match
#   the geometry of a hand-placed packing (gap < 1 % of the radius).
add_test(NAME case.coupling.contactFlags
    COMMAND ${couplingDir}/runContactFlagsTest.sh ${couplingWork}/contactFlags)
set_tests_properties(case.coupling.contactFlags PROPERTIES
    TIMEOUT 60 LABELS "case;coupling")

# interpolate: cellPointInterpolator (its tets listed once per cell, the
#   first tet holding the point taken) agrees with OpenFOAM's
#   interpolationCellPoint to 1e-9 at 10^5 random points of a non-linear
#   field on hex, tet and polyhedral meshes of 1 m (builds its small test
#   program with wmake).
add_test(NAME case.coupling.interpolate
    COMMAND ${couplingDir}/runMeshProgramTest.sh interpolate ${couplingWork}/interpolate)
set_tests_properties(case.coupling.interpolate PROPERTIES
    TIMEOUT 120 LABELS "case;coupling;throughput")

# locate: particleLocator (incremental walk + octree fallback) returns the
#   cell of OpenFOAM's global search for 10^5 points on the tet channel and
#   on a concave L-shaped mesh, as built and warped, and the wall distance
#   of a search over all wall faces (builds its small test program with
#   wmake).
add_test(NAME case.coupling.locate
    COMMAND ${couplingDir}/runMeshProgramTest.sh locate ${couplingWork}/locate)
set_tests_properties(case.coupling.locate PROPERTIES
    TIMEOUT 120 LABELS "case;coupling;throughput")
