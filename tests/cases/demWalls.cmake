# DEM wall export (src/demWalls, writeDEMWalls): the walls of a blockMesh box
# exported as STL must enclose the box's exact area and volume with normals
# out of the fluid; serial, 2 ranks (gathered on the master) and on the
# polyhedral dual mesh (polygonal faces), and refined to a longest edge
# (-maxEdge; a bad value refused).  Needs writeDEMWalls built
# (./Allwmake).  Cases run in the build tree.

foreach(mode serial parallel polyDual refined)
    add_test(NAME case.demWalls.${mode}
        COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/demWalls/runDemWallsTest.sh
                ${mode} ${CMAKE_CURRENT_BINARY_DIR}/demWalls/${mode})
    set_tests_properties(case.demWalls.${mode} PROPERTIES TIMEOUT 120 LABELS "case;demWalls")
endforeach()
