/*---------------------------------------------------------------------------*\
  colloidFoam: CFD-DEM for colloidal suspensions
\*---------------------------------------------------------------------------*/

#include "writeAsciiStl.H"
#include "OFstream.H"
#include "error.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::demWalls::writeAsciiStl
(
    const fileName& stlFile,
    const word& solidName,
    const UList<triPoints>& tris
)
{
    OFstream os(stlFile);
    if (!os.good())
    {
        FatalErrorInFunction
            << "Cannot open " << stlFile << " for writing"
            << exit(FatalError);
    }

    // Enough digits that micron-scale walls keep sub-nanometre detail
    os.precision(10);

    os  << "solid " << solidName.c_str() << '\n';

    for (const triPoints& tri : tris)
    {
        vector n = (tri[1] - tri[0]) ^ (tri[2] - tri[0]);
        n /= mag(n) + VSMALL;

        os  << "  facet normal "
            << n.x() << ' ' << n.y() << ' ' << n.z() << '\n'
            << "    outer loop\n";
        for (const point& p : tri)
        {
            os  << "      vertex "
                << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
        }
        os  << "    endloop\n"
            << "  endfacet\n";
    }

    os  << "endsolid " << solidName.c_str() << '\n';
}


// ************************************************************************* //
