#include "demCoupling.H"
#include "demUnits.H"
#include "particleVTKWriter.H"
#include "mathematicalConstants.H"
#include "Time.H"
#include "OSspecific.H"

#include <cmath>
#include <stdexcept>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

// LIGGGHTS command with a number written in full precision
std::string defineVariable(const char* name, const double value)
{
    std::ostringstream os;
    os.precision(17);
    os << "variable " << name << " equal " << value;
    return os.str();
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::demCoupling::checkTimeStep() const
{
    const Time& runTime = mesh_.time();

    // The DEM state (particles, contact histories) is not saved with the
    // time folders: a run that starts later would silently start the DEM
    // afresh
    if (runTime.startTime().value() != 0)
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "The run starts at time " << runTime.startTime().value()
            << " s (keywords 'startFrom'/'startTime' in "
            << runTime.controlDict().name() << "); colloidDEMFoam cannot"
            << " restart (the DEM state is not saved with the time"
            << " folders): start from time 0" << exit(FatalIOError);
    }
    const scalar deltaT = runTime.deltaTValue();
    const scalar couplingDt = props_.couplingTimeStep();

    if (mag(deltaT - couplingDt) > 1e-9*couplingDt)
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "Keyword 'deltaT' in " << runTime.controlDict().name()
            << " is " << deltaT << " s but must equal"
            << " DEM couplingInterval x timeStep = "
            << props_.couplingInterval() << " x " << props_.demTimeStep()
            << " = " << couplingDt << " s (" << props_.objectPath() << ")"
            << exit(FatalIOError);
    }

    // Relaxation time m/K of the particles of the settings
    const scalar d = props_.particleDiameter();
    const scalar mass =
        props_.particleDensity()*constant::mathematical::pi*pow3(d)/6;
    const scalar tau = mass/drag_->K(d, 0);
    Info<< "Time-step limit, Stokes relaxation time m/K of the particles: "
        << tau << " s; DEM timeStep " << props_.demTimeStep() << " s is "
        << props_.demTimeStep()/tau << " of it (the DEM prints its own"
        << " limits in log.liggghts)" << endl;
    checkRelaxationTime(tau);

    if (runTime.controlDict().getOrDefault<bool>("adjustTimeStep", false))
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "Keyword 'adjustTimeStep' in "
            << runTime.controlDict().name()
            << " must be 'no': the coupling step is fixed by the DEM"
            << exit(FatalIOError);
    }
}


void Foam::demCoupling::checkRelaxationTime(const scalar tau) const
{
    // LIGGGHTS applies the drag explicitly at each DEM step, which is
    // stable and smooth only for steps below the relaxation time
    if (props_.demTimeStep() > tau)
    {
        const dictionary& demDict = props_.subDict("DEM");
        FatalIOErrorInFunction(demDict)
            << "Keyword 'timeStep' in " << demDict.name() << " is "
            << props_.demTimeStep() << " s, longer than the particle"
            << " relaxation time m/K = " << tau << " s: the drag would be"
            << " unstable. Allowed range: timeStep <= " << tau
            << exit(FatalIOError);
    }
}


