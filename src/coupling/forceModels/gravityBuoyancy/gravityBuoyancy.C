#include "gravityBuoyancy.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace forceModels
{
    defineTypeNameAndDebug(gravityBuoyancy, 0);
    addToRunTimeSelectionTable(forceModel, gravityBuoyancy, dictionary);
}
}
