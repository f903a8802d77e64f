#include "measuredErrors.H"
#include "IFstream.H"
#include "OStringStream.H"
#include "HashPtrTable.H"
#include "OSspecific.H"
#include "Pstream.H"
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


// The number an entry holds, or false (the word none, not a number)
static bool numberOf(const entry& e, scalar& value)
{
    if (e.isDict())
    {
        return false;
    }
    ITstream& is = e.stream();
    if (is.size() != 1 || !is[0].isNumber())
    {
        return false;
    }
    value = is[0].number();
    return true;
}


// An entry of a case's dictionary; otherwise nullptr, with why not
static const entry* caseEntry
(
    const fileName& caseDir,
    const fileName& file,
    const word& entryPath,
    HashPtrTable<dictionary, fileName>& files,
    string& whyNot
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
        whyNot = "this case has no " + file;
        return nullptr;
    }
    // '/' scoping, e.g. DEM/timeStep or SIMPLE/residualControl/p
    const entry* e = dict->findScoped(entryPath, keyType::LITERAL);
    if (!e)
    {
        whyNot = file + " has no entry " + entryPath;
    }
    return e;
}


// Whether two numbers of a study and a case are the same setting: within
// 1e-9 relative (a value written back from a rung's text)
static bool sameNumber(const scalar x, const scalar y)
{
    return mag(x - y) <= 1e-9*max(mag(x), mag(y));
}


// The number an entry of a case's dictionary holds; otherwise false, with
// why not
static bool caseNumber
(
    const fileName& caseDir,
    const fileName& file,
    const word& entryPath,
    HashPtrTable<dictionary, fileName>& files,
    scalar& value,
    string& whyNot
)
{
    const entry* e = caseEntry(caseDir, file, entryPath, files, whyNot);
    if (!e)
    {
        return false;
    }
    if (!numberOf(*e, value))
    {
        whyNot = file + " entry " + entryPath + " is not a number";
        return false;
    }
    return true;
}


// An entry's value as text, for a message
static string textOf(const entry& e)
{
    if (e.isDict())
    {
        return "a dictionary";
    }
    OStringStream os;
    os.precision(12);       // numbers that differ show it
    const ITstream& is = e.stream();
    forAll(is, i)
    {
        if (i)
        {
            os  << ' ';
        }
        if (is[i].isStringType())
        {
            os  << is[i].stringToken().c_str();
        }
        else
        {
            os  << is[i];
        }
    }
    return os.str();
}


// Whether two entries hold the same value: numbers within 1e-9 relative,
// words and strings equal as text (a word and a string of the same text
// are the same)
static bool sameValue(const entry& a, const entry& b)
{
    scalar x = 0, y = 0;
    if (numberOf(a, x) && numberOf(b, y))
    {
        return sameNumber(x, y);
    }
    if (a.isDict() || b.isDict())
    {
        return false;
    }
    const ITstream& sa = a.stream();
    const ITstream& sb = b.stream();
    return
        sa.size() == 1 && sb.size() == 1
     && sa[0].isStringType() && sb[0].isStringType()
     && sa[0].stringToken() == sb[0].stringToken();
}


// Whether this case holds every value of the study's context (the entries
// its errors hold for, e.g. the form of the colloid cut-offs); otherwise
// false, with why not
static bool caseIsContext
(
    const fileName& caseDir,
    const dictionary& study,
    HashPtrTable<dictionary, fileName>& files,
    string& whyNot
)
{
    // A study without a context holds for any case (one written before
    // the context existed, or whose errorStudyDict declares none)
    const dictionary* context = study.findDict("context");
    if (!context)
    {
        return true;
    }
    for (const entry& c : *context)
    {
        const dictionary& s = c.dict();
        const fileName file(s.get<fileName>("file"));
        const word entryPath(s.get<string>("entry"), false);
        const entry* e = caseEntry(caseDir, file, entryPath, files, whyNot);
        if (!e)
        {
            return false;
        }
        const entry& measured = s.lookupEntry("value", keyType::LITERAL);
        if (!sameValue(*e, measured))
        {
            whyNot =
                "the study's " + file + " entry " + entryPath + " is "
              + textOf(measured) + ", this case's " + textOf(*e);
            return false;
        }
    }
    return true;
}


// Whether every entry a rung set holds the rung's number in this case:
// 1 yes, 0 no, -1 the case's entries cannot be compared (whyNot)
static label caseIsRung
(
    const fileName& caseDir,
    const dictionary& rungSet,
    HashPtrTable<dictionary, fileName>& files,
    string& whyNot
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
                value,
                whyNot
            )
        )
        {
            return -1;
        }
        if (!sameNumber(value, wanted))
        {
            return 0;
        }
    }
    return 1;
}


