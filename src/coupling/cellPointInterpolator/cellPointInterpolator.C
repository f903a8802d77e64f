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
    tetTri_(),
    faceStart_(mesh_.nCells() + 1, 0),
    faceRay_(),
    faceTetEnd_()
{
    const pointField& points = mesh_.points();
    const vectorField& C = mesh_.cellCentres();
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& Sf = mesh_.faceAreas();
    const cellList& cells = mesh_.cells();
    const labelList& own = mesh_.faceOwner();

    DynamicList<FixedList<label, 3>> tris(12*mesh_.nCells());
    DynamicList<vector> rays(6*mesh_.nCells());
    DynamicList<label> tetEnds(6*mesh_.nCells());
    for (label celli = 0; celli < mesh_.nCells(); ++celli)
    {
        tetStart_[celli] = tris.size();
        faceStart_[celli] = rays.size();
        for (const label facei : cells[celli])
        {
            for
            (
                const tetIndices& tetIs
              : polyMeshTetDecomposition::faceTetIndices(mesh_, facei, celli)
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
                    tris.append
                    (
                        FixedList<label, 3>({tri[0], tri[1], tri[2]})
                    );
                }
            }
            tetEnds.append(tris.size());

            // n/((Cf - C) . n), outward n: r . ray = 1 where the ray from
            // the centre along r meets the face's plane (0: the centre is
            // not inside the plane, the face is never tried first)
            const vector n = (own[facei] == celli ? 1 : -1)*Sf[facei];
            const scalar h = (Cf[facei] - C[celli]) & n;
            rays.append(h > 0 ? n/h : vector::zero);
        }
    }
    tetStart_[mesh_.nCells()] = tris.size();
    faceStart_[mesh_.nCells()] = rays.size();
    tetTri_.transfer(tris);
    faceRay_.transfer(rays);
    faceTetEnd_.transfer(tetEnds);
}


void Foam::cellPointInterpolator::update()
{
    pointField_ = volPointInterpolation::New(mesh_).interpolate(field_);
}


bool Foam::cellPointInterpolator::tetWeights
(
    const point& p,
    const label celli,
    FixedList<label, 3>& tri,
    FixedList<scalar, 4>& w
) const
{
    const pointField& points = mesh_.points();
    const point& cc = mesh_.cellCentres()[celli];
    const vector r = p - cc;

    // The face the ray from the centre through p meets first: in a cell
    // that is star-shaped from its centre, one of that face's tets holds
    // p, and it is tried first (a hex has 12 tets, 2 per face)
    const label f0 = faceStart_[celli];
    const label f1 = faceStart_[celli + 1];
    label firstFace = f0;
    scalar firstRay = -GREAT;
    for (label f = f0; f < f1; ++f)
    {
        const scalar s = r & faceRay_[f];
        if (s > firstRay)
        {
            firstRay = s;
            firstFace = f;
        }
    }
    const label firstTets =
        (firstFace == f0) ? tetStart_[celli] : faceTetEnd_[firstFace - 1];
    const label endTets = faceTetEnd_[firstFace];

    // The tet whose smallest barycentric coordinate is largest: the first
    // with none negative holds p; else the nearest (p on the cell boundary,
    // or outside it by round-off)
    scalar bestMin = -GREAT;
    label best = -1;

    const label nTets = tetStart_[celli + 1] - tetStart_[celli];
    const label nFirst = endTets - firstTets;
    for (label i = 0; i < nFirst + nTets; ++i)
    {
        // The first face's tets, then all of the cell's (those again)
        const label t =
            (i < nFirst) ? firstTets + i : tetStart_[celli] + i - nFirst;
        const FixedList<label, 3>& tt = tetTri_[t];
        const vector e1 = points[tt[0]] - cc;
        const vector e2 = points[tt[1]] - cc;
        const vector e3 = points[tt[2]] - cc;
        const scalar D = e1 & (e2 ^ e3);

        FixedList<scalar, 4> wt;
        wt[1] = (r & (e2 ^ e3))/D;
        wt[2] = (e1 & (r ^ e3))/D;
        wt[3] = (e1 & (e2 ^ r))/D;
        wt[0] = 1 - wt[1] - wt[2] - wt[3];

        const scalar wMin = min(min(wt[0], wt[1]), min(wt[2], wt[3]));
        if (wMin > bestMin)
        {
            bestMin = wMin;
            w = wt;
            best = t;
            if (wMin >= 0)
            {
                break;
            }
        }
    }

    if (best < 0)
    {
        return false;
    }
    tri = tetTri_[best];
    return true;
}


Foam::vector Foam::cellPointInterpolator::interpolate
(
    const point& p,
    const label celli
) const
{
    FixedList<label, 3> tri;
    FixedList<scalar, 4> w;
    if (!tetWeights(p, celli, tri, w))
    {
        // Every tet flat: a degenerate cell, fall back to its value
        return field_[celli];
    }
    return
        w[0]*field_[celli]
      + w[1]*pointField_[tri[0]]
      + w[2]*pointField_[tri[1]]
      + w[3]*pointField_[tri[2]];
}
