#include "depositKernel.H"
#include "couplingProperties.H"
#include "mathematicalConstants.H"

namespace Foam
{
    defineTypeNameAndDebug(depositKernel, 0);
    defineRunTimeSelectionTable(depositKernel, dictionary);
}


Foam::autoPtr<Foam::depositKernel> Foam::depositKernel::New
(
    const couplingProperties& props,
    const fvMesh& mesh,
    const particleLocator& locator,
    const cellPointInterpolator& tets
)
{
    const word& kernel = props.kernel();
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(kernel);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(props)
            << "Keyword 'kernel' in " << props.objectPath()
            << "::twoWay is '" << kernel << "'; allowed: "
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }
    return cstrIter()(props, mesh, locator, tets);
}


void Foam::depositKernel::deposit
(
    const pointField& x,
    const labelList& cell,
    const scalarField& r,
    const scalarField& K,
    const vectorField& F,
    scalarField& solidVolume,
    scalarField& dragCoeff,
    vectorField& dragForce
)
{
    scalarField before;
    if (debug)
    {
        before = solidVolume;
    }

    depositShares(x, cell, r, K, F, solidVolume, dragCoeff, dragForce);

    if (debug)
    {
        recordVolume_ = 4.0/3.0*constant::mathematical::pi*pow3(r);
        cellSolid_ = solidVolume - before;
    }
}


void Foam::depositKernel::sample
(
    const volScalarField& s,
    const UPtrList<const volVectorField>& v,
    scalarField& sAtRecords,
    List<vectorField>& vAtRecords
) const
{
    sampleFields(s, v, sAtRecords, vAtRecords);

    if (debug)
    {
        // The transpose: sum_k V_k s(x_k) = sum_c s_c (solid volume
        // deposited in c) for any cell field s
        const scalar onParticles = gSum(recordVolume_*sAtRecords);
        const scalar onCells = gSum(cellSolid_*s.primitiveField());
        Info<< "depositKernel: transpose check: particles "
            << onParticles << ", cells " << onCells
            << " (relative difference "
            << mag(onParticles - onCells)/max(mag(onCells), VSMALL) << ")"
            << endl;
    }
}
