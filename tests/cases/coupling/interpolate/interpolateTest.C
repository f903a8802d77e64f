/*---------------------------------------------------------------------------*\
Application
    interpolateTest

Description
    Test of cellPointInterpolator against OpenFOAM's own cell-point
    interpolation (interpolationCellPoint: the same cell-centre + face-
    triangle tets, barycentric weights from tetrahedron, point values from
    the same volPointInterpolation): at n points, each in the cell that
    polyMesh::findCell returns, the two must agree to 1e-9 of the field's
    largest magnitude.  The field is smooth and far from linear (a linear
    field would hide a wrong tet: every tet of a cell gives the same value).

    The mesh must be of the order of a metre: v1912's tetrahedron returns
    the centroid for tets under SMALL = 1e-15 m^3 (the reason the project
    has its own interpolator), so the reference is exact only there.
    Exit status 1 on any mismatch or if fewer than half the points land
    inside the mesh.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "fvMesh.H"
#include "volFields.H"
#include "Random.H"
#include "interpolationCellPoint.H"
#include "cellPointInterpolator.H"

using namespace Foam;

namespace
{

// Smooth, non-linear test field on a domain of unit size [any unit]
vector testField(const point& x)
{
    return vector
    (
        Foam::sin(3*x.x())*sqr(x.y()) + x.z(),
        Foam::exp(x.y())*x.z() - sqr(x.x()),
        Foam::cos(2*x.z() + x.x())
    );
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addOption("n", "label", "number of points (default 100000)");

    #include "setRootCase.H"
    #include "createTime.H"
    fvMesh mesh
    (
        IOobject
        (
            fvMesh::defaultRegion, runTime.timeName(), runTime,
            IOobject::MUST_READ
        )
    );

    const label n = args.getOrDefault<label>("n", 100000);

    volVectorField U
    (
        IOobject("U", runTime.timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero),
        "calculated"
    );
    forAll(U, celli)
    {
        U[celli] = testField(mesh.C()[celli]);
    }
    forAll(U.boundaryField(), patchi)
    {
        fvPatchVectorField& pU = U.boundaryFieldRef()[patchi];
        forAll(pU, facei)
        {
            pU[facei] = testField(mesh.C().boundaryField()[patchi][facei]);
        }
    }

    const cellPointInterpolator ours(U);
    const interpolationCellPoint<vector> reference(U);

    const boundBox bb(mesh.points());
    const scalar scale = max(mag(U.primitiveField()));
    Random rnd(20261202);

    label nInside = 0;
    label nMismatch = 0;
    scalar maxDiff = 0;
    for (label i = 0; i < n; ++i)
    {
        const point q = bb.min() + cmptMultiply(rnd.sample01<vector>(), bb.span());
        const label celli = mesh.findCell(q);
        if (celli < 0)
        {
            continue;
        }
        ++nInside;

        const scalar diff =
            mag(ours.interpolate(q, celli) - reference.interpolate(q, celli))
           /scale;
        maxDiff = max(maxDiff, diff);
        if (diff > 1e-9)
        {
            ++nMismatch;
            if (nMismatch <= 10)
            {
                Info<< "mismatch at " << q << " in cell " << celli
                    << ": ours " << ours.interpolate(q, celli)
                    << ", interpolationCellPoint "
                    << reference.interpolate(q, celli) << endl;
            }
        }
    }

    const bool fewInside = 2*nInside < n;
    Info<< "points " << n << ", inside the mesh " << nInside
        << ", mismatches above 1e-9 " << nMismatch
        << ", largest difference " << maxDiff << " of max |U|" << nl
        << ((nMismatch || fewInside) ? "FAIL" : "PASS") << endl;

    // (argList's destructor ends the program with status 0: a failure
    // leaves through FatalError, status 1)
    if (nMismatch || fewInside)
    {
        FatalErrorInFunction << "interpolateTest failed" << exit(FatalError);
    }
    return 0;
}
