#include "denseDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace dragModels
{
    defineTemplateTypeNameAndDebugWithName(gidaspow, "gidaspow", 0);
    defineTemplateTypeNameAndDebugWithName(diFelice, "diFelice", 0);
    defineTemplateTypeNameAndDebugWithName(beetstra, "beetstra", 0);

    addToRunTimeSelectionTable(dragModel, gidaspow, dictionary);
    addToRunTimeSelectionTable(dragModel, diFelice, dictionary);
    addToRunTimeSelectionTable(dragModel, beetstra, dictionary);
}
}
