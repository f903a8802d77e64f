#include "stokes.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(stokes, 0);
    addToRunTimeSelectionTable(dragModel, stokes, dictionary);
}
}


namespace
{
    // OpenFOAM v1912 compiles as C++11: no aggregate initialisation of a
    // struct with default member values
    colloid::StokesDragParameters lawParameters(const Foam::scalar mu)
    {
        colloid::StokesDragParameters p;
        p.viscosity = mu;
        return p;
    }
}


Foam::dragModels::stokes::stokes(const dictionary& dict, const scalar mu)
:
    dragModel(dict, mu),
    law_(lawParameters(mu))
{}


Foam::scalar Foam::dragModels::stokes::K(const scalar d, const scalar) const
{
    return law_.coefficient(d);
}
