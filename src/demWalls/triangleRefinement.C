/*---------------------------------------------------------------------------*\
  colloidFoam: CFD-DEM for colloidal suspensions
\*---------------------------------------------------------------------------*/

#include "triangleRefinement.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

Foam::label Foam::demWalls::refinementLevels
(
    const UList<triPoints>& tris,
    const scalar maxEdge
)
{
    scalar longest = 0;
    for (const triPoints& tri : tris)
    {
        for (label e = 0; e < 3; ++e)
        {
            longest = max(longest, mag(tri[(e + 1) % 3] - tri[e]));
        }
    }

    // Each level halves every edge
    label levels = 0;
    while (longest > maxEdge)
    {
        longest *= 0.5;
        ++levels;
    }
    return levels;
}


Foam::List<Foam::triPoints> Foam::demWalls::refineTriangles
(
    const UList<triPoints>& tris,
    const label levels
)
{
    List<triPoints> current(tris);

    for (label level = 0; level < levels; ++level)
    {
        List<triPoints> finer(4*current.size());
        label n = 0;
        for (const triPoints& t : current)
        {
            const point ab(0.5*(t[0] + t[1]));
            const point bc(0.5*(t[1] + t[2]));
            const point ca(0.5*(t[2] + t[0]));

            // Three corner triangles and the middle one, all wound as t
            finer[n++] = triPoints(t[0], ab, ca);
            finer[n++] = triPoints(ab, t[1], bc);
            finer[n++] = triPoints(ca, bc, t[2]);
            finer[n++] = triPoints(ab, bc, ca);
        }
        current.transfer(finer);
    }

    return current;
}


// ************************************************************************* //
