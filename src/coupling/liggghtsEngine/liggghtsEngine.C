/*---------------------------------------------------------------------------*\
    The only translation unit of the project's OpenFOAM side that sees
    LIGGGHTS' headers.  They are included as <liggghts/...> with no
    -I/usr/include/liggghts, because that folder holds error.h and memory.h,
    which would shadow the C library's headers of the same names.
\*---------------------------------------------------------------------------*/

#include "liggghtsEngine.H"

#include <mpi.h>
#include <liggghts/lammps.h>
#include <liggghts/input.h>
#include <liggghts/atom.h>
#include <liggghts/update.h>
#include <liggghts/modify.h>
#include <liggghts/force.h>
#include <liggghts/domain.h>
#include <liggghts/comm.h>
#include <liggghts/fix.h>
#include <liggghts/compute.h>
#include "liggghtsColloid/register_colloid_models.h"
#include "liggghtsColloid/colloid_contact_analysis_api.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace
{

// LIGGGHTS ends the process itself on a bad command (exit(1) after
// writing the error to its log).  With its screen output off, the user
// would see a silent stop: at exit during a LIGGGHTS call, show the end of
// its log on stderr.
std::string logFileName;
bool insideLiggghts = false;
int worldRank = 0;      // MPI_COMM_WORLD's rank 0 reports (the log is written
                        // by LIGGGHTS' rank 0, the same file)

void reportLiggghtsExit()
{
    if (!insideLiggghts || worldRank != 0) return;

    std::ifstream log(logFileName);
    std::deque<std::string> tail;
    for (std::string line; std::getline(log, line); )
    {
        tail.push_back(line);
        if (tail.size() > 5) tail.pop_front();
    }
    std::fprintf(stderr, "\n--> LIGGGHTS stopped the run; end of %s:\n",
        logFileName.c_str());
    for (const std::string& line : tail)
    {
        std::fprintf(stderr, "    %s\n", line.c_str());
    }

    // What LIGGGHTS' terse messages mean in a coupled run
    static const char* const hints[][2] =
    {
        {
            "Did not assign all atoms correctly",
            "some particles of the DEM's data file lie outside its"
            " simulation box (the box bounds of read_data, or the region of"
            " create_box): compare their coordinates with the box"
        },
        {
            "Lost atoms",
            "particles left the DEM box through a non-periodic boundary:"
            " check the box against the fluid domain and the particles'"
            " speeds; to go on without them, 'thermo_modify lost ignore' in"
            " the DEM script and DEM { allowLostParticles yes; } in"
            " constant/couplingProperties"
        },
        {
            "Unknown command",
            "a misspelt or unknown LIGGGHTS command in the DEM script (the"
            " line above the error)"
        }
    };
    for (const auto& hint : hints)
    {
        for (const std::string& line : tail)
        {
            if (line.find("ERROR") != std::string::npos
             && line.find(hint[0]) != std::string::npos)
            {
                std::fprintf(stderr, "--> That is: %s\n", hint[1]);
                break;
            }
        }
    }
}


// Scope of a call into LIGGGHTS, for reportLiggghtsExit.
// OpenFOAM's floating-point traps (FOAM_SIGFPE) stay on inside LIGGGHTS:
// the coupled runs tried so far raise none, and a trap is louder than the
// NaN LIGGGHTS would otherwise carry on with (e.g. a particle centred
// exactly on a mesh wall: 0/0 in the wall contact normal).
struct liggghtsCall
{
    liggghtsCall() { insideLiggghts = true; }
    ~liggghtsCall() { insideLiggghts = false; }
};


LAMMPS_NS::LAMMPS* engine(void* p)
{
    return static_cast<LAMMPS_NS::LAMMPS*>(p);
}


LAMMPS_NS::Fix* findFix(void* p, const std::string& id)
{
    LAMMPS_NS::Modify* modify = engine(p)->modify;
    const int i = modify->find_fix(id.c_str());
    if (i < 0)
    {
        throw std::runtime_error("LIGGGHTS has no fix with id '" + id + "'");
    }
    return modify->fix[i];
}

} // End anonymous namespace


