/*---------------------------------------------------------------------------*\
  colloidFoam: CFD-DEM for colloidal suspensions
\*---------------------------------------------------------------------------*/

#include "demWallExport.H"
#include "patchTriangulation.H"
#include "triangleRefinement.H"
#include "writeAsciiStl.H"
#include "wallPolyPatch.H"
#include "Pstream.H"
#include "OSspecific.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demWallExport::demWallExport
(
    const polyMesh& mesh,
    const scalar scale,
    const scalar maxEdge
)
:
    mesh_(mesh),
    scale_(scale),
    maxEdge_(maxEdge)
{
    if (!(maxEdge_ > 0))
    {
        FatalErrorInFunction
            << "Longest DEM triangle edge " << maxEdge_
            << " (DEM length units) must be > 0"
            << exit(FatalError);
    }
    if (!(scale_ > 0))
    {
        FatalErrorInFunction
            << "DEM length scale " << scale_
            << " (DEM length units per metre) must be > 0;"
            << " LIGGGHTS 'units micro' needs 1e6"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::demWallExport::wallPatches() const
{
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();

    DynamicList<label> ids(pbm.size());
    forAll(pbm, patchi)
    {
        if (isA<wallPolyPatch>(pbm[patchi]))
        {
            ids.append(patchi);
        }
    }
    return labelList(std::move(ids));
}


Foam::labelList Foam::demWallExport::patches(const wordRes& selection) const
{
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();

    DynamicList<label> ids(pbm.size());
    for (const wordRe& key : selection)
    {
        bool found = false;
        forAll(pbm, patchi)
        {
            if (key.match(pbm[patchi].name()))
            {
                found = true;
                if (!ids.found(patchi))
                {
                    ids.append(patchi);
                }
            }
        }

        if (!found)
        {
            FatalErrorInFunction
                << "No patch matches " << key << " in mesh "
                << mesh_.objectPath() << nl
                << "Patches: " << pbm.names()
                << exit(FatalError);
        }
    }
    return labelList(std::move(ids));
}


Foam::List<Foam::triPoints>
Foam::demWallExport::triangles(const label patchi) const
{
    return demWalls::triangulatePatch(mesh_.boundaryMesh()[patchi], scale_);
}


Foam::fileName Foam::demWallExport::write
(
    const label patchi,
    const fileName& dir
) const
{
    const word& name = mesh_.boundaryMesh()[patchi].name();

    // Each rank's share, gathered on the master (walls are small: one
    // layer of boundary faces, so gathering them costs little)
    List<List<triPoints>> shares(Pstream::nProcs());
    shares[Pstream::myProcNo()] = triangles(patchi);
    Pstream::gatherList(shares);

    label nTris = 0;
    if (Pstream::master())
    {
        for (const List<triPoints>& share : shares)
        {
            nTris += share.size();
        }
    }
    Pstream::scatter(nTris);

    if (nTris == 0)
    {
        WarningInFunction
            << "Patch " << name << " has no faces; no DEM surface written"
            << endl;
        return fileName::null;
    }

    const fileName stlFile(dir/name + ".stl");

    if (Pstream::master())
    {
        if (!isDir(dir) && !mkDir(dir))
        {
            FatalErrorInFunction
                << "Cannot create directory " << dir
                << " for the DEM wall files"
                << exit(FatalError);
        }

        List<triPoints> all(nTris);
        label n = 0;
        for (const List<triPoints>& share : shares)
        {
            for (const triPoints& tri : share)
            {
                all[n++] = tri;
            }
        }

        // Refined once all ranks' triangles are together: the same levels
        // for the whole patch keep it conforming
        const label levels = demWalls::refinementLevels(all, maxEdge_);
        if (levels)
        {
            all = demWalls::refineTriangles(all, levels);
        }

        Info<< "DEM surface " << name << ": " << all.size() << " triangles";
        if (levels)
        {
            Info<< " (" << nTris << " refined " << levels
                << " times: no edge longer than " << maxEdge_ << ')';
        }
        Info<< " -> " << stlFile << endl;

        demWalls::writeAsciiStl(stlFile, name, all);
    }

    return stlFile;
}


Foam::fileNameList Foam::demWallExport::write
(
    const labelUList& patchIDs,
    const fileName& dir
) const
{
    DynamicList<fileName> files(patchIDs.size());
    for (const label patchi : patchIDs)
    {
        const fileName stlFile(write(patchi, dir));
        if (!stlFile.empty())
        {
            files.append(stlFile);
        }
    }
    return fileNameList(std::move(files));
}


// ************************************************************************* //