// The report of a study file, into os
static void report
(
    const fileName& caseDir,
    const dictionary& study,
    Ostream& os
)
{
    HashPtrTable<dictionary, fileName> files;
    string notContext;
    if (!caseIsContext(caseDir, study, files, notContext))
    {
        os  << "Expected error: none measured for this case"
            << " (errorStudy/measuredErrors, "
            << study.get<string>("measured").c_str() << ": "
            << notContext.c_str() << ")" << nl;
        return;
    }

    os  << "Expected error at this case's settings, measured by"
        << " colloidErrorStudy (errorStudy/measuredErrors, "
        << study.get<string>("measured").c_str() << "; relative errors):"
        << nl;

    const wordList quantities(study.get<wordList>("quantities"));
    for (const entry& settingEntry : study.subDict("settings"))
    {
        const dictionary& setting = settingEntry.dict();

        const dictionary* match = nullptr;
        string whyNot;
        DynamicList<scalar> values;
        for (const entry& rungEntry : setting.subDict("rungs"))
        {
            const dictionary& rung = rungEntry.dict();
            values.append(rung.get<scalar>("value"));
            if (!match && whyNot.empty())
            {
                const label on =
                    caseIsRung(caseDir, rung.subDict("set"), files, whyNot);
                if (on == 1)
                {
                    match = &rung;
                }
            }
        }

        os  << "    " << settingEntry.keyword();
        if (!match)
        {
            os  << ": not measured (";
            if (whyNot.size())
            {
                os  << whyNot.c_str();
            }
            else
            {
                os  << "this case's value is none of the rungs";
                for (const scalar v : values)
                {
                    os  << " " << v;
                }
            }
            os  << ")" << nl;
            continue;
        }
        os  << " " << match->get<scalar>("value");
        if (match->get<word>("status") != "ok")
        {
            os  << ": the study's run at this value failed" << nl;
            continue;
        }

        os  << ":";
        const dictionary& errors = match->subDict("errors");
        for (const word& q : quantities)
        {
            const dictionary* qDict = errors.findDict(q);
            scalar error = 0;
            if (!qDict)
            {
                os  << " " << q << " not analysed (fewer than two rungs ran)";
            }
            else if (numberOf(qDict->lookupEntry("error", keyType::LITERAL), error))
            {
                os  << " " << q << " " << sig3(100*error) << " % ("
                    << qDict->get<string>("source").c_str() << ")";
            }
            else
            {
                // The rung the others are measured against
                os  << " " << q << " the reference ("
                    << qDict->get<string>("source").c_str() << ")";
            }
        }
        const scalar cost = match->get<scalar>("cost");
        os  << "; run time " << sig3(cost) << " s";

        for (const entry& c : setting.subDict("cheapest"))
        {
            const dictionary& cheapest = c.dict();
            os  << "; cheapest within "
                << sig3(100*cheapest.get<scalar>("tolerance")) << " %: ";
            scalar value = 0, cheapestCost = 0;
            if
            (
                numberOf(cheapest.lookupEntry("value", keyType::LITERAL), value)
             && numberOf
                (
                    cheapest.lookupEntry("cost", keyType::LITERAL),
                    cheapestCost
                )
            )
            {
                os  << value << " (" << sig3(cheapestCost/max(cost, VSMALL))
                    << " x this run time)";
            }
            else
            {
                os  << "no rung";
            }
        }
        os  << nl;
    }
}

} // End namespace Foam


void Foam::reportMeasuredErrors(const Time& runTime)
{
    // The master reads and prints: the report is for the log only
    if (!Pstream::master())
    {
        return;
    }

    const fileName caseDir(runTime.globalPath());
    const fileName studyFile(caseDir/"errorStudy"/"measuredErrors");
    if (!isFile(studyFile))
    {
        Info<< "Expected error: none measured for this case (no"
            << " errorStudy/measuredErrors: colloidErrorStudy writes it)"
            << endl;
        return;
    }

    // A file this run cannot read is reported, not fatal: what a study
    // measured never stops a run
    const bool throwingIO = FatalIOError.throwExceptions(true);
    const bool throwing = FatalError.throwExceptions(true);
    try
    {
        const dictionary study((IFstream(studyFile))());
        OStringStream os;
        report(caseDir, study, os);
        Info<< os.str().c_str() << endl;
    }
    catch (const Foam::error& err)
    {
        Info<< "Expected error: errorStudy/measuredErrors cannot be used ("
            << err.message().c_str() << "); run colloidErrorStudy again"
            << endl;
    }
    FatalIOError.throwExceptions(throwingIO);
    FatalError.throwExceptions(throwing);
}
