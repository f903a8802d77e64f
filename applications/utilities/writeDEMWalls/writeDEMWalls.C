/*---------------------------------------------------------------------------*\
  colloidFoam: CFD-DEM for colloidal suspensions

Application
    writeDEMWalls

Group
    grpPreProcessingUtilities

Description
    Write boundary patches of the case's mesh as triangulated ASCII STL
    files in DEM length units, for LIGGGHTS' 'fix mesh/surface' (walls),
    'fix massflow/mesh' (removal planes: an outlet, an inlet).

    One file per patch, <dir>/<patch>.stl, normals out of the fluid.  Runs
    serial or on a decomposed case (-parallel): the master writes each file
    once from the faces of all ranks.

Usage
    \b writeDEMWalls [OPTION]

    Options:
      - \par -patches '(inlet "wall.*")'
        Patches to write (names or regular expressions).
        Default: every wall-type patch.

      - \par -walls
        With -patches: write every wall-type patch as well.

      - \par -scale \<factor\>
        DEM length units per metre (default 1e6, LIGGGHTS 'units micro').

      - \par -dir \<dir\>
        Output directory, relative to the case (default DEM/meshes).

      - \par -maxEdge \<length\>
        Longest triangle edge, in DEM length units: longer triangles are
        cut into four by their edge midpoints, as often as the longest
        edge of the patch needs (default: as triangulated).  A periodic
        LIGGGHTS box needs triangles no longer than its period.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "demWallExport.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Write boundary patches as ASCII STL surfaces in DEM length units"
    );
    argList::noFunctionObjects();
    argList::addOption
    (
        "patches",
        "wordRes",
        "Patches to write (names or regular expressions);"
        " default: every wall-type patch"
    );
    argList::addBoolOption
    (
        "walls",
        "With -patches: write every wall-type patch as well"
    );
    argList::addOption
    (
        "scale",
        "factor",
        "DEM length units per metre (default 1e6: LIGGGHTS units micro)"
    );
    argList::addOption
    (
        "dir",
        "dir",
        "Output directory, relative to the case (default DEM/meshes)"
    );

    argList::addOption
    (
        "maxEdge",
        "length",
        "Longest triangle edge in DEM length units (refine longer ones;"
        " a periodic LIGGGHTS box needs edges no longer than its period)"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    const scalar scale = args.getOrDefault<scalar>("scale", 1e6);
    fileName dir = args.getOrDefault<fileName>("dir", "DEM/meshes");
    if (!dir.isAbsolute())
    {
        dir = runTime.globalPath()/dir;
    }

    const scalar maxEdge = args.getOrDefault<scalar>("maxEdge", VGREAT);
    if (!(maxEdge > 0))
    {
        FatalErrorInFunction
            << "-maxEdge " << maxEdge
            << ": the longest triangle edge must be > 0 (DEM length units)"
            << exit(FatalError);
    }

    const demWallExport walls(mesh, scale, maxEdge);

    labelList patchIDs;
    if (args.found("patches"))
    {
        patchIDs = walls.patches(wordRes(args.getList<wordRe>("patches")));
        if (args.found("walls"))
        {
            for (const label patchi : walls.wallPatches())
            {
                if (!patchIDs.found(patchi))
                {
                    patchIDs.append(patchi);
                }
            }
        }
    }
    else
    {
        patchIDs = walls.wallPatches();
    }

    if (patchIDs.empty())
    {
        FatalErrorInFunction
            << "Nothing to write: the mesh has no wall-type patch and no"
            << " -patches were given" << nl
            << "Patches: " << mesh.boundaryMesh().names()
            << exit(FatalError);
    }

    Info<< "DEM length units per metre: " << scale << nl << endl;

    walls.write(patchIDs, dir);

    Info<< nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
