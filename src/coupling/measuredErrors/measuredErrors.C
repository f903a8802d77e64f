#include "measuredErrors.H"
#include "IFstream.H"
#include "HashPtrTable.H"
#include "OSspecific.H"
#include <cstdio>

namespace Foam
{

// Three significant digits: a measured error is not known better
static word sig3(const scalar x)
{
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.3g", x);
    return word(buf, false);
}


// The number an entry of a case's dictionary holds, or false if it holds
// none (missing file or entry, a word, a sub-dictionary)
static bool caseNumber
(
    const fileName& caseDir,
    const fileName& file,
    const word& entryPath,
    HashPtrTable<dictionary, fileName>& files,
    scalar& value
)
{
    if (!files.found(file))
    {
        const fileName path(caseDir/file);
        files.set
        (
            file,
            isFile(path) ? new dictionary(IFstream(path)()) : nullptr
        );
    }
    const dictionary* dict = files[file];
    if (!dict)
    {
        return false;
    }
    // '/' scoping, e.g. DEM/timeStep or SIMPLE/residualControl/p
    const entry* e = dict->findScoped(entryPath, keyType::LITERAL);
    if (!e || e->isDict())
    {
        return false;
    }
    ITstream& is = e->stream();
    if (is.size() != 1 || !is[0].isNumber())
    {
        return false;
    }
    value = is[0].number();
    return true;
}


// Whether every entry a rung set holds the rung's number in this case
static bool caseIsRung
(
    const fileName& caseDir,
    const dictionary& rungSet,
    HashPtrTable<dictionary, fileName>& files
)
{
    for (const entry& e : rungSet)
    {
        const dictionary& s = e.dict();
        const scalar wanted = s.get<scalar>("value");
        scalar value = 0;
        if
        (
            !caseNumber
            (
                caseDir,
                s.get<fileName>("file"),
                word(s.get<string>("entry"), false),
                files,
                value
            )
         || mag(value - wanted) > 1e-9*max(mag(value), mag(wanted))
        )
        {
            return false;
        }
    }
    return true;
}

} // End namespace Foam


void Foam::reportMeasuredErrors(const Time& runTime)
{
    const fileName caseDir(runTime.globalPath());
    const fileName studyFile(caseDir/"errorStudy"/"measuredErrors");
    if (!isFile(studyFile))
    {
        Info<< "Expected error: none measured for this case (no"
            << " errorStudy/measuredErrors: colloidErrorStudy writes it)"
            << endl;
        return;
    }

    const dictionary study((IFstream(studyFile))());
    Info<< "Expected error at this case's settings, measured by"
        << " colloidErrorStudy (errorStudy/measuredErrors, "
        << study.get<string>("measured").c_str() << "; relative errors):" << nl;

    HashPtrTable<dictionary, fileName> files;
    for (const entry& settingEntry : study.subDict("settings"))
    {
        const dictionary& setting = settingEntry.dict();
        const dictionary& rungs = setting.subDict("rungs");

        const dictionary* match = nullptr;
        DynamicList<scalar> values;
        for (const entry& rungEntry : rungs)
        {
            const dictionary& rung = rungEntry.dict();
            values.append(rung.get<scalar>("value"));
            if (!match && caseIsRung(caseDir, rung.subDict("set"), files))
            {
                match = &rung;
            }
        }

        Info<< "    " << settingEntry.keyword();
        if (!match)
        {
            Info<< ": not measured (this case's value is none of the rungs";
            for (const scalar v : values)
            {
                Info<< " " << v;
            }
            Info<< ")" << nl;
            continue;
        }
        Info<< " " << match->get<scalar>("value");
        if (match->get<word>("status") != "ok")
        {
            Info<< ": the study's run at this value failed" << nl;
            continue;
        }

        const scalar cost = match->get<scalar>("cost");
        const dictionary& errors = match->subDict("errors");
        Info<< ":";
        if (errors.empty())
        {
            Info<< " no quantity analysed (fewer than two rungs ran)";
        }
        for (const entry& q : errors)
        {
            Info<< " " << q.keyword() << " "
                << sig3(100*q.dict().get<scalar>("error")) << " % ("
                << q.dict().get<string>("source").c_str() << ")";
        }
        Info<< "; run time " << sig3(cost) << " s";

        for (const entry& c : setting.subDict("cheapest"))
        {
            const dictionary& cheapest = c.dict();
            const scalar cheapestCost = cheapest.get<scalar>("cost");
            Info<< "; cheapest within "
                << sig3(100*cheapest.get<scalar>("tolerance")) << " %: "
                << cheapest.get<scalar>("value");
            if (cheapestCost > 0)
            {
                Info<< " (" << sig3(cost/cheapestCost) << "x faster)";
            }
        }
        Info<< nl;
    }
    Info<< endl;
}
