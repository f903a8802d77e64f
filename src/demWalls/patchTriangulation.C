/*---------------------------------------------------------------------------*\
  colloidFoam: CFD-DEM for colloidal suspensions
\*---------------------------------------------------------------------------*/

#include "patchTriangulation.H"
#include "DynamicList.H"
#include "SubField.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::List<Foam::triPoints> Foam::demWalls::triangulatePatch
(
    const polyPatch& patch,
    const scalar scale
)
{
    const pointField& points = patch.points();
    const pointField::subField centres(patch.faceCentres());

    DynamicList<triPoints> tris(2*patch.size());

    forAll(patch, facei)
    {
        const face& f = patch[facei];
        const label n = f.size();

        if (n == 3)
        {
            tris.append(triPoints(points[f[0]], points[f[1]], points[f[2]]));
        }
        else if (n == 4)
        {
            const point& a = points[f[0]];
            const point& b = points[f[1]];
            const point& c = points[f[2]];
            const point& d = points[f[3]];

            if (magSqr(c - a) <= magSqr(d - b))
            {
                tris.append(triPoints(a, b, c));
                tris.append(triPoints(a, c, d));
            }
            else
            {
                tris.append(triPoints(b, c, d));
                tris.append(triPoints(b, d, a));
            }
        }
        else
        {
            const point& centre = centres[facei];
            for (label i = 0; i < n; ++i)
            {
                tris.append
                (
                    triPoints(centre, points[f[i]], points[f.nextLabel(i)])
                );
            }
        }
    }

    for (triPoints& tri : tris)
    {
        for (point& p : tri)
        {
            p *= scale;
        }
    }

    return List<triPoints>(std::move(tris));
}


// ************************************************************************* //