void Foam::demCoupling::startDEM()
{
    const Time& runTime = mesh_.time();
    const dictionary& demDict = props_.subDict("DEM");

    const fileName logFile(runTime.globalPath()/"log.liggghts");
    const fileName screenFile
    (
        props_.demScreen() ? fileName() : fileName(logFile + ".screen")
    );
    Info<< "LIGGGHTS log: " << logFile;
    if (!screenFile.empty())
    {
        Info<< ", screen output (errors on one rank): " << screenFile;
    }
    Info<< endl;

    engine_.reset(new liggghtsEngine(logFile, screenFile));
    liggghtsEngine& dem = engine_();

    // Set before the script: the script may only refine them
    dem.command(std::string("units ") + demUnits::style);
    dem.command("atom_modify map array");   // needed by fix couple/cfd

    // Case folder, for files named in the script (LIGGGHTS resolves
    // relative names from the working directory, which -case does not set)
    dem.command("variable colloid_case string " + runTime.globalPath());

    const scalar d = props_.particleDiameter()/demUnits::length;
    dem.command(defineVariable("colloid_diameter", d));
    dem.command(defineVariable("colloid_radius", 0.5*d));
    dem.command
    (
        defineVariable
        (
            "colloid_density",
            props_.particleDensity()/demUnits::density
        )
    );
    dem.command
    (
        defineVariable
        (
            "colloid_timestep",
            props_.demTimeStep()/demUnits::time
        )
    );

    Info<< "Reading DEM script " << props_.demScript() << endl;
    dem.file(props_.demScript());

    if (dem.unitStyle() != demUnits::style)
    {
        FatalIOErrorInFunction(demDict)
            << "The DEM script " << props_.demScript() << " (keyword 'script'"
            << " in " << demDict.name() << ") sets units '"
            << dem.unitStyle() << "'; the coupling needs units "
            << demUnits::style << exit(FatalIOError);
    }
    if (dem.nFixesOfStyle("gravity") > 0)
    {
        FatalIOErrorInFunction(demDict)
            << "The DEM script " << props_.demScript() << " (keyword 'script'"
            << " in " << demDict.name() << ") defines a 'fix gravity'."
            << " Gravity comes from constant/g and is applied by the"
            << " coupling: remove the fix" << exit(FatalIOError);
    }

    // The DEM step of the settings wins over any in the script
    dem.command("timestep ${colloid_timestep}");

    // Per-atom Ksl, uf (implicit drag) and dragforce (explicit force) are
    // created by couple/cfd/force/implicit; the 'mpi' data coupling leaves
    // all transfers to the caller, who writes the arrays in place.
    dem.command("fix colloidCfd all couple/cfd couple_every 0 mpi");
    dem.command("fix colloidCfdForce all couple/cfd/force/implicit");

    // Fluid rank and cell of each particle: the start of the next search
    dem.command("fix colloidCell all property/atom colloidCell vector yes no no -1 -1");

    // 0 until the coupling has counted the particle as inserted
    dem.command("fix colloidSeen all property/atom colloidSeen scalar yes no no 0");

    if (dem.hasPairStyle())
    {
        std::ostringstream os;
        os.precision(17);
        os << "compute colloidContacts all contact/atom skin "
           << touchTolerance_*0.5*d;
        dem.command(os.str());
    }

    // Full set-up (neighbour lists, initial insertion) without moving
    dem.run(0);
}


void Foam::demCoupling::countNewParticles()
{
    liggghtsEngine& dem = engine_();
    const int n = dem.nLocal();
    double* seen = dem.scalarProperty("colloidSeen");

    label nNew = 0;
    for (int i = 0; i < n; ++i)
    {
        if (seen[i] == 0)
        {
            seen[i] = 1;
            ++nNew;
        }
    }
    nInserted_ += returnReduce(nNew, sumOp<label>());
}


