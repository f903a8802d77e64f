#include "pressureGradient.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace forceModels
{
    defineTypeNameAndDebug(pressureGradient, 0);
    addToRunTimeSelectionTable(forceModel, pressureGradient, dictionary);
}
}
