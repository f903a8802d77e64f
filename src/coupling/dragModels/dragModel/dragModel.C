#include "dragModel.H"

#include <stdexcept>

namespace Foam
{
    defineTypeNameAndDebug(dragModel, 0);
    defineRunTimeSelectionTable(dragModel, dictionary);
}


Foam::dragModel::dragModel(const dictionary&, const scalar mu)
:
    mu_(mu)
{}


Foam::autoPtr<Foam::dragModel> Foam::dragModel::New
(
    const dictionary& dict,
    const scalar mu
)
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

    // Kernels of src/colloidModels check their parameters and throw
    try
    {
        return cstrIter()(dict, mu);
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(dict)
            << "dragModel '" << modelType << "' (" << dict.name() << "): "
            << e.what() << exit(FatalIOError);
    }
    return nullptr;
}