Foam::liggghtsEngine::liggghtsEngine
(
    const std::string& logFile,
    const std::string& screenFile,
    const int demRank
)
:
    lmp_(nullptr),
    world_(nullptr),
    ownsMPI_(false),
    setUpWithParticles_(false),
    setUpNext_(false),
    withoutDrag_()
{
    int started = 0;
    MPI_Initialized(&started);
    if (!started)
    {
        int argc = 0;
        char** argv = nullptr;
        MPI_Init(&argc, &argv);
        ownsMPI_ = true;
    }

    // LAMMPS takes a mutable argv
    std::vector<std::string> args{"liggghts", "-log", logFile};
    if (!screenFile.empty())
    {
        // Not "none": some LIGGGHTS commands (mesh file input) print to
        // the screen without checking that it exists
        args.push_back("-screen");
        args.push_back(screenFile);
    }
    std::vector<char*> argv;
    for (std::string& a : args)
    {
        argv.push_back(&a[0]);
    }

    logFileName = logFile;
    MPI_Comm_rank(MPI_COMM_WORLD, &worldRank);
    static bool exitReported = false;
    if (!exitReported)
    {
        std::atexit(reportLiggghtsExit);
        exitReported = true;
    }

    MPI_Comm* world = new MPI_Comm;
    if (demRank >= 0)
    {
        MPI_Comm_split(MPI_COMM_WORLD, 0, demRank, world);
    }
    else
    {
        MPI_Comm_dup(MPI_COMM_WORLD, world);
    }
    world_ = world;

    liggghtsCall call;
    lmp_ = new LAMMPS_NS::LAMMPS
    (
        static_cast<int>(argv.size()), argv.data(), *world
    );

    // An error on one rank ends with MPI_Abort, which flushes nothing
    for (FILE* f : {engine(lmp_)->screen, engine(lmp_)->logfile})
    {
        if (f)
        {
            std::setvbuf(f, nullptr, _IOLBF, BUFSIZ);
        }
    }
}


Foam::liggghtsEngine::~liggghtsEngine()
{
    colloidDragCallback(lmp_, nullptr, nullptr);
    delete engine(lmp_);
    int finished = 0;
    MPI_Finalized(&finished);
    MPI_Comm* world = static_cast<MPI_Comm*>(world_);
    if (!finished)
    {
        MPI_Comm_free(world);
    }
    delete world;
    if (ownsMPI_ && !finished)
    {
        MPI_Finalize();
    }
}


void Foam::liggghtsEngine::command(const std::string& line)
{
    liggghtsCall call;
    engine(lmp_)->input->one(line.c_str());
}


void Foam::liggghtsEngine::file(const std::string& fileName)
{
    liggghtsCall call;
    engine(lmp_)->input->file(fileName.c_str());
}


std::string Foam::liggghtsEngine::writeRestart(const std::string& pattern)
{
    const std::string::size_type percent = pattern.find('%');
    if (percent == std::string::npos)
    {
        throw std::runtime_error
        (
            "restart file pattern '" + pattern + "' has no '%'"
        );
    }
    command("write_restart " + pattern);

    auto named = [&](const std::string& part)
    {
        std::string name(pattern);
        return name.replace(percent, 1, part);
    };

    // This rank's atoms: an int n, then n doubles (write_restart.cpp), in
    // the file of its rank in LIGGGHTS' communicator
    const std::string own = named(std::to_string(rank()));
    std::ifstream is(own, std::ios::binary | std::ios::ate);
    const long long size = is ? static_cast<long long>(is.tellg()) : -1;
    int n = -1;
    if (size >= static_cast<long long>(sizeof(int)))
    {
        is.seekg(0);
        is.read(reinterpret_cast<char*>(&n), sizeof(int));
    }
    const long long expected =
        static_cast<long long>(sizeof(int))
      + static_cast<long long>(sizeof(double))*n;
    if (n < 0 || size != expected)
    {
        return
            "the DEM restart file " + own + " is incomplete ("
          + std::to_string(size < 0 ? 0 : size) + " bytes"
          + (n < 0 ? std::string() : " of " + std::to_string(expected))
          + ")";
    }
    if (rank() == 0)
    {
        std::ifstream base(named("base"), std::ios::binary | std::ios::ate);
        if (!base || base.tellg() <= 0)
        {
            return
                "the DEM restart file " + named("base")
              + " is empty or missing";
        }
    }
    return std::string();
}


