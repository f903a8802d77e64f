/*---------------------------------------------------------------------------*\
Application
    locateTest

Description
    Test of particleLocator: n points visited as a particle would (mostly
    steps of up to one cell from the previous point, with the previous cell
    as hint; one in ten a jump anywhere in the bounding box) must each land
    in the cell OpenFOAM's own global search (polyMesh::findCell, octree
    over the cells' tets) returns, -1 included for points outside the
    mesh.  Exit status 1 on any mismatch.

    With -convex (a convex domain) the incremental walk must also succeed
    for every point inside the mesh: the locator's octree searches must be
    exactly the points outside.

    Wall distances: at every 10th point inside, for ranges of 0.3, 0.05,
    0.4 and 1.5 cells (in that order: the locator keeps per cell the wall
    faces for the longest range asked so far, and must find more when a
    longer one is asked), particleLocator::wallDistance must equal the distance
    to the nearest face of the wall patches found by going over all of
    them (face::nearestPoint), to 1e-9 of a cell, or say "none within the
    range" exactly when that distance exceeds the range (points within
    1e-9 of a cell of the range itself are not counted: either answer is
    right there).

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "Random.H"
#include "particleLocator.H"
#include "wallPolyPatch.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addOption("n", "label", "number of points (default 100000)");
    argList::addBoolOption("convex", "the domain is convex: walks must not fail");

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    const label n = args.getOrDefault<label>("n", 100000);

    particleLocator locator(mesh);
    Random rnd(20261125);

    const boundBox bb(mesh.points());
    const scalar h = Foam::cbrt(bb.volume()/mesh.nCells());

    // Every wall face, for the reference distances
    DynamicList<label> wallFaces;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<wallPolyPatch>(pp))
        {
            forAll(pp, i)
            {
                wallFaces.append(pp.start() + i);
            }
        }
    }
    label nWallChecks = 0;
    label nWallNear = 0;
    label nWallMismatch = 0;

    point p = mesh.cellCentres()[0];
    label hint = 0;
    label nInside = 0;
    label nMismatch = 0;

    for (label i = 0; i < n; ++i)
    {
        point q;
        if (rnd.sample01<scalar>() < 0.9)
        {
            q = p + 2*h*(rnd.sample01<vector>() - vector::uniform(0.5));
        }
        else
        {
            q = bb.min() + cmptMultiply(rnd.sample01<vector>(), bb.span());
        }

        const label expected = mesh.findCell(q);
        const label found = locator.findCell(q, hint);

        if (found != expected)
        {
            ++nMismatch;
            if (nMismatch <= 10)
            {
                Info<< "mismatch at " << q << ": found " << found
                    << ", global search " << expected << endl;
            }
        }
        if (expected >= 0 && found == expected && i % 10 == 0)
        {
            scalar nearest = GREAT;
            for (const label facei : wallFaces)
            {
                nearest = min
                (
                    nearest,
                    mesh.faces()[facei].nearestPoint(q, mesh.points()).distance()
                );
            }
            for (const scalar range : {0.3*h, 0.05*h, 0.4*h, 1.5*h})
            {
                if (mag(nearest - range) < 1e-9*h)
                {
                    continue;
                }
                ++nWallChecks;
                const scalar reference = nearest <= range ? nearest : GREAT;
                nWallNear += nearest <= range;
                const scalar d = locator.wallDistance(q, found, range);
                if (mag(d - reference) > 1e-9*h)
                {
                    ++nWallMismatch;
                    if (nWallMismatch <= 10)
                    {
                        Info<< "wall distance at " << q << " within "
                            << range << ": " << d << ", over all wall faces "
                            << reference << endl;
                    }
                }
            }
        }
        if (expected >= 0)
        {
            ++nInside;
            p = q;
            hint = found;
        }
    }

    const label nOctree = locator.nGlobalSearches();
    const bool walksFailed = args.found("convex") && nOctree != n - nInside;

    Info<< "points " << n << ", inside the mesh " << nInside
        << ", octree searches by the locator " << nOctree
        << ", mismatches " << nMismatch << nl;
    if (walksFailed)
    {
        Info<< "walks gave up " << nOctree - (n - nInside)
            << " times in a convex domain" << nl;
    }
    Info<< "wall distances checked " << nWallChecks << " (" << nWallNear
        << " within the range), mismatches " << nWallMismatch << nl;
    // the check must have seen both answers
    const bool wallUntested =
        wallFaces.empty() || nWallNear == 0 || nWallNear == nWallChecks;
    if (wallUntested)
    {
        Info<< "the wall distances were not tested: " << wallFaces.size()
            << " wall faces, " << nWallNear << " of " << nWallChecks
            << " checks near a wall" << nl;
    }
    const bool failed =
        nMismatch || walksFailed || nWallMismatch || wallUntested;
    Info<< (failed ? "FAIL" : "PASS") << endl;

    // (argList's destructor ends the program with status 0: a failure
    // leaves through FatalError, status 1)
    if (failed)
    {
        FatalErrorInFunction << "locateTest failed" << exit(FatalError);
    }
    return 0;
}
