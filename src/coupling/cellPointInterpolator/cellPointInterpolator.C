#include "cellPointInterpolator.H"
#include "volPointInterpolation.H"
#include "polyMeshTetDecomposition.H"

namespace
{

// Six times the signed volume of the tet (cc, a, b, c) [m^3]; zero when the
// tet is flat relative to its own edge lengths (scale free)
Foam::scalar tetDeterminant
(
    const Foam::vector& e1,
    const Foam::vector& e2,
    const Foam::vector& e3
)
{
    const Foam::scalar D = e1 & (e2 ^ e3);
    const Foam::scalar scale = Foam::mag(e1)*Foam::mag(e2)*Foam::mag(e3);
    return (Foam::mag(D) <= 1e-12*scale) ? 0 : D;
}

} // End anonymous namespace


Foam::cellPointInterpolator::cellPointInterpolator
(
    const volVectorField& field
)
:
    mesh_(field.mesh()),
    field_(field),
    pointField_(volPointInterpolation::New(field.mesh()).interpolate(field)),
    tetStart_(mesh_.nCells() + 1, 0),
    tetTri_()
{
    const pointField& points = mesh_.points();
    const vectorField& C = mesh_.cellCentres();

    DynamicList<FixedList<label, 3>> tris(12*mesh_.nCells());
    for (label celli = 0; celli < mesh_.nCells(); ++celli)
    {
        tetStart_[celli] = tris.size();
        for
        (
            const tetIndices& tetIs
          : polyMeshTetDecomposition::cellTetIndices(mesh_, celli)
        )
        {
            const triFace tri = tetIs.faceTriIs(mesh_);
            const scalar D = tetDeterminant
            (
                points[tri[0]] - C[celli],
                points[tri[1]] - C[celli],
                points[tri[2]] - C[celli]
            );
            if (D != 0)
            {
                tris.append(FixedList<label, 3>({tri[0], tri[1], tri[2]}));
            }
        }
    }
    tetStart_[mesh_.nCells()] = tris.size();
    tetTri_.transfer(tris);
}


void Foam::cellPointInterpolator::update()
{
    pointField_ = volPointInterpolation::New(mesh_).interpolate(field_);
}


Foam::vector Foam::cellPointInterpolator::interpolate
(
    const point& p,
    const label celli
) const
{
    const pointField& points = mesh_.points();
    const point& cc = mesh_.cellCentres()[celli];
    const vector r = p - cc;

    // The tet whose smallest barycentric coordinate is largest: the first
    // with none negative holds p; else the nearest (p on the cell boundary,
    // or outside it by round-off)
    scalar bestMin = -GREAT;
    FixedList<scalar, 4> bestW(scalar(0));
    label best = -1;

    for (label t = tetStart_[celli]; t < tetStart_[celli + 1]; ++t)
    {
        const FixedList<label, 3>& tri = tetTri_[t];
        const vector e1 = points[tri[0]] - cc;
        const vector e2 = points[tri[1]] - cc;
        const vector e3 = points[tri[2]] - cc;
        const scalar D = e1 & (e2 ^ e3);

        FixedList<scalar, 4> w;
        w[1] = (r & (e2 ^ e3))/D;
        w[2] = (e1 & (r ^ e3))/D;
        w[3] = (e1 & (e2 ^ r))/D;
        w[0] = 1 - w[1] - w[2] - w[3];

        const scalar wMin = min(min(w[0], w[1]), min(w[2], w[3]));
        if (wMin > bestMin)
        {
            bestMin = wMin;
            bestW = w;
            best = t;
            if (wMin >= 0)
            {
                break;
            }
        }
    }

    if (best < 0)
    {
        // Every tet flat: a degenerate cell, fall back to its value
        return field_[celli];
    }

    const FixedList<label, 3>& tri = tetTri_[best];
    return
        bestW[0]*field_[celli]
      + bestW[1]*pointField_[tri[0]]
      + bestW[2]*pointField_[tri[1]]
      + bestW[3]*pointField_[tri[2]];
}