void Foam::liggghtsEngine::run(long nSteps)
{
    std::string line = "run " + std::to_string(nSteps);
    if (setUpWithParticles_)
    {
        line += setUpNext_ ? " pre yes post no" : " pre no post no";
    }
    const bool withParticles = nGlobal() > 0;

    // The set-up asked for before steps is the particles' first half
    // kick: its drag impulse is the fluid's too (the set-ups of a run 0,
    // and those LIGGGHTS makes until a run starts with particles, replace
    // forces whose impulse a step counted)
    const bool firstKick = setUpWithParticles_ && setUpNext_ && nSteps > 0;
    if (firstKick)
    {
        colloidFirstKick(lmp_, 1);
    }
    command(line);
    if (firstKick)
    {
        colloidFirstKick(lmp_, 0);
    }
    setUpWithParticles_ = setUpWithParticles_ || withParticles;
    setUpNext_ = false;
}


void Foam::liggghtsEngine::setUpNextRun()
{
    setUpNext_ = true;
}


bool Foam::liggghtsEngine::queueAtoms
(
    const std::vector<double>& x,
    const std::vector<double>& v,
    double radius,
    double density,
    int type
)
{
    liggghtsCall call;
    return colloidInsertAtoms
    (
        lmp_, int(x.size()/3), x.data(), v.data(), radius, density, type
    ) == 0;
}


long Foam::liggghtsEngine::queuedAtomsCreated() const
{
    return long(colloidInsertedAtoms(lmp_));
}


std::string Foam::liggghtsEngine::unitStyle() const
{
    const char* u = engine(lmp_)->update->unit_style;
    return u ? std::string(u) : std::string();
}


bool Foam::liggghtsEngine::hasFix(const std::string& fixId) const
{
    return engine(lmp_)->modify->find_fix(fixId.c_str()) >= 0;
}


int Foam::liggghtsEngine::nFixesOfStyle(const std::string& style) const
{
    return engine(lmp_)->modify->n_fixes_style_strict(style.c_str());
}


double Foam::liggghtsEngine::sumFixVector
(
    const std::string& style,
    const int index
) const
{
    double sum = 0;
    for (const auto& idValue : fixVectors(style, index))
    {
        sum += idValue.second;
    }
    return sum;
}


std::vector<std::pair<std::string, double>>
Foam::liggghtsEngine::fixVectors
(
    const std::string& style,
    const int index
) const
{
    LAMMPS_NS::Modify* modify = engine(lmp_)->modify;
    const int n = modify->n_fixes_style_strict(style.c_str());

    std::vector<std::pair<std::string, double>> values;
    for (int rank = 0; rank < n; ++rank)
    {
        LAMMPS_NS::Fix* fix =
            modify->find_fix_style_strict(style.c_str(), rank);
        if (!fix->vector_flag || index >= fix->size_vector)
        {
            throw std::runtime_error
            (
                "fix " + std::string(fix->id) + " (" + style
              + ") has no global vector element " + std::to_string(index)
            );
        }
        values.emplace_back(fix->id, fix->compute_vector(index));
    }
    return values;
}


void Foam::liggghtsEngine::implicitDamping()
{
    liggghtsCall call;
    registerColloidModels();
    // Before the implicit update: that fix stays last (its set-up must
    // follow the walls')
    colloidReneighborAt(lmp_, -1);
    colloidInsertAtoms(lmp_, 0, nullptr, nullptr, 0, 0, 1);
    colloidImplicitUpdate(lmp_);
}


void Foam::liggghtsEngine::reneighbourAt(const long step)
{
    colloidReneighborAt(lmp_, step);
}


void Foam::liggghtsEngine::callWithoutDrag(void* engine)
{
    insideLiggghts = false;
    static_cast<liggghtsEngine*>(engine)->withoutDrag_();
    insideLiggghts = true;
}


void Foam::liggghtsEngine::onAtomsWithoutDrag(std::function<void()> f)
{
    withoutDrag_ = std::move(f);
    colloidDragCallback
    (
        lmp_,
        withoutDrag_ ? &liggghtsEngine::callWithoutDrag : nullptr,
        this
    );
}


bool Foam::liggghtsEngine::hasGlobalProperty(const std::string& name) const
{
    return engine(lmp_)->modify->find_fix_property
    (
        name.c_str(), "property/global", "scalar", 0, 0, "colloidFoam", false
    ) != nullptr;
}


void* Foam::liggghtsEngine::newContactAnalysis
(
    double touchingGap,
    double releaseGap,
    double agglomerateGap
)
{
    liggghtsCall call;
    return colloidContactAnalysisNew(lmp_, touchingGap, releaseGap, agglomerateGap);
}


