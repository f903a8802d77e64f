/*---------------------------------------------------------------------------*\
  colloidFoam
\*---------------------------------------------------------------------------*/

#include "contactCellFields.H"
#include "volFields.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// A number density field [1/m^3] from counts per cell
bool writeDensity
(
    const Foam::fvMesh& mesh,
    const Foam::word& name,
    const Foam::scalarField& countPerCell
)
{
    using namespace Foam;

    volScalarField density
    (
        IOobject
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh,
        dimensionedScalar(dimless/dimVolume, Zero),
        zeroGradientFvPatchScalarField::typeName
    );
    density.primitiveFieldRef() = countPerCell/mesh.V();
    density.correctBoundaryConditions();
    return density.write();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * //

bool Foam::writeContactCellFields
(
    const fvMesh& mesh,
    const labelUList& cell,
    const labelUList& nContacts,
    const labelUList& touchingWall,
    const labelUList& agglomerateSize,
    const bool withAgglomerates
)
{
    scalarField particles(mesh.nCells(), Zero);
    scalarField pairContacts(mesh.nCells(), Zero);
    scalarField wallContacts(mesh.nCells(), Zero);
    scalarField agglomerated(mesh.nCells(), Zero);

    forAll(cell, k)
    {
        const label celli = cell[k];
        particles[celli] += 1;
        // A contact has two particles: half of it in each one's cell
        pairContacts[celli] += 0.5*nContacts[k];
        wallContacts[celli] += touchingWall[k];
        if (agglomerateSize[k] > 1)
        {
            agglomerated[celli] += 1;
        }
    }

    bool ok = writeDensity(mesh, "particleNumberDensity", particles);
    ok = writeDensity(mesh, "pairContactDensity", pairContacts) && ok;
    ok = writeDensity(mesh, "wallContactDensity", wallContacts) && ok;
    if (withAgglomerates)
    {
        ok = writeDensity(mesh, "agglomeratedNumberDensity", agglomerated) && ok;
    }
    return ok;
}


// ************************************************************************* //
