#include "dragModel.H"

#include <stdexcept>

namespace Foam
{
    defineTypeNameAndDebug(dragModel, 0);
    defineRunTimeSelectionTable(dragModel, dictionary);
}


Foam::autoPtr<Foam::dragModel> Foam::dragModel::New(const dictionary& dict)
{
    if (!dict.found("dragModel"))
    {
        FatalIOErrorInFunction(dict)
            << "Missing keyword 'dragModel' in " << dict.name() << nl
            << "Valid drag models: "
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    const word modelType(dict.get<word>("dragModel"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown dragModel '" << modelType << "' (keyword 'dragModel'"
            << " in " << dict.name() << ")" << nl
            << "Valid drag models: "
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    Info<< "Drag model: " << modelType << endl;

    return cstrIter()(dict.subOrEmptyDict(modelType + "Coeffs"));
}
