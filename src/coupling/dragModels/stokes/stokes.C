#include "stokes.H"
#include "colloidModels/stokesDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(stokes, 0);
    addToRunTimeSelectionTable(dragModel, stokes, dictionary);
}
}


Foam::dragModels::stokes::stokes(const dictionary&)
{}


Foam::scalar Foam::dragModels::stokes::K(const particleContext& p) const
{
    // OpenFOAM v1912 compiles as C++11: no aggregate initialisation of a
    // struct with default member values
    colloid::StokesDragParameters law;
    law.viscosity = p.mu;
    return colloid::StokesDrag(law).coefficient(p.d);
}