void Foam::demCoupling::locateLocal
(
    const bool wantWallDistance,
    pointField& position,
    vectorField& Uf,
    labelList& proc,
    labelList& cell,
    scalarField& wallDist
)
{
    liggghtsEngine& dem = engine_();
    const int n = dem.nLocal();
    double** x = dem.x();
    double* r = dem.radius();
    double** hint = dem.vectorProperty("colloidCell");

    if (n > 0 && !(r && dem.rmass()))
    {
        throw std::runtime_error
        (
            "the DEM atoms have no radius or per-atom mass:"
            " the script must use 'atom_style sphere'"
        );
    }

    position.setSize(n);
    labelList prevProc(n);
    labelList prevCell(n);
    scalarField maxWallDist(n, 0);

    // LIGGGHTS maps atoms back into a periodic box only when it rebuilds
    // its neighbour lists: locate the periodic image inside the box (the
    // fluid mesh's cyclic patches must coincide with the box faces)
    double lo[3], hi[3];
    bool periodic[3];
    dem.box(lo, hi, periodic);

    for (int i = 0; i < n; ++i)
    {
        double xi[3] = {x[i][0], x[i][1], x[i][2]};
        for (int k = 0; k < 3; ++k)
        {
            if (periodic[k])
            {
                const double L = hi[k] - lo[k];
                xi[k] -= L*std::floor((xi[k] - lo[k])/L);
            }
        }
        position[i] = demUnits::length*point(xi[0], xi[1], xi[2]);
        prevProc[i] = label(hint[i][0]);
        prevCell[i] = label(hint[i][1]);
        if (wantWallDistance)
        {
            maxWallDist[i] = (1 + touchTolerance_)*demUnits::length*r[i];
        }
    }

    exchange_.locate
    (
        position, prevProc, prevCell, maxWallDist, Uf, proc, cell, wallDist
    );

    // Store the new hints with the atoms
    for (int i = 0; i < n; ++i)
    {
        hint[i][0] = proc[i];
        hint[i][1] = cell[i];
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::demCoupling::demCoupling
(
    const volVectorField& U,
    const uniformDimensionedVectorField& g
)
:
    mesh_(U.mesh()),
    g_(g),
    props_(U.mesh()),
    drag_(dragModel::New(props_, props_.muFluid())),
    locator_(U.mesh()),
    exchange_(U, locator_),
    engine_(),
    nInserted_(0),
    demSeconds_(0),
    couplingSeconds_(0),
    particleSteps_(0)
{
    checkTimeStep();

    Info<< "Coupling: fluid rho " << props_.rhoFluid() << " kg/m^3, mu "
        << props_.muFluid() << " Pa s; particles d "
        << props_.particleDiameter() << " m, rho "
        << props_.particleDensity() << " kg/m^3" << nl
        << "    DEM step " << props_.demTimeStep() << " s, "
        << props_.couplingInterval() << " DEM steps per coupling step"
        << nl << endl;

    try
    {
        startDEM();
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << "DEM start-up failed: " << e.what() << exit(FatalError);
    }
}


Foam::demCoupling::~demCoupling()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::demCoupling::evolve()
{
    try
    {
        clockTime clock;

        countNewParticles();

        pointField position;
        vectorField Uf;
        labelList proc, cell;
        scalarField wallDist;
        locateLocal(false, position, Uf, proc, cell, wallDist);

        liggghtsEngine& dem = engine_();
        const int n = dem.nLocal();
        double** v = dem.v();
        double* r = dem.radius();
        double* m = dem.rmass();
        double* Ksl = dem.scalarProperty("Ksl");
        double** uf = dem.vectorProperty("uf");
        double** fExplicit = dem.vectorProperty("dragforce");

        const vector& g = g_.value();
        const scalar rhoF = props_.rhoFluid();

        label nOutside = 0;
        scalar tauMin = GREAT;

        for (int i = 0; i < n; ++i)
        {
            const scalar radius = demUnits::length*r[i];
            const scalar mass = demUnits::mass*m[i];
            const scalar volume =
                4.0/3.0*constant::mathematical::pi*pow3(radius);

            // Gravity and buoyancy: explicit, constant over the interval
            const vector fBody = (mass - rhoF*volume)*g;
            for (direction k = 0; k < 3; ++k)
            {
                fExplicit[i][k] = fBody[k]/demUnits::force;
            }

            if (cell[i] < 0)
            {
                ++nOutside;
                Ksl[i] = 0;
                uf[i][0] = uf[i][1] = uf[i][2] = 0;
                continue;
            }

            const vector vp(v[i][0], v[i][1], v[i][2]);
            const vector Ui = Uf[i];
            const scalar K =
                drag_->K(2*radius, mag(Ui - demUnits::velocity*vp));

            tauMin = min(tauMin, mass/K);

            Ksl[i] = K/demUnits::dragCoeff;
            for (direction k = 0; k < 3; ++k)
            {
                uf[i][k] = Ui[k]/demUnits::velocity;
            }
        }

        reduce(tauMin, minOp<scalar>());
        reduce(nOutside, sumOp<label>());

        // Particles of the script may differ from those of the settings
        checkRelaxationTime(tauMin);

        const label nTotal = returnReduce(label(n), sumOp<label>());

        Info<< "Coupling: " << nTotal
            << " particles, " << nOutside << " outside the fluid, "
            << returnReduce(locator_.nGlobalSearches(), sumOp<label>())
            << " global searches" << endl;

        couplingSeconds_ += clock.timeIncrement();

        dem.run(props_.couplingInterval());

        demSeconds_ += clock.timeIncrement();
        particleSteps_ += scalar(nTotal)*props_.couplingInterval();
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << "Coupling step failed: " << e.what() << exit(FatalError);
    }
}


void Foam::demCoupling::write()
{
    try
    {
        countNewParticles();

        pointField position;
        vectorField Uf;
        labelList proc, cell;
        scalarField wallDist;
        locateLocal(true, position, Uf, proc, cell, wallDist);

        liggghtsEngine& dem = engine_();
        const int n = dem.nLocal();
        double** v = dem.v();
        double* r = dem.radius();
        const double* contacts =
            dem.hasPairStyle() ? dem.computePerAtom("colloidContacts") : nullptr;

        const label nProcs = Pstream::nProcs();
        const label me = Pstream::myProcNo();
        List<pointField> allPosition(nProcs);
        List<vectorField> allVelocity(nProcs);
        List<scalarField> allRadius(nProcs);
        List<labelList> allTouchP(nProcs);
        List<labelList> allTouchW(nProcs);

        allPosition[me] = position;
        allVelocity[me].setSize(n);
        allRadius[me].setSize(n);
        allTouchP[me].setSize(n);
        allTouchW[me].setSize(n);
        for (int i = 0; i < n; ++i)
        {
            const scalar radius = demUnits::length*r[i];
            allVelocity[me][i] =
                demUnits::velocity*vector(v[i][0], v[i][1], v[i][2]);
            allRadius[me][i] = radius;
            allTouchP[me][i] = (contacts && contacts[i] > 0) ? 1 : 0;
            allTouchW[me][i] =
                (wallDist[i] <= (1 + touchTolerance_)*radius) ? 1 : 0;
        }

        // Output only: particles gathered on the master for one file
        Pstream::gatherList(allPosition);
        Pstream::gatherList(allVelocity);
        Pstream::gatherList(allRadius);
        Pstream::gatherList(allTouchP);
        Pstream::gatherList(allTouchW);

        const label nPresent = returnReduce(label(n), sumOp<label>());

        // The searches of this output are not those of a coupling step
        locator_.nGlobalSearches();

        if (Pstream::master())
        {
            const Time& runTime = mesh_.time();
            const fileName file
            (
                runTime.globalPath()/"VTK"
               /("particles_" + Foam::name(runTime.timeIndex()) + ".vtk")
            );

            particleVTKWriter::write
            (
                file,
                "colloidDEMFoam particles, time " + runTime.timeName() + " s",
                ListListOps::combine<pointField>
                (
                    allPosition, accessOp<pointField>()
                ),
                ListListOps::combine<vectorField>
                (
                    allVelocity, accessOp<vectorField>()
                ),
                ListListOps::combine<scalarField>
                (
                    allRadius, accessOp<scalarField>()
                ),
                ListListOps::combine<labelList>
                (
                    allTouchP, accessOp<labelList>()
                ),
                ListListOps::combine<labelList>
                (
                    allTouchW, accessOp<labelList>()
                )
            );
        }

        // Removed: counted by the DEM's outflow fixes (massflow/mesh with
        // delete_atoms yes), independently of the two other counts
        const label nRemoved =
            label(std::lround(dem.sumFixVector("massflow/mesh", 5)));

        Info<< "Particles: present " << nPresent
            << ", inserted " << nInserted_
            << ", removed " << nRemoved << endl;

        if (nPresent != nInserted_ - nRemoved)
        {
            WarningInFunction
                << "present " << nPresent << " != inserted " << nInserted_
                << " - removed " << nRemoved << ": particles were lost"
                << " other than through a massflow/mesh outflow"
                << " (e.g. 'thermo_modify lost ignore' in the DEM script)"
                << endl;
        }

        if (demSeconds_ > 0)
        {
            const scalar total = demSeconds_ + couplingSeconds_;
            Info<< "Timing (master, wall clock): DEM " << demSeconds_
                << " s, coupling " << couplingSeconds_ << " s; "
                << particleSteps_/total/Pstream::nProcs()
                << " particle-steps per second per rank" << endl;
        }
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << "Writing particles failed: " << e.what() << exit(FatalError);
    }
}