void Foam::liggghtsEngine::analyseContacts
(
    void* analysis,
    double t,
    const int* touchingWall,
    ColloidContactCounts* counts
)
{
    liggghtsCall call;
    colloidContactAnalyse(analysis, t, touchingWall, counts);
}


bool Foam::liggghtsEngine::hasPairStyle() const
{
    return engine(lmp_)->force->pair != nullptr;
}


void Foam::liggghtsEngine::box
(
    double lo[3],
    double hi[3],
    bool periodic[3]
) const
{
    const LAMMPS_NS::Domain* domain = engine(lmp_)->domain;
    for (int k = 0; k < 3; ++k)
    {
        lo[k] = domain->boxlo[k];
        hi[k] = domain->boxhi[k];
        periodic[k] = domain->periodicity[k] != 0;
    }
}


void Foam::liggghtsEngine::subBox(double lo[3], double hi[3]) const
{
    const LAMMPS_NS::Domain* domain = engine(lmp_)->domain;
    for (int k = 0; k < 3; ++k)
    {
        lo[k] = domain->sublo[k];
        hi[k] = domain->subhi[k];
    }
}


void Foam::liggghtsEngine::processorGrid(int grid[3]) const
{
    const LAMMPS_NS::Comm* comm = engine(lmp_)->comm;
    for (int k = 0; k < 3; ++k)
    {
        grid[k] = comm->procgrid[k];
    }
}


void Foam::liggghtsEngine::askedProcessorGrid(int grid[3]) const
{
    const LAMMPS_NS::Comm* comm = engine(lmp_)->comm;
    for (int k = 0; k < 3; ++k)
    {
        grid[k] = comm->user_procgrid[k];
    }
}


int Foam::liggghtsEngine::dimension() const
{
    return engine(lmp_)->domain->dimension;
}


int Foam::liggghtsEngine::rank() const
{
    return engine(lmp_)->comm->me;
}


long Foam::liggghtsEngine::timeStep() const
{
    return static_cast<long>(engine(lmp_)->update->ntimestep);
}


double Foam::liggghtsEngine::timeStepSize() const
{
    return engine(lmp_)->update->dt;
}


int Foam::liggghtsEngine::nLocal() const
{
    return engine(lmp_)->atom->nlocal;
}


long Foam::liggghtsEngine::nGlobal() const
{
    return static_cast<long>(engine(lmp_)->atom->natoms);
}


const int* Foam::liggghtsEngine::tag() const
{
    return engine(lmp_)->atom->tag;
}


double** Foam::liggghtsEngine::x() const
{
    return engine(lmp_)->atom->x;
}


double** Foam::liggghtsEngine::v() const
{
    return engine(lmp_)->atom->v;
}


double** Foam::liggghtsEngine::f() const
{
    return engine(lmp_)->atom->f;
}


double** Foam::liggghtsEngine::torque() const
{
    return engine(lmp_)->atom->torque;
}


double* Foam::liggghtsEngine::radius() const
{
    return engine(lmp_)->atom->radius;
}


double* Foam::liggghtsEngine::rmass() const
{
    return engine(lmp_)->atom->rmass;
}


double* Foam::liggghtsEngine::scalarProperty(const std::string& fixId) const
{
    LAMMPS_NS::Fix* f = findFix(lmp_, fixId);
    if (std::strcmp(f->style, "property/atom") != 0 || !f->vector_atom)
    {
        if (nLocal() == 0) return nullptr;
        throw std::runtime_error
        (
            "LIGGGHTS fix '" + fixId + "' is not a scalar property/atom"
        );
    }
    return f->vector_atom;
}


double** Foam::liggghtsEngine::vectorProperty(const std::string& fixId) const
{
    LAMMPS_NS::Fix* f = findFix(lmp_, fixId);
    if (std::strcmp(f->style, "property/atom") != 0 || !f->array_atom)
    {
        if (nLocal() == 0) return nullptr;
        throw std::runtime_error
        (
            "LIGGGHTS fix '" + fixId + "' is not a vector property/atom"
        );
    }
    return f->array_atom;
}


double* Foam::liggghtsEngine::computePerAtom(const std::string& computeId) const
{
    LAMMPS_NS::Compute* c =
        engine(lmp_)->modify->find_compute_id(computeId.c_str());
    if (!c || !c->peratom_flag)
    {
        throw std::runtime_error
        (
            "LIGGGHTS has no per-atom compute with id '" + computeId + "'"
        );
    }
    liggghtsCall call;
    c->compute_peratom();
    return c->vector_atom;
}
