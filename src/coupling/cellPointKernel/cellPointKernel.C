#include "cellPointKernel.H"
#include "syncTools.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(cellPointKernel, 0);
    addToRunTimeSelectionTable(depositKernel, cellPointKernel, dictionary);
}


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::cellPointKernel::pointValues
(
    const Field<Type>& cellValues
) const
{
    const label nPoints = mesh_.nPoints();
    tmp<Field<Type>> tvalues(new Field<Type>(nPoints, Zero));
    Field<Type>& values = tvalues.ref();
    for (label pointi = 0; pointi < nPoints; ++pointi)
    {
        Type sum(Zero);
        for (label j = pointStart_[pointi]; j < pointStart_[pointi + 1]; ++j)
        {
            sum += pointWeight_[j]*cellValues[pointCell_[j]];
        }
        values[pointi] = sum;
    }
    // This rank's cells' part; the other copies' parts added
    syncTools::syncPointList(mesh_, values, plusEqOp<Type>(), Type(Zero));
    return tvalues;
}


template<class Type>
void Foam::cellPointKernel::spreadPointTotals
(
    Field<Type>& pointTotals,
    Field<Type>& cellValues
) const
{
    syncTools::syncPointList
    (
        mesh_, pointTotals, plusEqOp<Type>(), Type(Zero)
    );
    const label nPoints = mesh_.nPoints();
    for (label pointi = 0; pointi < nPoints; ++pointi)
    {
        const Type& total = pointTotals[pointi];
        for (label j = pointStart_[pointi]; j < pointStart_[pointi + 1]; ++j)
        {
            cellValues[pointCell_[j]] += pointWeight_[j]*total;
        }
    }
}


template<class Type>
void Foam::cellPointKernel::recordValues
(
    const Field<Type>& cellValues,
    Field<Type>& atRecords
) const
{
    const tmp<Field<Type>> tpv = pointValues(cellValues);
    const Field<Type>& pv = tpv();
    const label n = recordCell_.size();
    atRecords.setSize(n);
    for (label k = 0; k < n; ++k)
    {
        const FixedList<label, 3>& tri = recordTri_[k];
        const FixedList<scalar, 4>& w = recordWeights_[k];
        atRecords[k] = w[0]*cellValues[recordCell_[k]];
        if (tri[0] >= 0)
        {
            atRecords[k] +=
                w[1]*pv[tri[0]] + w[2]*pv[tri[1]] + w[3]*pv[tri[2]];
        }
    }
}


Foam::cellPointKernel::cellPointKernel
(
    const couplingProperties&,
    const fvMesh& mesh,
    const particleLocator&,
    const cellPointInterpolator& tets
)
:
    mesh_(mesh),
    tets_(tets),
    pointStart_(mesh.nPoints() + 1, 0)
{
    // Each cell around a point in proportion to its volume, normalised by
    // the sum over every copy of the point (other ranks, periodic images):
    // the weights of all cells around a point add up to 1 however the
    // mesh is decomposed, and what a point passes on raises the solid
    // fraction of its cells alike (inverse distances instead gave small
    // cells of a polyhedral mesh more solid than their volume: fluid
    // fraction -0.10 in the packed bed's polyDual test)
    const scalarField& V = mesh_.V();
    const labelListList& pointCells = mesh_.pointCells();
    forAll(pointCells, pointi)
    {
        pointStart_[pointi + 1] =
            pointStart_[pointi] + pointCells[pointi].size();
    }
    pointCell_.setSize(pointStart_.last());
    pointWeight_.setSize(pointStart_.last());
    scalarField total(mesh_.nPoints(), 0);
    forAll(pointCells, pointi)
    {
        label j = pointStart_[pointi];
        for (const label celli : pointCells[pointi])
        {
            pointCell_[j] = celli;
            pointWeight_[j] = V[celli];
            total[pointi] += V[celli];
            ++j;
        }
    }
    syncTools::syncPointList(mesh_, total, plusEqOp<scalar>(), scalar(0));
    forAll(pointCells, pointi)
    {
        for (label j = pointStart_[pointi]; j < pointStart_[pointi + 1]; ++j)
        {
            pointWeight_[j] /= total[pointi];
        }
    }
}


void Foam::cellPointKernel::depositShares
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
    const label n = x.size();
    recordCell_ = cell;
    recordTri_.setSize(n);
    recordWeights_.setSize(n);

    const label nPoints = mesh_.nPoints();
    scalarField pointVolume(nPoints, 0);
    scalarField pointDragCoeff(nPoints, 0);
    vectorField pointDragForce(nPoints, Zero);

    // The records come in the order of their cells (particleRecords): each
    // cell's tets are read once from memory (any order gives the same
    // shares, only slower)
    for (label k = 0; k < n; ++k)
    {
        const label celli = cell[k];
        FixedList<label, 3>& tri = recordTri_[k];
        FixedList<scalar, 4>& w = recordWeights_[k];
        if (tets_.tetWeights(x[k], celli, tri, w))
        {
            // A particle on its cell's boundary, or outside it by
            // round-off: negative weights set to 0 and the rest scaled to
            // add up to 1, so that every share stays non-negative
            scalar sum = 0;
            for (scalar& wi : w)
            {
                wi = max(wi, scalar(0));
                sum += wi;
            }
            for (scalar& wi : w)
            {
                wi /= sum;
            }
        }
        else
        {
            // A degenerate cell (every tet flat): all to the cell
            tri = FixedList<label, 3>(-1);
            w = FixedList<scalar, 4>({1, 0, 0, 0});
        }

        const scalar vol = 4.0/3.0*constant::mathematical::pi*pow3(r[k]);
        solidVolume[celli] += w[0]*vol;
        dragCoeff[celli] += w[0]*K[k];
        dragForce[celli] += w[0]*F[k];
        if (tri[0] >= 0)
        {
            for (label i = 0; i < 3; ++i)
            {
                const label pointi = tri[i];
                pointVolume[pointi] += w[i + 1]*vol;
                pointDragCoeff[pointi] += w[i + 1]*K[k];
                pointDragForce[pointi] += w[i + 1]*F[k];
            }
        }
    }

    spreadPointTotals(pointVolume, solidVolume);
    spreadPointTotals(pointDragCoeff, dragCoeff);
    spreadPointTotals(pointDragForce, dragForce);
}


void Foam::cellPointKernel::sampleFields
(
    const volScalarField& s,
    const UPtrList<const volVectorField>& v,
    scalarField& sAtRecords,
    List<vectorField>& vAtRecords
) const
{
    recordValues(s.primitiveField(), sAtRecords);
    vAtRecords.setSize(v.size());
    forAll(v, fieldi)
    {
        recordValues(v[fieldi].primitiveField(), vAtRecords[fieldi]);
    }
}
