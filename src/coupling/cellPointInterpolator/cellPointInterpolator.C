#include "cellPointInterpolator.H"
#include "volPointInterpolation.H"
#include "polyMeshTetDecomposition.H"

Foam::cellPointInterpolator::cellPointInterpolator
(
    const volVectorField& field
)
:
    mesh_(field.mesh()),
    field_(field),
    pointField_(volPointInterpolation::New(field.mesh()).interpolate(field))
{}


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
    const List<tetIndices> tets =
        polyMeshTetDecomposition::cellTetIndices(mesh_, celli);

    const pointField& points = mesh_.points();
    const point& cc = mesh_.cellCentres()[celli];

    // The tet whose smallest barycentric coordinate is largest contains p
    // (or is nearest to it when p sits on the cell boundary)
    scalar bestMin = -GREAT;
    FixedList<scalar, 4> bestW(scalar(0));
    triFace bestTri;

    for (const tetIndices& tetIs : tets)
    {
        const triFace tri = tetIs.faceTriIs(mesh_);
        const vector e1 = points[tri[0]] - cc;
        const vector e2 = points[tri[1]] - cc;
        const vector e3 = points[tri[2]] - cc;
        const vector r = p - cc;

        // Six times the signed volume; skip tets that are flat relative
        // to their own edge lengths (scale free)
        const scalar D = e1 & (e2 ^ e3);
        const scalar scale = mag(e1)*mag(e2)*mag(e3);
        if (mag(D) <= 1e-12*scale)
        {
            continue;
        }

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
            bestTri = tri;
        }
    }

    if (bestMin == -GREAT)
    {
        // Every tet flat: a degenerate cell, fall back to its value
        return field_[celli];
    }

    return
        bestW[0]*field_[celli]
      + bestW[1]*pointField_[bestTri[0]]
      + bestW[2]*pointField_[bestTri[1]]
      + bestW[3]*pointField_[bestTri[2]];
}
