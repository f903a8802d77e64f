#include "particleVTKWriter.H"
#include "OFstream.H"
#include "OSspecific.H"

void Foam::particleVTKWriter::write
(
    const fileName& file,
    const string& title,
    const pointField& position,
    const vectorField& velocity,
    const scalarField& radius,
    const labelList& touchingParticle,
    const labelList& touchingWall
)
{
    mkDir(file.path());
    OFstream os(file);
    os.precision(10);

    const label n = position.size();

    os  << "# vtk DataFile Version 3.0" << nl
        << title.c_str() << nl
        << "ASCII" << nl
        << "DATASET POLYDATA" << nl
        << "POINTS " << n << " double" << nl;
    for (const point& p : position)
    {
        os  << p.x() << ' ' << p.y() << ' ' << p.z() << nl;
    }

    os  << "VERTICES " << n << ' ' << 2*n << nl;
    for (label i = 0; i < n; ++i)
    {
        os  << "1 " << i << nl;
    }

    os  << "POINT_DATA " << n << nl
        << "VECTORS velocity double" << nl;
    for (const vector& v : velocity)
    {
        os  << v.x() << ' ' << v.y() << ' ' << v.z() << nl;
    }

    os  << "SCALARS radius double 1" << nl
        << "LOOKUP_TABLE default" << nl;
    for (const scalar r : radius)
    {
        os  << r << nl;
    }

    os  << "SCALARS touchingParticle int 1" << nl
        << "LOOKUP_TABLE default" << nl;
    for (const label f : touchingParticle)
    {
        os  << f << nl;
    }

    os  << "SCALARS touchingWall int 1" << nl
        << "LOOKUP_TABLE default" << nl;
    for (const label f : touchingWall)
    {
        os  << f << nl;
    }
}
