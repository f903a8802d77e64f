/*---------------------------------------------------------------------------*\
  colloidFoam: see contactAnalysis.H
\*---------------------------------------------------------------------------*/

#include "contactAnalysis.H"
#include "couplingProperties.H"
#include "liggghtsEngine.H"
#include "Time.H"
#include "OSspecific.H"
#include "liggghtsColloid/colloid_contact_analysis_api.h"

#include <cerrno>
#include <cstring>
#include <sstream>
#include <vector>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::contactAnalysis::contactAnalysis
(
    const couplingProperties& props,
    liggghtsEngine& dem,
    const Time& runTime
)
:
    handle_(nullptr),
    interval_(props.contactInterval()),
    lastTime_(-1)
{
    handle_ = dem.newContactAnalysis
    (
        props.touchingGap(),
        props.releaseGap(),
        props.agglomerateGap()
    );

    if (Pstream::master())
    {
        const fileName dir =
            runTime.globalPath()/"postProcessing"/"contactAnalysis"
           /runTime.timeName();
        mkDir(dir);
        contacts_.reset(new OFstream(dir/"contacts.csv"));
        durations_.reset(new OFstream(dir/"contactDurations.csv"));
        sizes_.reset(new OFstream(dir/"agglomerateSizes.csv"));
        for (OFstream* os : {contacts_.get(), durations_.get(), sizes_.get()})
        {
            os->precision(12);
        }
        contacts_()
            << "# touching: gap < " << props.touchingGap()
            << " x the smaller radius; released: gap >= "
            << props.releaseGap() << " x it; agglomerate bonds: contacts"
            << " and gaps < " << props.agglomerateGap() << " x it; every "
            << interval_ << " coupling steps" << nl
            << "time,particles,pairContacts,wallContacts,pairFormed,"
            << "pairBroken,wallFormed,wallBroken,pairFormedPerUs,"
            << "wallFormedPerUs,meanContacts,with0,with1,with2,with3orMore,"
            << "agglomerates,agglomeratedParticles,largestAgglomerate"
            << endl;
        durations_() << "timeEnded,kind,duration" << endl;
        sizes_() << "time,size,count" << endl;
    }

    Info<< "Contact analysis: every " << interval_ << " coupling steps,"
        << " touching below " << props.touchingGap() << ", released at "
        << props.releaseGap() << " and agglomerate bonds (besides"
        << " contacts) below " << props.agglomerateGap() << " of the"
        << " smaller radius (postProcessing/contactAnalysis)" << endl;
}


Foam::contactAnalysis::~contactAnalysis()
{
    colloidContactAnalysisFree(handle_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::contactAnalysis::analyse
(
    liggghtsEngine& dem,
    const scalar t,
    const labelList& touchingWall
)
{
    std::vector<int> wall(touchingWall.begin(), touchingWall.end());
    ColloidContactCounts c;
    dem.analyseContacts(handle_, t, wall.data(), &c);

    if (Pstream::master())
    {
        const long* byContacts;
        const int nBy = colloidContactByContacts(handle_, &byContacts);
        auto with = [&](int k) { return k < nBy ? byContacts[k] : 0L; };
        long more = 0;
        for (int k = 3; k < nBy; ++k)
        {
            more += byContacts[k];
        }
        // rates per microsecond over the interval since the last analysis
        const scalar dt = lastTime_ >= 0 ? (t - lastTime_)/1e-6 : 0;
        const scalar pairRate = dt > 0 ? c.pairFormed/dt : 0;
        const scalar wallRate = dt > 0 ? c.wallFormed/dt : 0;
        contacts_()
            << t << ',' << c.particles << ',' << c.pairContacts << ','
            << c.wallContacts << ',' << c.pairFormed << ',' << c.pairBroken
            << ',' << c.wallFormed << ',' << c.wallBroken << ',' << pairRate
            << ',' << wallRate << ','
            << (c.particles ? 2.0*c.pairContacts/c.particles : 0.0) << ','
            << with(0) << ',' << with(1) << ',' << with(2) << ',' << more
            << ',' << c.agglomerates << ',' << c.agglomerated << ','
            << c.largest << endl;

        for (const int w : {0, 1})
        {
            const double* d;
            const int n = colloidContactDurations(handle_, w, &d);
            for (int k = 0; k < n; ++k)
            {
                durations_()
                    << t << ',' << (w ? "wall" : "pair") << ',' << d[k] << nl;
            }
        }
        durations_().flush();

        const long* sizes;
        const int nSizes = colloidContactAgglomerateSizes(handle_, &sizes);
        for (int k = 0; k < nSizes; ++k)
        {
            sizes_() << t << ',' << sizes[2*k] << ',' << sizes[2*k + 1] << nl;
        }
        sizes_().flush();

        std::ostringstream os;
        os  << c.pairContacts << " particle and " << c.wallContacts
            << " wall contacts; agglomerates " << c.agglomerates
            << " (largest " << c.largest << ")";
        summary_ = os.str();
    }
    lastTime_ = t;
}


Foam::string Foam::contactAnalysis::saveHistories(const fileName& file) const
{
    const int err = colloidContactSaveHistories(handle_, file.c_str());
    if (err == 0)
    {
        return string();
    }
    return "cannot write the contact histories " + file + ": "
        + std::strerror(err);
}


void Foam::contactAnalysis::loadHistories(const fileName& file, const scalar t)
{
    const int err = colloidContactLoadHistories(handle_, file.c_str());
    const int absent = returnReduce(err == ENOENT ? 1 : 0, sumOp<int>());
    if (returnReduce(err == EINVAL ? 1 : 0, sumOp<int>()))
    {
        FatalErrorInFunction
            << "The contact histories " << file << " (on at least one rank)"
            << " were not written by a run of " << Pstream::nProcs()
            << " ranks, or are incomplete: resume with as many ranks as the"
            << " run that wrote them" << exit(FatalError);
    }
    if (absent && absent != Pstream::nProcs())
    {
        FatalErrorInFunction
            << "The contact histories " << file << " are missing on "
            << absent << " of " << Pstream::nProcs() << " ranks"
            << exit(FatalError);
    }
    if (absent)
    {
        Info<< "Contact analysis: no contact histories in " << file.path()
            << " (written before they were saved): the contacts present now"
            << " have no known start" << endl;
        return;
    }
    lastTime_ = t;
    Info<< "Contact analysis: contact histories of time " << t
        << " s read back" << endl;
}


namespace
{
    // The plugin's per-atom values (long) as OpenFOAM labels
    Foam::labelList labels(const long* values, const Foam::label n)
    {
        Foam::labelList out(n);
        forAll(out, i)
        {
            out[i] = Foam::label(values[i]);
        }
        return out;
    }
}


Foam::labelList Foam::contactAnalysis::agglomerateSize(const label nLocal) const
{
    return labels(colloidContactAgglomerateSize(handle_), nLocal);
}


Foam::labelList Foam::contactAnalysis::agglomerateId(const label nLocal) const
{
    return labels(colloidContactAgglomerateId(handle_), nLocal);
}
