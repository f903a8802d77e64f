#include "demRestart.H"
#include "contactAnalysis.H"
#include "IOdictionary.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "Time.H"
#include "ListOps.H"
#include "demUnits.H"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>
#include <sys/statvfs.h>

namespace
{

const char* const markerName = "colloidCoupling";

// In a write time's DEM folder: the contact analysis' histories
const char* const contactHistoryName = "contactHistory";

// The per-atom properties of the last step's force and torque
const char* const forceFix = "colloidForce";
const char* const torqueFix = "colloidTorque";

// LIGGGHTS' insert/stream: per atom, column 4 of its release data is the
// step at which a particle inserted in the feed zone is released; a copy
// of it (see the class description)
const char* const releaseFix = "release_fix_insert_stream";
const int releaseStepColumn = 4;
const char* const releaseCopyFix = "colloidReleaseStep";

// to[i] = from[i] for n per-atom 3-vectors
void copyVectors(double** from, double** to, const int n)
{
    for (int i = 0; i < n; ++i)
    {
        for (int k = 0; k < 3; ++k)
        {
            to[i][k] = from[i][k];
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

Foam::fileName Foam::demRestart::pattern(const fileName& dir)
{
    return dir/"restart.%";
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::demRestart::demRestart(const fvMesh& mesh)
:
    mesh_(mesh),
    resume_(false),
    demStep_(0),
    nInserted_(0),
    demTimeStepSize_(0),
    demRank_(Pstream::myProcNo()),
    demGrid_(label(0))
{
    const Time& runTime = mesh.time();

    IOobject markerIO
    (
        markerName,
        runTime.timeName(),
        "uniform",
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    resume_ = returnReduce
    (
        markerIO.typeHeaderOk<IOdictionary>(false),
        andOp<bool>()
    );

    if (resume_)
    {
        IOdictionary marker(markerIO);
        demStep_ = marker.get<label>("demStep");
        nInserted_ = marker.get<label>("nInserted");
        const label nProcs = marker.get<label>("nProcs");
        demTimeStepSize_ = marker.get<scalar>("demTimeStep");
        // Written only by runs that asked LIGGGHTS for a grid
        demGrid_ = marker.getOrDefault<FixedList<label, 3>>
        (
            "demGrid", FixedList<label, 3>(label(0))
        );
        if (nProcs != Pstream::nProcs())
        {
            FatalIOErrorInFunction(marker)
                << "The DEM state of time " << runTime.timeName()
                << " was written by " << nProcs << " ranks (keyword"
                << " 'nProcs' in " << marker.name() << "); this run has "
                << Pstream::nProcs() << ".  Resume it with " << nProcs
                << " ranks" << exit(FatalIOError);
        }

        const fileName files(pattern(runTime.timePath()/"DEM"));

        // This rank's rank in LIGGGHTS in the written run: the number of
        // its own restart file (LIGGGHTS' ranks may be in another order
        // than the fluid's, demCoupling::chooseDEMDecomposition).  (Not in
        // the marker: a dictionary in uniform/ is read on the master
        // only.)
        label nNumbered = 0;
        for (const fileName& f : readDir(files.path(), fileName::FILE))
        {
            const word name(f.name());
            label n = -1;
            if
            (
                name.size() > 8 && name.substr(0, 8) == "restart."
             && Foam::read(name.substr(8), n)
            )
            {
                demRank_ = n;
                ++nNumbered;
            }
        }
        // One file per rank, the numbers 0 ... nProcs - 1 (a rank without
        // one, -1, is named by the check of the files below)
        labelList demRanks(Pstream::nProcs(), -1);
        demRanks[Pstream::myProcNo()] =
            (nNumbered == 0) ? -1 : (nNumbered == 1) ? demRank_ : -2;
        Pstream::gatherList(demRanks);
        Pstream::scatterList(demRanks);
        labelList sorted(demRanks);
        Foam::sort(sorted);
        if (!demRanks.found(-1) && sorted != identity(Pstream::nProcs()))
        {
            FatalErrorInFunction
                << "Cannot resume from time " << runTime.timeName()
                << ": each rank's DEM folder must hold one numbered restart"
                << " file, their numbers 0 to " << Pstream::nProcs() - 1
                << " (restart.<n>, n: the rank's rank in LIGGGHTS); found"
                << " per rank (-2: more than one) " << demRanks
                << exit(FatalError);
        }
        if (nNumbered != 1)
        {
            demRank_ = Pstream::myProcNo();
        }

        fileName missing;
        if (demRank_ == 0 && !isFile(files.path()/"restart.base"))
        {
            missing = files.path()/"restart.base";
        }
        const fileName own
        (
            files.path()/("restart." + Foam::name(demRank_))
        );
        if (!isFile(own))
        {
            missing = own;
        }
        if (returnReduce(!missing.empty(), orOp<bool>()))
        {
            FatalErrorInFunction
                << "Cannot resume from time " << runTime.timeName()
                << ": its DEM state is incomplete"
                << (missing.empty() ? word() : word(" (no " + missing + ")"))
                << " although " << marker.objectPath() << " says it was"
                << " written" << exit(FatalError);
        }

        Info<< "Resuming from time " << runTime.timeName() << ": DEM step "
            << demStep_ << ", " << nInserted_ << " particles inserted so far"
            << " (" << files << ")" << nl << endl;
        return;
    }

    // No resumable state: a fresh start, unless earlier times exist (the
    // start time was not written completely, or not by this solver)
    const scalar start = runTime.value();
    const scalar tol = 1e-6*runTime.deltaTValue();
    word latestComplete;
    bool earlier = false;
    for (const instant& t : runTime.times())
    {
        if (t.name() == "constant" || t.value() >= start - tol)
        {
            continue;
        }
        earlier = true;
        if (isFile(runTime.path()/t.name()/"uniform"/markerName))
        {
            latestComplete = t.name();
        }
    }
    if (returnReduce(earlier, orOp<bool>()))
    {
        FatalErrorInFunction
            << "The start time " << runTime.timeName() << " has no DEM"
            << " state (" << runTime.timePath()/"uniform"/markerName
            << "): its write did not complete (the run was stopped while"
            << " writing) or it was not written by colloidDEMFoam. "
            << (
                   latestComplete.empty()
                 ? word("No earlier time can be resumed from either.")
                 : word
                   (
                       "The latest time that can be resumed from is "
                     + latestComplete + ": set startFrom startTime;"
                       " startTime " + latestComplete + "; in"
                       " system/controlDict, or delete the later time"
                       " folders."
                   )
               )
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::demRestart::defineVariables(liggghtsEngine& dem) const
{
    dem.command
    (
        std::string("variable colloid_restart equal ") + (resume_ ? "1" : "0")
    );
    dem.command
    (
        "variable colloid_restart_file string "
      + pattern(mesh_.time().timePath()/"DEM")
    );
}


void Foam::demRestart::addFixes(liggghtsEngine& dem) const
{
    for (const char* id : {forceFix, torqueFix})
    {
        dem.command
        (
            std::string("fix ") + id + " all property/atom " + id
          + " vector yes no no 0 0 0"
        );
    }
    dem.command
    (
        std::string("fix ") + releaseCopyFix + " all property/atom "
      + releaseCopyFix + " scalar yes no no -1"
    );
}


Foam::label Foam::demRestart::restored
(
    liggghtsEngine& dem,
    const fileName& script
) const
{
    if (!resume_)
    {
        return 0;
    }

    if (dem.timeStep() != demStep_)
    {
        FatalErrorInFunction
            << "Resuming from time " << mesh_.time().timeName()
            << " (DEM step " << demStep_ << "), the DEM script " << script
            << " did not read the DEM state (the DEM is at step "
            << dem.timeStep() << ").  The script must read it instead of"
            << " creating the box and particles when colloid_restart is 1:"
            << nl << nl
            << "    if \"${colloid_restart} == 0\" then &" << nl
            << "        \"atom_style sphere\" ... \"read_data ...\" &" << nl
            << "    else &" << nl
            << "        \"read_restart ${colloid_restart_file}\"" << nl
            << exit(FatalError);
    }

    // The feed's release steps too, unless the step changed (then
    // LIGGGHTS' rescaled ones stand)
    const scalar dt = dem.timeStepSize()*demUnits::time;
    restoreLastStep(dem, mag(dt - demTimeStepSize_) <= 1e-6*demTimeStepSize_);
    return nInserted_;
}


void Foam::demRestart::restoreLastStep
(
    liggghtsEngine& dem,
    const bool releaseSteps
) const
{
    // The force and torque of the last step's end, for the first
    // half-step (see the class description)
    const int n = dem.nLocal();
    copyVectors(dem.vectorProperty(forceFix), dem.f(), n);
    copyVectors(dem.vectorProperty(torqueFix), dem.torque(), n);

    // The feed's release steps as they were
    if (releaseSteps && dem.hasFix(releaseFix))
    {
        double** release = dem.vectorProperty(releaseFix);
        double* saved = dem.scalarProperty(releaseCopyFix);
        for (int i = 0; i < n; ++i)
        {
            if (saved[i] >= 0)
            {
                release[i][releaseStepColumn] = saved[i];
            }
        }
    }
}


Foam::fileName Foam::demRestart::contactHistoryFile() const
{
    return mesh_.time().timePath()/"DEM"/contactHistoryName;
}


Foam::string Foam::demRestart::write
(
    liggghtsEngine& dem,
    const label nInserted,
    const contactAnalysis* contacts,
    const FixedList<label, 3>& demGrid
) const
{
    const Time& runTime = mesh_.time();
    const fileName dir(runTime.timePath()/"DEM");
    const fileName tmp(runTime.timePath()/"DEM.tmp");

    // A problem on any rank is a problem of all (collective)
    string problem;
    auto failed = [&problem]()
    {
        if (returnReduce(problem.empty(), andOp<bool>()))
        {
            return false;
        }
        if (problem.empty())
        {
            problem = "the DEM state could not be written on another rank";
        }
        return true;
    };

    const long step = dem.timeStep();
    if (step > labelMax)
    {
        FatalErrorInFunction
            << "DEM step " << step << " exceeds the largest label "
            << labelMax << ": the restart counters cannot hold it"
            << exit(FatalError);
    }

    const int n = dem.nLocal();
    copyVectors(dem.f(), dem.vectorProperty(forceFix), n);
    copyVectors(dem.torque(), dem.vectorProperty(torqueFix), n);
    if (dem.hasFix(releaseFix))
    {
        double** release = dem.vectorProperty(releaseFix);
        double* copy = dem.scalarProperty(releaseCopyFix);
        for (int i = 0; i < n; ++i)
        {
            copy[i] = release[i][releaseStepColumn];
        }
    }

    // (a left-over of an interrupted write; usually there is none, and
    // rmDir would warn at every write)
    if (isDir(tmp))
    {
        rmDir(tmp);
    }
    if (!mkDir(tmp))
    {
        problem = "cannot create " + tmp;
    }
    if (failed())
    {
        return problem;
    }
    problem = dem.writeRestart(pattern(tmp));
    if (failed())
    {
        return problem;
    }
    if (contacts)
    {
        problem = contacts->saveHistories(tmp/contactHistoryName);
        if (failed())
        {
            return problem;
        }
    }

    // write_restart exchanged atoms between ranks (and wrapped periodic
    // ones) but left the neighbour lists and their reference positions as
    // they were: set up again, and continue from the last step's forces
    dem.setUpNextRun();
    dem.run(0);
    restoreLastStep(dem, true);

    // Every rank's files are complete: replace the time's DEM state (if a
    // resumed run passes a time written before)
    if (isDir(dir))
    {
        rmDir(dir);
    }
    if (!mv(tmp, dir))
    {
        problem = "cannot rename " + tmp + " to " + dir;
    }
    if (failed())
    {
        return problem;
    }

    // The counters, last, also written under a temporary name
    IOdictionary marker
    (
        IOobject
        (
            word(markerName) + ".tmp",
            runTime.timeName(),
            "uniform",
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    marker.add("demStep", label(step));
    marker.add("nInserted", nInserted);
    marker.add("nProcs", Pstream::nProcs());
    marker.add("demTimeStep", dem.timeStepSize()*demUnits::time);
    if (demGrid[0] > 0)
    {
        marker.add("demGrid", demGrid);
    }
    // Read back before it counts: a small file can fail unseen when it is
    // closed on a full disk
    bool written = marker.regIOobject::write();
    if (written)
    {
        IFstream is(marker.objectPath());
        const dictionary copy(is);
        written =
            copy.getOrDefault<label>("demStep", -1) == label(step)
         && copy.found("demTimeStep");
    }
    if
    (
        !written
     || !mv(marker.objectPath(), marker.objectPath().path()/markerName)
    )
    {
        problem = "cannot write " + marker.objectPath();
    }
    failed();
    return problem;
}


void Foam::demRestart::abandonWrite(const string& what) const
{
    const Time& runTime = mesh_.time();
    const fileName dir(runTime.timePath());

    // The file system's reason: a probe write of 64 kB beside the time
    // folder (the writers above do not keep errno), and the space left
    const fileName probe(dir.path()/(".colloidWriteProbe" + Foam::name(Pstream::myProcNo())));
    std::string reason = "the probe write succeeded";
    {
        std::FILE* f = std::fopen(probe.c_str(), "wb");
        const std::vector<char> block(1 << 16, 0);
        errno = 0;
        if
        (
            !f
         || std::fwrite(block.data(), 1, block.size(), f) != block.size()
         || std::fflush(f) != 0
        )
        {
            reason = std::strerror(errno);
        }
        if (f)
        {
            std::fclose(f);
        }
        std::remove(probe.c_str());
    }
    struct statvfs fs;
    const double freeBytes =
        statvfs(dir.path().c_str(), &fs) == 0
      ? double(fs.f_bavail)*double(fs.f_frsize) : -1;

    // The start time holds the case's own fields: only the output of
    // this run goes.  Every rank removes its part before any stops.
    const bool atStart = runTime.timeIndex() == runTime.startTimeIndex();
    const fileName removed(atStart ? dir/"lagrangian" : dir);
    rmDir(removed);
    returnReduce(true, andOp<bool>());

    FatalErrorInFunction
        << "Writing time " << runTime.timeName() << " failed: " << what.c_str()
        << ".  The file system (" << dir.path() << ") says: "
        << reason.c_str() << "; " << freeBytes << " bytes free.  The"
        << " incomplete " << (atStart ? "output " : "time folder ") << removed
        << " was removed: free some space and "
        << (
               atStart
             ? "run again"
             : "resume from the latest complete write time (startFrom"
               " latestTime; in system/controlDict)"
           )
        << exit(FatalError);
}


void Foam::demRestart::invalidate() const
{
    // A time folder written again (a run resumed from an earlier time
    // passes the later ones) must not keep the marker of its earlier
    // content while the new content is written
    rm(mesh_.time().timePath()/"uniform"/markerName);
}
