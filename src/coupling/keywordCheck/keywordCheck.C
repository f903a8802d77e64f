#include "keywordCheck.H"
#include "error.H"
#include "FlatOutput.H"

Foam::label Foam::editDistance(const word& a, const word& b)
{
    // Wagner-Fischer, one row
    labelList row(b.size() + 1);
    forAll(row, j)
    {
        row[j] = j;
    }
    for (std::string::size_type i = 1; i <= a.size(); ++i)
    {
        label diagonal = row[0];
        row[0] = i;
        for (std::string::size_type j = 1; j <= b.size(); ++j)
        {
            const label above = row[j];
            row[j] = min
            (
                min(row[j] + 1, row[j - 1] + 1),
                diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)
            );
            diagonal = above;
        }
    }
    return row[b.size()];
}


void Foam::keywordCheck
(
    const dictionary& dict,
    const wordList& allowed,
    const bool strict
)
{
    for (const word& key : dict.toc())
    {
        if (allowed.found(key))
        {
            continue;
        }
        word nearest;
        label distance = labelMax;
        for (const word& candidate : allowed)
        {
            const label d = editDistance(key, candidate);
            if (d < distance)
            {
                distance = d;
                nearest = candidate;
            }
        }
        // Not strict: a short key (a case parameter such as "E" or "mu")
        // is two edits from many names; only longer ones are judged
        if (strict || (distance <= 2 && key.size() >= 4))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown keyword '" << key.c_str() << "' in "
                << dict.name().c_str();
            if (distance <= 2)
            {
                FatalIOError
                    << "; did you mean '" << nearest.c_str() << "'?";
            }
            FatalIOError
                << " Allowed: " << flatOutput(allowed) << exit(FatalIOError);
        }
    }
}
