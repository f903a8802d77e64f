#include "viscousStress.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace forceModels
{
    defineTypeNameAndDebug(viscousStress, 0);
    addToRunTimeSelectionTable(forceModel, viscousStress, dictionary);
}
}
