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

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "Random.H"
#include "particleLocator.H"

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
    Info<< ((nMismatch || walksFailed) ? "FAIL" : "PASS") << endl;

    return (nMismatch || walksFailed) ? 1 : 0;
}
