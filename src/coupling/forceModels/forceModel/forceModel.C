#include "forceModel.H"
#include "HashSet.H"

namespace Foam
{
    defineTypeNameAndDebug(forceModel, 0);
    defineRunTimeSelectionTable(forceModel, dictionary);
}


Foam::PtrList<Foam::forceModel> Foam::forceModel::New(const dictionary& dict)
{
    const wordList names
    (
        dict.getOrDefault<wordList>("forceModels", wordList({"gravityBuoyancy"}))
    );

    PtrList<forceModel> models(names.size());
    wordHashSet seen;

    forAll(names, i)
    {
        const word& name = names[i];
        auto cstrIter = dictionaryConstructorTablePtr_->cfind(name);

        if (!cstrIter.found())
        {
            FatalIOErrorInFunction(dict)
                << "Unknown force model '" << name << "' (keyword"
                << " 'forceModels' in " << dict.name() << ")" << nl
                << "Valid force models: "
                << dictionaryConstructorTablePtr_->sortedToc()
                << exit(FatalIOError);
        }
        if (!seen.insert(name))
        {
            FatalIOErrorInFunction(dict)
                << "Force model '" << name << "' is listed twice (keyword"
                << " 'forceModels' in " << dict.name() << "): each force"
                << " is counted once" << exit(FatalIOError);
        }

        models.set(i, cstrIter()(dict.subOrEmptyDict(name + "Coeffs")));
    }

    Info<< "Force models: " << names << endl;

    return models;
}
