#include "demCoupling.H"
#include "measuredErrors.H"
#include "colloidModels/exchangeStability.H"
#include "demUnits.H"
#include "liggghtsColloid/colloid_drag_properties.h"
#include "particleCloudWriter.H"
#include "initialOverlaps.H"
#include "atomicFileOperation.H"
#include "OStringStream.H"
#include "fvcGrad.H"
#include "fvcLaplacian.H"
#include "fvcDiv.H"
#include "zeroGradientFvPatchFields.H"
#include "mathematicalConstants.H"
#include "Time.H"
#include "OSspecific.H"

#include <cmath>
#include <stdexcept>
#include <sstream>
#include <utility>

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

Foam::particleContext Foam::demCoupling::restContext
(
    const scalar radius,
    const scalar mass,
    const vector& v
) const
{
    particleContext c;
    c.d = 2*radius;
    c.volume = 4.0/3.0*constant::mathematical::pi*pow3(radius);
    c.mass = mass;
    c.v = v;
    c.U = c.gradp = c.divTau = Zero;
    c.eps = 1;
    c.rho = props_.rhoFluid();
    c.mu = props_.muFluid();
    c.g = g_.value();
    c.cell = -1;
    return c;
}


void Foam::demCoupling::checkTimeStep() const
{
    const Time& runTime = mesh_.time();

    // OpenFOAM deletes the oldest time folder as soon as the new fields
    // are written, before the new DEM state is complete: a write that
    // then failed would leave nothing to resume from
    const label purge =
        runTime.controlDict().getOrDefault<label>("purgeWrite", 0);
    if (purge != 0)
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "Keyword 'purgeWrite' in " << runTime.controlDict().name()
            << " is " << purge << "; colloidDEMFoam needs 0 (OpenFOAM would"
            << " delete the oldest time folder before the new one's DEM"
            << " state is complete).  Delete old time folders yourself"
            << exit(FatalIOError);
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

    // Relaxation time m/K of the particles of the settings; with a size
    // range at both its ends (m/K grows as d^2 with Stokes' drag, but a
    // drag law need not keep that order), each end checked
    const scalarList diameters
    (
        props_.sizeRange()
      ? scalarList({props_.smallestDiameter(), props_.largestDiameter()})
      : scalarList({props_.particleDiameter()})
    );
    for (const scalar d : diameters)
    {
        const scalar mass = settingsMass(d);
        const scalar tau = mass/drag_->K(restContext(0.5*d, mass, Zero));
        Info<< "Time-step limit, Stokes relaxation time m/K of the particles";
        if (props_.sizeRange())
        {
            Info<< " of diameter " << d << " m";
        }
        Info<< ": " << tau << " s; DEM timeStep " << props_.demTimeStep()
            << " s is " << props_.demTimeStep()/tau << " of it (the DEM"
            << " prints its own limits in log.liggghts)" << endl;
        checkRelaxationTime(tau, d);
        if (props_.twoWay())
        {
            checkExchangeStability(d);
        }
    }
    reportMeasuredErrors(runTime);

    if (runTime.controlDict().getOrDefault<bool>("adjustTimeStep", false))
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "Keyword 'adjustTimeStep' in "
            << runTime.controlDict().name()
            << " must be 'no': the coupling step is fixed by the DEM"
            << exit(FatalIOError);
    }
}


Foam::scalar Foam::demCoupling::settingsMass(const scalar d) const
{
    return props_.particleDensity()*constant::mathematical::pi*pow3(d)/6;
}


void Foam::demCoupling::checkRelaxationTime
(
    const scalar tau,
    const scalar d
) const
{
    // The DEM applies the drag implicitly (stable at any step), but the
    // particle's inertia is resolved, and the drift accurate to about 1 %,
    // only for steps up to the relaxation time
    if (props_.demTimeStep() > tau)
    {
        const dictionary& demDict = props_.subDict("DEM");
        FatalIOErrorInFunction(demDict)
            << "Keyword 'timeStep' in " << demDict.name() << " is "
            << props_.demTimeStep() << " s, longer than the relaxation"
            << " time m/K = " << tau << " s of ";
        if (d > 0)
        {
            FatalIOError<< "particles of diameter " << d << " m";
        }
        else
        {
            FatalIOError<< "the run's particles";
        }
        FatalIOError
            << ": the particle's"
            << " inertia would not be resolved. Allowed range: timeStep <= "
            << tau
            << exit(FatalIOError);
    }
}


void Foam::demCoupling::checkExchangeStability(const scalar d) const
{
    // The fluid step and its DEM interval see each other a step late; over
    // free particles (looser than random loose packing, or than the case's
    // twoWay/freeFluidFraction) the lag amplifies a disturbance once the
    // fluid step is about a relaxation time (exchangeStability.H).  Model
    // B's drag is K/eps.
    const scalar mass = settingsMass(d);
    const bool modelB = props_.modelB();
    const auto tau = [&](const double eps)
    {
        particleContext c(restContext(0.5*d, mass, Zero));
        c.eps = eps;
        return (modelB ? eps : 1.0)*mass/drag_->K(c);
    };
    const scalar epsFree = props_.freeFluidFraction();
    const colloid::exchangeStability::StepLimit limit =
        colloid::exchangeStability::largestStableStep
        (
            tau,
            modelB,
            props_.rhoFluid()/props_.particleDensity(),
            epsFree
        );

    const scalar couplingDt = props_.couplingTimeStep();
    Info<< "Time-step limit, explicit two-way exchange over free particles";
    if (props_.sizeRange())
    {
        Info<< " of diameter " << d << " m";
    }
    Info<< " at fluid fractions " << epsFree << " to 1 (twoWay/"
        << "freeFluidFraction): ";
    if (std::isinf(limit.step))
    {
        Info<< "none, stable at any fluid step (fluid step " << couplingDt
            << " s)" << endl;
        return;
    }
    Info<< "fluid step <= " << limit.step << " s (set at fluid fraction "
        << limit.eps << "); fluid step " << couplingDt << " s is "
        << couplingDt/limit.step << " of it" << endl;

    if (couplingDt > limit.step)
    {
        const dictionary& demDict = props_.subDict("DEM");
        const label maxInterval =
            label(limit.step/props_.demTimeStep()*(1 + 1e-12));
        FatalIOErrorInFunction(demDict)
            << "Keyword 'couplingInterval' in " << demDict.name() << " is "
            << props_.couplingInterval() << ": the fluid step "
            << props_.couplingInterval() << " x " << props_.demTimeStep()
            << " = " << couplingDt << " s is longer than the largest step "
            << limit.step << " s at which the explicit two-way exchange is"
            << " stable: a layer of free particles at fluid fraction "
            << limit.eps << " would be blown apart.  Allowed range: ";
        if (maxInterval >= 1)
        {
            FatalIOError
                << "couplingInterval <= " << maxInterval;
        }
        else if (limit.step > 0)
        {
            FatalIOError
                << "none at this DEM timeStep; the fluid step must be <= "
                << limit.step << " s (a shorter DEM 'timeStep' and"
                << " couplingInterval 1)";
        }
        else
        {
            // Lagged fluid acceleration on dense, light particles: an
            // added-mass instability at any step (exchangeStability.H)
            FatalIOError
                << "none: that layer is unstable at any fluid step";
        }
        FatalIOError
            << " (or, if no particles of this case move freely at fluid"
            << " fractions below " << epsFree << ", state the densest"
            << " that do as twoWay/freeFluidFraction)"
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

    // Resuming, each rank's DEM file is that of the rank it had in
    // LIGGGHTS; a fresh start takes LIGGGHTS' order, then maybe another
    if (restart_.resume())
    {
        demGrid_ = restart_.demGrid();
        openDEM(logFile, screenFile, restart_.demRank(), demGrid_);
        if (demGrid_[0] > 0)
        {
            Info<< "DEM subdomains: a grid of " << demGrid_ << ", as the"
                << " written run asked of LIGGGHTS" << endl;
        }
    }
    else
    {
        openDEM(logFile, screenFile, -1, demGrid_);
    }
    if (Pstream::parRun() && !restart_.resume())
    {
        const label demRank = chooseDEMDecomposition();
        if
        (
            demGrid_[0] > 0
         || returnReduce(demRank != Pstream::myProcNo(), orOp<bool>())
        )
        {
            // LIGGGHTS gives its subdomains to its ranks in their order:
            // open it again with that grid and its ranks in the matching
            // order (the script runs a second time; the log is the second
            // run's)
            Info<< "Opening LIGGGHTS again with these subdomains" << endl;
            engine_.clear();
            openDEM(logFile, screenFile, demRank, demGrid_);

            // A script whose processors command has only '*' (one with
            // numbers is kept, chooseDEMDecomposition) overrides the grid
            // asked: the ranks matched to the subdomains it made instead
            // (the same command is asked on resuming, so the same grid)
            int grid[3];
            engine_->processorGrid(grid);
            if
            (
                demGrid_[0] > 0
             && (grid[0] != demGrid_[0] || grid[1] != demGrid_[1]
              || grid[2] != demGrid_[2])
            )
            {
                WarningInFunction
                    << "LIGGGHTS was asked for a grid of " << demGrid_
                    << " subdomains and made " << grid[0] << ' ' << grid[1]
                    << ' ' << grid[2] << ": the DEM script "
                    << props_.demScript() << " has a processors command of"
                    << " its own; its ranks are matched to those subdomains"
                    << endl;
                const label madeRank = matchMadeSubdomains();
                if
                (
                    returnReduce
                    (
                        madeRank != engine_->rank(), orOp<bool>()
                    )
                )
                {
                    Info<< "Opening LIGGGHTS again with its ranks in that"
                        << " order" << endl;
                    engine_.clear();
                    openDEM(logFile, screenFile, madeRank, demGrid_);
                }
            }

            // What it made of them
            const List<scalarList> overlap = fluidInBoxes(demSubdomains());
            scalar total = 0, same = 0;
            forAll(overlap, f)
            {
                total += sum(overlap[f]);
                same += overlap[f][f];
            }
            Info<< "DEM subdomains: grid " << grid[0] << ' ' << grid[1]
                << ' ' << grid[2] << ", " << 100*same/max(total, VSMALL)
                << " % of the fluid volume in the DEM box on the rank of its"
                << " DEM subdomain" << endl;
        }
    }
    liggghtsEngine& dem = engine_();

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

    // The drag handed to the DEM, per atom (colloid_drag_properties.h):
    // coefficient and fluid velocity of the implicit part, explicit force,
    // and the impulse the implicit update applied since the last exchange
    // (fix id = property name)
    dem.command
    (
        std::string("fix ") + colloidDrag::coefficient + " all property/atom "
      + colloidDrag::coefficient + " scalar yes no no 0"
    );
    for
    (
        const char* name
      : {colloidDrag::fluidVelocity, colloidDrag::explicitForce, colloidDrag::impulse}
    )
    {
        dem.command(std::string("fix ") + name + " all property/atom " + name + " vector yes no no 0 0 0");
    }

    // 1 once the coupling has set an atom's drag; 0 for those inserted
    // since, whose drag the plugin then asks for (coupleInserted)
    dem.command
    (
        std::string("fix ") + colloidDrag::assigned + " all property/atom "
      + colloidDrag::assigned + " scalar yes no no 0"
    );

    // Fluid rank and cell of each particle: the start of the next search
    dem.command("fix colloidCell all property/atom colloidCell vector yes no no -1 -1");

    // 0 until the coupling has counted the particle as inserted
    dem.command("fix colloidSeen all property/atom colloidSeen scalar yes no no 0");

    if (dem.hasPairStyle())
    {
        std::ostringstream os;
        os.precision(17);
        os << "compute colloidContacts all contact/atom skin "
           << touchTolerance_*0.5*props_.particleDiameter()/demUnits::length;
        dem.command(os.str());
    }

    // Brownian motion: the plugin's drag update reads these properties;
    // couplingProperties is their one source
    if (props_.brownianTemperature() > 0)
    {
        for (const char* name : {"brownianTemperature", "brownianSeed"})
        {
            if (dem.hasGlobalProperty(name))
            {
                FatalIOErrorInFunction(props_)
                    << "Brownian motion is set in " << props_.name()
                    << " (brownian), and the DEM script "
                    << props_.demScript() << " defines property " << name
                    << " too: remove it from the script" << exit(FatalIOError);
            }
        }
        std::ostringstream os;
        os.precision(17);
        os  << "fix colloidBrownianTemperature all property/global"
            << " brownianTemperature scalar " << props_.brownianTemperature();
        dem.command(os.str());
        dem.command
        (
            "fix colloidBrownianSeed all property/global brownianSeed scalar "
          + std::to_string(props_.brownianSeed())
        );
        Info<< "Brownian motion: " << props_.brownianTemperature()
            << " K, seed " << props_.brownianSeed() << endl;
    }

    restart_.addFixes(dem);
    dem.implicitDamping();

    // A fresh start's particles, before LIGGGHTS' set-up meets them
    if (!restart_.resume())
    {
        checkInitialOverlaps(dem, props_.demScript());
    }

    // Before the first run: the analysis adds a per-atom property
    if (props_.contactAnalysis())
    {
        contacts_.reset(new contactAnalysis(props_, dem, mesh_.time()));
    }

    // Full set-up (neighbour lists, initial insertion) without moving
    dem.run(0);

    // Resuming: the script read the state; the last step's force back
    nInserted_ = restart_.restored(dem, props_.demScript());

    // ... and the contacts' starts, so that durations go on
    if (restart_.resume() && contacts_.valid())
    {
        contacts_->loadHistories
        (
            restart_.contactHistoryFile(),
            mesh_.time().value()
        );
    }
}


void Foam::demCoupling::openDEM
(
    const fileName& logFile,
    const fileName& screenFile,
    const label demRank,
    const FixedList<label, 3>& grid
)
{
    const Time& runTime = mesh_.time();

    engine_.reset(new liggghtsEngine(logFile, screenFile, demRank));
    liggghtsEngine& dem = engine_();

    if (grid[0] > 0)
    {
        // Subdomain (i, j, k) on LIGGGHTS rank i + Px (j + Py k)
        dem.command
        (
            "processors " + std::to_string(grid[0]) + " "
          + std::to_string(grid[1]) + " " + std::to_string(grid[2])
          + " map xyz"
        );
    }

    // Set before the script: the script may only refine them
    dem.command(std::string("units ") + demUnits::style);
    dem.command("atom_modify map array");   // atom ids to local indices

    // Case folder, for files named in the script (LIGGGHTS resolves
    // relative names from the working directory, which -case does not set)
    dem.command("variable colloid_case string " + runTime.globalPath());

    // The particles', the fluid's (for the DEM's own liquid models, e.g.
    // the plugin's lubrication viscosity: one source for rho and mu) and
    // the DEM step, in the DEM's units
    const scalar d = props_.particleDiameter()/demUnits::length;
    const std::pair<const char*, scalar> variables[] =
    {
        {"colloid_diameter", d},
        {"colloid_radius", 0.5*d},
        {"colloid_density", props_.particleDensity()/demUnits::density},
        {"colloid_fluid_density", props_.rhoFluid()/demUnits::density},
        {"colloid_fluid_viscosity", props_.muFluid()/demUnits::viscosity},
        {"colloid_timestep", props_.demTimeStep()/demUnits::time}
    };
    for (const auto& variable : variables)
    {
        dem.command(defineVariable(variable.first, variable.second));
    }

    // Fresh start or resume (colloid_restart, colloid_restart_file)
    restart_.defineVariables(dem);

    Info<< "Reading DEM script " << props_.demScript() << endl;
    dem.file(props_.demScript());
}


Foam::List<Foam::boundBox> Foam::demCoupling::demSubdomains() const
{
    double lo[3], hi[3];
    engine_->subBox(lo, hi);
    List<boundBox> boxes(Pstream::nProcs());
    boxes[Pstream::myProcNo()] = boundBox
    (
        demUnits::length*point(lo[0], lo[1], lo[2]),
        demUnits::length*point(hi[0], hi[1], hi[2])
    );
    Pstream::gatherList(boxes);
    Pstream::scatterList(boxes);
    return boxes;
}


Foam::List<Foam::scalarList> Foam::demCoupling::fluidInBoxes
(
    const List<boundBox>& boxes
) const
{
    const label me = Pstream::myProcNo();
    List<scalarList> overlap(Pstream::nProcs());
    overlap[me].setSize(boxes.size(), 0);
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    forAll(C, celli)
    {
        forAll(boxes, d)
        {
            if (boxes[d].contains(C[celli]))
            {
                overlap[me][d] += V[celli];
                break;
            }
        }
    }
    Pstream::gatherList(overlap);
    Pstream::scatterList(overlap);
    return overlap;
}


namespace
{

// Each fluid rank's box, the largest overlap first (every rank computes
// the same answer), and the fluid volume on the rank of its box
Foam::labelList matchBoxes
(
    const Foam::List<Foam::scalarList>& overlap,
    Foam::scalar& matched
)
{
    using namespace Foam;
    const label n = overlap.size();
    labelList boxOf(n, -1);
    labelList fluidOf(n, -1);
    for (label m = 0; m < n; ++m)
    {
        scalar best = -1;
        label bestF = -1, bestD = -1;
        for (label f = 0; f < n; ++f)
        {
            for (label d = 0; d < n && boxOf[f] < 0; ++d)
            {
                if (fluidOf[d] < 0 && overlap[f][d] > best)
                {
                    best = overlap[f][d];
                    bestF = f;
                    bestD = d;
                }
            }
        }
        boxOf[bestF] = bestD;
        fluidOf[bestD] = bestF;
    }
    matched = 0;
    for (label f = 0; f < n; ++f)
    {
        matched += overlap[f][boxOf[f]];
    }
    return boxOf;
}

} // End anonymous namespace


Foam::label Foam::demCoupling::chooseDEMDecomposition()
{
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();

    // LIGGGHTS' own subdomains, one per rank (boxes, not particles)
    const List<scalarList> overlap = fluidInBoxes(demSubdomains());
    scalar matched = 0;
    const labelList boxOf = matchBoxes(overlap, matched);
    scalar total = 0, same = 0;
    forAll(overlap, f)
    {
        total += sum(overlap[f]);
        same += overlap[f][f];
    }
    total = max(total, VSMALL);

    int grid[3];
    engine_->processorGrid(grid);
    Info<< "DEM subdomains and fluid parts: " << 100*same/total
        << " % of the fluid volume in the DEM box is on the rank of its"
        << " DEM subdomain in LIGGGHTS' order (grid " << grid[0] << ' '
        << grid[1] << ' ' << grid[2] << ")";

    // LIGGGHTS' own order unless the matching is better
    const bool reorder = matched > same + 1e-9*total;
    scalar best = reorder ? matched : same;
    label demRank = reorder ? boxOf[me] : me;
    if (reorder)
    {
        Info<< ", " << 100*matched/total << " % with each subdomain on the"
            << " rank that holds most of its cells";
    }
    Info<< endl;

    // A DEM script whose processors command gives numbers keeps its grid
    // (a command asked before the script would be overridden by it)
    int asked[3];
    engine_->askedProcessorGrid(asked);
    if (asked[0] || asked[1] || asked[2])
    {
        Info<< "DEM subdomains: the DEM script " << props_.demScript()
            << " asks for a grid of " << asked[0] << ' ' << asked[1] << ' '
            << asked[2] << " (0: any): kept" << endl;
        return demRank;
    }

    // Every other grid of equal subdomains of the box (LIGGGHTS splits it
    // evenly unless told otherwise), its subdomain (i, j, k) on LIGGGHTS
    // rank i + Px (j + Py k) ('map xyz'), each matched to a fluid rank
    double lo[3], hi[3];
    bool periodic[3];
    engine_->box(lo, hi, periodic);
    const point boxLo = demUnits::length*point(lo[0], lo[1], lo[2]);
    const vector boxSpan =
        demUnits::length*point(hi[0], hi[1], hi[2]) - boxLo;
    const bool flat = engine_->dimension() == 2;
    for (label px = 1; px <= nProcs; ++px)
    {
        for (label py = 1; px*py <= nProcs; ++py)
        {
            const label pz = nProcs/(px*py);
            if
            (
                px*py*pz != nProcs || (flat && pz != 1)
             || (px == grid[0] && py == grid[1] && pz == grid[2])
            )
            {
                continue;
            }
            List<boundBox> even(nProcs);
            for (label k = 0; k < pz; ++k)
            {
                for (label j = 0; j < py; ++j)
                {
                    for (label i = 0; i < px; ++i)
                    {
                        const vector a
                        (
                            scalar(i)/px, scalar(j)/py, scalar(k)/pz
                        );
                        const vector b
                        (
                            scalar(i + 1)/px, scalar(j + 1)/py,
                            scalar(k + 1)/pz
                        );
                        even[i + px*(j + py*k)] = boundBox
                        (
                            boxLo + cmptMultiply(a, boxSpan),
                            boxLo + cmptMultiply(b, boxSpan)
                        );
                    }
                }
            }
            scalar evenMatched = 0;
            const labelList evenBoxOf =
                matchBoxes(fluidInBoxes(even), evenMatched);
            if (evenMatched > best + 0.01*total)
            {
                best = evenMatched;
                demRank = evenBoxOf[me];
                demGrid_ = FixedList<label, 3>({px, py, pz});
            }
        }
    }
    if (demGrid_[0] > 0)
    {
        Info<< "DEM subdomains: a grid of " << demGrid_ << " equal"
            << " subdomains puts " << 100*best/total << " % of the fluid"
            << " volume on the rank of its subdomain" << endl;
    }

    return demRank;
}


Foam::label Foam::demCoupling::matchMadeSubdomains() const
{
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();

    // Each rank's subdomain and its rank in LIGGGHTS
    const List<boundBox> boxes = demSubdomains();
    labelList demRanks(nProcs);
    demRanks[me] = engine_->rank();
    Pstream::gatherList(demRanks);
    Pstream::scatterList(demRanks);

    // The subdomains by LIGGGHTS rank, each matched to a fluid rank
    List<boundBox> byDemRank(nProcs);
    forAll(boxes, w)
    {
        byDemRank[demRanks[w]] = boxes[w];
    }
    scalar matched = 0;
    return matchBoxes(fluidInBoxes(byDemRank), matched)[me];
}


void Foam::demCoupling::analyseContacts(const scalarField& wallDist)
{
    if (!contacts_.valid() || analysedAt_ == mesh_.time().timeIndex())
    {
        return;
    }
    clockTime clock;
    const double* r = engine_().radius();
    // 1: touching a wall; 2: within the release gap of one (a wall
    // contact already formed lasts)
    labelList touchingWall(wallDist.size(), 0);
    forAll(touchingWall, i)
    {
        const scalar radius = demUnits::length*r[i];
        touchingWall[i] =
            wallDist[i] < (1 + props_.touchingGap())*radius ? 1
          : wallDist[i] < (1 + props_.releaseGap())*radius ? 2
          : 0;
    }
    contacts_->analyse(engine_(), mesh_.time().value(), touchingWall);
    analysedAt_ = mesh_.time().timeIndex();
    analysisSeconds_ += clock.timeIncrement();
    ++nAnalyses_;
}


void Foam::demCoupling::countNewParticles()
{
    liggghtsEngine& dem = engine_();
    const int n = dem.nLocal();
    double* seen = dem.scalarProperty("colloidSeen");

    // The particles of the settings: the start-up checks (time-step
    // limits at both ends of diameterRange) are made for them
    const double* r = dem.radius();
    const double* m = dem.rmass();
    const scalar dMin = props_.smallestDiameter();
    const scalar dMax = props_.largestDiameter();
    const scalar rho = props_.particleDensity();
    label nNew = 0;
    label nOther = 0;
    scalar otherD = 0, otherRho = 0;
    DynamicList<label> newAtoms;    // local indices; empty on most steps
    for (int i = 0; i < n; ++i)
    {
        if (seen[i] == 0)
        {
            seen[i] = 1;
            newAtoms.append(i);
            ++nNew;
            const scalar di = 2*demUnits::length*r[i];
            const scalar rhoi =
                demUnits::mass*m[i]
               /(constant::mathematical::pi/6*pow3(di));
            if
            (
                di < (1 - 1e-6)*dMin
             || di > (1 + 1e-6)*dMax
             || mag(rhoi - rho) > 1e-6*rho
            )
            {
                ++nOther;
                otherD = di;
                otherRho = rhoi;
            }
        }
    }
    const label nNewAll = returnReduce(nNew, sumOp<label>());
    nInserted_ += nNewAll;

    // The particles the script inserted during the run (those present at
    // the start were checked before the first run): their smallest gap,
    // in the log, and no overlap
    if (startCounted_ && nNewAll)
    {
        boolList inserted(n, false);
        UIndirectList<bool>(inserted, newAtoms) = true;
        checkInitialOverlaps(dem, props_.demScript(), &inserted);
    }
    startCounted_ = true;

    if (returnReduce(nOther, sumOp<label>()))
    {
        const dictionary& particles = props_.subDict("particles");
        FatalIOErrorInFunction(particles)
            << returnReduce(nOther, sumOp<label>()) << " particles of the"
            << " DEM (e.g. diameter " << returnReduce(otherD, maxOp<scalar>())
            << " m, density " << returnReduce(otherRho, maxOp<scalar>())
            << " kg/m^3) are not those of " << particles.name()
            << " (";
        if (props_.sizeRange())
        {
            FatalIOError
                << "diameterRange (" << dMin << " " << dMax << ") m";
        }
        else
        {
            FatalIOError<< "diameter " << dMin << " m";
        }
        FatalIOError
            << ", density " << rho << " kg/m^3), for which the start-up"
            << " checks were made: set the DEM's particles from"
            << " colloid_diameter and colloid_density, or change 'diameter',"
            << " 'diameterRange' and 'density' there"
            << exit(FatalIOError);
    }
}


void Foam::demCoupling::locateLocal
(
    const scalar wallRange,
    pointField& position,
    labelList& proc,
    labelList& cell,
    scalarField& wallDist
)
{
    locateAtoms
    (
        identity(engine_().nLocal()), wallRange, position, proc, cell, wallDist
    );
}


void Foam::demCoupling::locateAtoms
(
    const labelUList& atoms,
    const scalar wallRange,
    pointField& position,
    labelList& proc,
    labelList& cell,
    scalarField& wallDist
)
{
    liggghtsEngine& dem = engine_();
    const label n = atoms.size();
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

    forAll(atoms, k)
    {
        const label i = atoms[k];
        double xi[3] = {x[i][0], x[i][1], x[i][2]};
        for (int d = 0; d < 3; ++d)
        {
            if (periodic[d])
            {
                const double L = hi[d] - lo[d];
                xi[d] -= L*std::floor((xi[d] - lo[d])/L);
            }
        }
        position[k] = demUnits::length*point(xi[0], xi[1], xi[2]);
        prevProc[k] = label(hint[i][0]);
        prevCell[k] = label(hint[i][1]);
        if (wallRange > 0)
        {
            maxWallDist[k] = (1 + wallRange)*demUnits::length*r[i];
        }
    }

    exchange_.locate
    (
        position, prevProc, prevCell, maxWallDist, proc, cell, wallDist
    );

    // Store the new hints with the atoms
    forAll(atoms, k)
    {
        hint[atoms[k]][0] = proc[k];
        hint[atoms[k]][1] = cell[k];
    }
}


void Foam::demCoupling::checkTransientSetup() const
{
    const dictionary& ddt = mesh_.schemesDict().subDict("ddtSchemes");
    word scheme("none");
    if (ddt.found("default"))
    {
        ITstream& is = ddt.lookup("default");
        is >> scheme;
    }
    // Euler only: the start-up limit of the explicit exchange on the
    // fluid step (exchangeStability.H) is derived for it; with backward,
    // d(eps)/dt draws on two intervals and dense free layers of Model B
    // are unstable up to eps = 2/3 instead of 0.5
    if (scheme != "Euler")
    {
        FatalIOErrorInFunction(ddt)
            << "couplingMode twoWay solves the fluid in time with the"
            << " exchange's stability limit derived for Euler: keyword"
            << " 'default' of ddtSchemes in " << ddt.name() << " is '"
            << scheme << "'; allowed: Euler"
            << exit(FatalIOError);
    }

    const dictionary& solution = mesh_.solutionDict();
    if (!solution.isDict("PIMPLE"))
    {
        FatalIOErrorInFunction(solution)
            << "couplingMode twoWay needs a 'PIMPLE' dictionary in "
            << solution.name() << " (nOuterCorrectors, nCorrectors,"
            << " nNonOrthogonalCorrectors)" << exit(FatalIOError);
    }
    const dictionary& solvers = solution.subDict("solvers");
    for (const char* field : {"p", "U"})
    {
        if (!solvers.found(field))
        {
            FatalIOErrorInFunction(solvers)
                << "couplingMode twoWay needs a linear solver for '"
                << field << "' in " << solvers.name()
                << exit(FatalIOError);
        }
    }
    if (!p_)
    {
        FatalErrorInFunction
            << "couplingMode twoWay needs the pressure field p in "
            << mesh_.time().timeName() << exit(FatalError);
    }
}


void Foam::demCoupling::checkForceModels() const
{
    bool pressureForce = false;
    for (const forceModel& model : forces_)
    {
        pressureForce = pressureForce || model.needsPressureGradient();
    }
    if (props_.twoWay() && !props_.modelB() && !pressureForce)
    {
        FatalIOErrorInFunction(props_)
            << "Keyword 'forceModels' in " << props_.objectPath()
            << " lacks 'pressureGradient', which modelType A needs: its"
            << " fluid feels -eps grad p, so the particles must feel"
            << " -V grad p (or use modelType B)" << exit(FatalIOError);
    }

    for (const forceModel& model : forces_)
    {
        if (model.modelAOnly() && props_.modelB())
        {
            FatalIOErrorInFunction(props_)
                << "Force model '" << model.type() << "' (keyword"
                << " 'forceModels' in " << props_.objectPath() << ") with"
                << " modelType B: Model B's drag (K/eps) carries the"
                << " pressure and viscous forces; remove it, or use"
                << " modelType A" << exit(FatalIOError);
        }
        if (model.needsPressureGradient() && !p_)
        {
            FatalIOErrorInFunction(props_)
                << "Force model '" << model.type() << "' (keyword"
                << " 'forceModels' in " << props_.objectPath() << ") needs the"
                << " pressure field p, which is not in "
                << mesh_.time().timeName() << exit(FatalIOError);
        }
    }
}


void Foam::demCoupling::gatherRecords
(
    const scalar wallRange,
    scalarField& wallDist
)
{
    clockTime clock;
    countNewParticles();

    pointField position;
    labelList cell;
    locateLocal(wallRange, position, proc_, cell, wallDist);
    stageSeconds_[locateStage] += clock.timeIncrement();

    liggghtsEngine& dem = engine_();
    const int n = dem.nLocal();
    double** v = dem.v();
    double* r = dem.radius();
    double* m = dem.rmass();
    double* Ksl = dem.scalarProperty(colloidDrag::coefficient);
    double** impulse = dem.vectorProperty(colloidDrag::impulse);

    const scalar T = props_.couplingTimeStep()/demUnits::time;

    scalarField radius(n), mass(n), K(n);
    vectorField velocity(n), F(n);
    for (int i = 0; i < n; ++i)
    {
        radius[i] = demUnits::length*r[i];
        mass[i] = demUnits::mass*m[i];
        velocity[i] = demUnits::velocity*vector(v[i][0], v[i][1], v[i][2]);
        K[i] = demUnits::dragCoeff*Ksl[i];

        // Drag impulse of the interval / T, as the DEM applied it (for a
        // particle inserted during the interval: from its first step)
        F[i] = demUnits::force/T*vector(impulse[i][0], impulse[i][1], impulse[i][2]);
    }

    records_.gather(proc_, cell, position, radius, mass, velocity, K, F);
    nRecordsGathered_ += n;
    nRecordsAway_ += records_.nSentAway();
    stageSeconds_[recordsStage] += clock.timeIncrement();

    if (props_.twoWay())
    {
        depositRecords();
        stageSeconds_[depositStage] += clock.timeIncrement();
    }
}


void Foam::demCoupling::depositRecords()
{
    scalarField solidVolume(mesh_.nCells(), 0);
    scalarField Kc(mesh_.nCells(), 0);
    vectorField Fc(mesh_.nCells(), Zero);

    deposit_->deposit
    (
        records_.position, records_.cell, records_.radius,
        records_.dragCoeff, records_.dragForce,
        solidVolume, Kc, Fc
    );

    const scalarField& V = mesh_.V();
    const scalar rho = props_.rhoFluid();
    const scalar epsMin = props_.epsilonMin();

    scalarField& eps = voidfraction_->primitiveFieldRef();
    label nClipped = 0;
    forAll(eps, celli)
    {
        eps[celli] = 1 - solidVolume[celli]/V[celli];
        if (eps[celli] < epsMin)
        {
            eps[celli] = epsMin;
            ++nClipped;
        }
    }
    voidfraction_->correctBoundaryConditions();

    Kexchange_->primitiveFieldRef() = Kc/(rho*V);
    Kexchange_->correctBoundaryConditions();
    Fexchange_->primitiveFieldRef() = -Fc/(rho*V);
    Fexchange_->correctBoundaryConditions();

    // The bookkeeping the momentum test reads: what the particles received
    // (sum over records) against what the cells hold (sum over cells)
    const scalar particleVolume = returnReduce
    (
        sum(4.0/3.0*constant::mathematical::pi*pow3(records_.radius)),
        sumOp<scalar>()
    );
    const scalar solid = gSum(solidVolume);
    Info<< "Fluid fraction: min " << gMin(eps) << ", solid volume "
        << solid << " m^3 of particles' " << particleVolume
        << " m^3 (relative difference "
        << mag(solid - particleVolume)/max(particleVolume, VSMALL) << ")";
    const label nClippedAll = returnReduce(nClipped, sumOp<label>());
    if (nClippedAll && !props_.clipFluidFraction())
    {
        // The fluid would no longer hold the particles' volume: stop
        // rather than go on with a wrong mass balance (a filter cake that
        // collapsed into one cell did so at 1.74 ms of the filtration
        // tutorial at default size, and its particles were then blown
        // off the medium)
        FatalErrorInFunction
            << "At time " << mesh_.time().timeName() << " s the particles"
            << " leave less fluid than twoWay/epsilonMin " << epsMin
            << " in " << nClippedAll << " cells (lowest "
            << gMin(1 - solidVolume/V) << ") of constant/couplingProperties:"
            << " the fluid fraction would be clipped and the fluid would no"
            << " longer hold the particles' volume.  Lower epsilonMin (in"
            << " (0, 1)), spread the particles over more of the mesh"
            << " (twoWay/kernel satellite with a larger twoWay/kernelRadius"
            << " [m]), or set twoWay/clipFluidFraction"
            << " yes to clip and go on" << exit(FatalError);
    }
    if (nClippedAll)
    {
        Info<< "; " << nClippedAll << " cells clipped at epsilonMin " << epsMin;
    }
    const vector onParticles = gSum(records_.dragForce);
    const vector onFluid = -gSum(Fc);
    Info<< nl << "Momentum exchange: drag on particles " << onParticles
        << " N, on fluid " << onFluid << " N (relative difference "
        << mag(onParticles + onFluid)/max(mag(onParticles), VSMALL) << ")"
        << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::demCoupling::demCoupling
(
    const volVectorField& U,
    const uniformDimensionedVectorField& g,
    const volScalarField* p
)
:
    mesh_(U.mesh()),
    g_(g),
    p_(p),
    props_(U.mesh()),
    drag_(dragModel::New(props_)),
    forces_(forceModel::New(props_)),
    locator_(U.mesh()),
    exchange_(U.mesh(), locator_),
    UInterp_(U),
    records_(),
    deposit_(),
    insertedSampler_(),
    feed_(),
    proc_(),
    engine_(),
    restart_(U.mesh()),
    demGrid_(label(0)),
    nCouplingSteps_(0),
    analysedAt_(-1),
    nAnalyses_(0),
    analysisSeconds_(0),
    writeAnalysisSeconds_(0),
    nInserted_(0),
    startCounted_(false),
    demSeconds_(0),
    couplingSeconds_(0),
    particleSteps_(0),
    nRecordsGathered_(0),
    nRecordsAway_(0),
    insertedSeconds_(0),
    stageSeconds_(scalar(0))
{
    checkTimeStep();
    checkForceModels();
    if (props_.found("feed"))
    {
        feed_.reset
        (
            new particleFeed
            (
                props_.subDict("feed"), U, props_.particleDiameter(),
                props_.particleDensity(), props_.couplingInterval(),
                props_.demTimeStep()
            )
        );
    }

    if (props_.twoWay())
    {
        checkTransientSetup();

        Info<< "Two-way coupling, Model " << (props_.modelB() ? "B" : "A")
            << ", fluid fraction bounded below by "
            << props_.epsilonMin() << endl;
        deposit_ = depositKernel::New(props_, mesh_, locator_, UInterp_);
        Info<< "Deposit kernel: " << props_.kernel() << endl;

        voidfraction_.reset
        (
            new volScalarField
            (
                IOobject
                (
                    "voidfraction",
                    mesh_.time().timeName(),
                    mesh_,
                    IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                ),
                mesh_,
                dimensionedScalar("one", dimless, 1.0),
                zeroGradientFvPatchScalarField::typeName
            )
        );
        voidfraction_->oldTime();
        Kexchange_.reset
        (
            new volScalarField
            (
                IOobject("Kexchange", mesh_.time().timeName(), mesh_),
                mesh_,
                dimensionedScalar("zero", dimless/dimTime, 0.0),
                zeroGradientFvPatchScalarField::typeName
            )
        );
        Fexchange_.reset
        (
            new volVectorField
            (
                IOobject("Fexchange", mesh_.time().timeName(), mesh_),
                mesh_,
                dimensionedVector("zero", dimAcceleration, Zero),
                zeroGradientFvPatchVectorField::typeName
            )
        );
    }

    Info<< "Coupling: fluid rho " << props_.rhoFluid() << " kg/m^3, mu "
        << props_.muFluid() << " Pa s; particles d "
        << props_.particleDiameter() << " m";
    if (props_.sizeRange())
    {
        Info<< " (from " << props_.smallestDiameter() << " to "
            << props_.largestDiameter() << " m)";
    }
    Info<< ", rho " << props_.particleDensity() << " kg/m^3" << nl
        << "    DEM step " << props_.demTimeStep() << " s, "
        << props_.couplingInterval() << " DEM steps per coupling step"
        << nl << endl;

    try
    {
        startDEM();
        clockTime clock;
        scalarField wallDist;
        gatherRecords(contacts_.valid() ? props_.releaseGap() : 0, wallDist);
        if (!restart_.resume())
        {
            reportOutsideFluid();
        }
        updateForces();
        analyseContacts(wallDist);

        // The start-up's work is not that of a coupling step: the timing
        // of the run (Timing, Contact analysis) counts from here
        const scalar startupSeconds = clock.elapsedTime();
        couplingSeconds_ = 0;
        stageSeconds_ = scalar(0);
        analysisSeconds_ = 0;
        writeAnalysisSeconds_ = 0;
        nAnalyses_ = 0;
        Info<< "Coupling start-up (locating every particle, first forces"
            << (contacts_.valid() ? ", first contact analysis" : "")
            << "): " << startupSeconds << " s, not in the timing of the run"
            << nl << endl;

        // From now on, particles the DEM inserts feel the fluid from their
        // first step (before: the drag of their first interval was zero)
        engine_().onAtomsWithoutDrag
        (
            [this]()
            {
                try
                {
                    coupleInserted();
                }
                catch (const std::exception& e)
                {
                    FatalErrorInFunction
                        << "Coupling the particles inserted at DEM step "
                        << engine_().timeStep() << " failed: " << e.what()
                        << exit(FatalError);
                }
            }
        );

        // A fresh start's first step sets up with these forces (a resumed
        // run has the written run's last forces back instead)
        if (!restart_.resume())
        {
            engine_().setUpNextRun();
        }
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

void Foam::demCoupling::reportOutsideFluid() const
{
    const liggghtsEngine& dem = engine_();
    double** x = dem.x();
    const int* tag = dem.tag();

    label nOutside = 0;
    OStringStream list;
    forAll(proc_, i)
    {
        if (proc_[i] < 0)
        {
            if (nOutside < 5)
            {
                list<< nl << "    particle " << tag[i] << " at "
                    << demUnits::length*vector(x[i][0], x[i][1], x[i][2])
                    << " m";
            }
            ++nOutside;
        }
    }
    List<string> lists(Pstream::nProcs());
    lists[Pstream::myProcNo()] = list.str();
    Pstream::gatherList(lists);     // at most 5 lines per rank
    reduce(nOutside, sumOp<label>());
    if (nOutside)
    {
        string text;
        for (const string& part : lists)
        {
            text += part;
        }
        WarningInFunction
            << nOutside << " particles of the DEM lie outside the fluid mesh"
            << " at the start (they feel no drag there until they enter"
            << " it; an insertion zone outside the fluid is one reason):"
            << text.c_str() << endl;
    }
}


Foam::vector Foam::demCoupling::explicitForce
(
    const particleContext& c
) const
{
    vector F = Zero;
    for (const forceModel& model : forces_)
    {
        F += model.force(c);
    }
    return F;
}


Foam::List<Foam::FixedList<Foam::scalar, 7>> Foam::demCoupling::fluidForces
(
    const particleRecords& rec,
    const depositKernel* sampler,
    scalar& tauMin
)
{
    // Two-way: eps and grad p averaged over each particle's kernel (the
    // transpose of its deposit: the pressure-gradient forces then balance
    // the fluid's eps grad p exactly), and so is U with a kernel wider
    // than the particle (couplingProperties::kernelSamplesU); else U
    // interpolated at the centre
    const bool kernelU = props_.kernelSamplesU();

    tmp<volVectorField> tgradp, tdivTau;
    for (const forceModel& model : forces_)
    {
        if (model.needsPressureGradient() && !tgradp.valid())
        {
            tgradp = props_.rhoFluid()*fvc::grad(*p_);
        }
        if (model.needsViscousStress() && !tdivTau.valid())
        {
            // div(mu (grad U + grad U^T)) [Pa/m]
            const volVectorField& Uf = UInterp_.field();
            tdivTau =
                props_.muFluid()
               *(fvc::laplacian(Uf) + fvc::div(T(fvc::grad(Uf))));
        }
    }

    // The fields the forces need, sampled together: one pass over the
    // kernel points and one exchange
    scalarField sampledEps;
    List<vectorField> sampled;
    label iU = -1, iGradp = -1, iDivTau = -1;
    if (sampler)
    {
        UPtrList<const volVectorField> fields(3);
        label nFields = 0;
        if (kernelU)
        {
            iU = nFields;
            fields.set(nFields++, &UInterp_.field());
        }
        if (tgradp.valid())
        {
            iGradp = nFields;
            fields.set(nFields++, &tgradp());
        }
        if (tdivTau.valid())
        {
            iDivTau = nFields;
            fields.set(nFields++, &tdivTau());
        }
        fields.setSize(nFields);
        sampler->sample(voidfraction_(), fields, sampledEps, sampled);
    }

    const scalar mu = props_.muFluid();

    // Per record: K [kg/s], U [m/s], explicit force [N]
    const label nRec = rec.position.size();
    List<FixedList<scalar, 7>> answer(nRec);
    for (label k = 0; k < nRec; ++k)
    {
        // The context; eps = 1, U = 0, no grad(p) without two-way
        // coupling
        const label celli = rec.cell[k];
        particleContext c =
            restContext(rec.radius[k], rec.mass[k], rec.velocity[k]);
        c.cell = celli;
        c.U =
            iU >= 0 ? sampled[iU][k]
          : kernelU ? vector::zero
          : UInterp_.interpolate(rec.position[k], celli);
        c.gradp =
            iGradp >= 0 ? sampled[iGradp][k]
          : tgradp.valid() ? tgradp()[celli] : vector::zero;
        c.divTau =
            iDivTau >= 0 ? sampled[iDivTau][k]
          : tdivTau.valid() ? tdivTau()[celli] : vector::zero;
        c.eps =
            sampler ? sampledEps[k]
          : voidfraction_.valid() ? voidfraction_()[celli] : 1.0;

        scalar K = drag_->K(c);
        if (props_.modelB())
        {
            K /= c.eps;
        }
        if (props_.selfInducedVelocity())
        {
            // The kernel-averaged fluid carries the particle's own
            // disturbance: the fluid's reaction -F spread over the ball
            // moves it by u_self = -g F, g = 1/(5 pi mu R).  The drag on
            // the undisturbed slip, F = K (U - u_self - v), is
            // F = K/(1 - K g) (U - v)
            const scalar R = max(0.5*c.d, props_.kernelRadius());
            const scalar Kg = K/(5*constant::mathematical::pi*mu*R);
            if (Kg >= 0.5)
            {
                FatalIOErrorInFunction(props_)
                    << "selfInducedVelocity: the particle's own"
                    << " disturbance is " << Kg << " of its slip"
                    << " (kernelRadius " << props_.kernelRadius()
                    << " m in " << props_.objectPath() << "): the"
                    << " correction is for dilute particles much"
                    << " smaller than the kernel; allowed: K/(5 pi mu R)"
                    << " < 0.5" << exit(FatalIOError);
            }
            K /= 1 - Kg;
        }
        tauMin = min(tauMin, c.mass/K);
        const vector F = explicitForce(c);
        answer[k] = FixedList<scalar, 7>
        ({K, c.U.x(), c.U.y(), c.U.z(), F.x(), F.y(), F.z()});
    }
    return answer;
}


Foam::label Foam::demCoupling::setAtomForces
(
    const labelUList& atoms,
    const labelUList& proc,
    const List<FixedList<scalar, 7>>& perAtom,
    const bool newInterval
)
{
    liggghtsEngine& dem = engine_();
    double** v = dem.v();
    double* r = dem.radius();
    double* m = dem.rmass();
    double* Ksl = dem.scalarProperty(colloidDrag::coefficient);
    double** uf = dem.vectorProperty(colloidDrag::fluidVelocity);
    double** fExplicit = dem.vectorProperty(colloidDrag::explicitForce);
    double** impulse = dem.vectorProperty(colloidDrag::impulse);
    double* assigned = dem.scalarProperty(colloidDrag::assigned);

    label nOutside = 0;
    forAll(atoms, k)
    {
        const label i = atoms[k];
        FixedList<scalar, 7> a = perAtom[k];
        if (proc[k] < 0)
        {
            // Outside the fluid: no drag, the body forces only
            ++nOutside;
            const vector F = explicitForce
            (
                restContext
                (
                    demUnits::length*r[i], demUnits::mass*m[i],
                    demUnits::velocity*vector(v[i][0], v[i][1], v[i][2])
                )
            );
            a = FixedList<scalar, 7>({0, 0, 0, 0, F.x(), F.y(), F.z()});
        }
        Ksl[i] = a[0]/demUnits::dragCoeff;
        for (direction d = 0; d < 3; ++d)
        {
            uf[i][d] = a[1 + d]/demUnits::velocity;
            fExplicit[i][d] = a[4 + d]/demUnits::force;
            if (newInterval)
            {
                impulse[i][d] = 0;
            }
        }
        assigned[i] = 1;
    }
    return nOutside;
}


void Foam::demCoupling::coupleInserted()
{
    clockTime clock;

    liggghtsEngine& dem = engine_();
    const int n = dem.nLocal();
    const double* assigned = dem.scalarProperty(colloidDrag::assigned);
    DynamicList<label> atoms;
    for (int i = 0; i < n; ++i)
    {
        if (assigned[i] == 0)
        {
            atoms.append(i);
        }
    }

    pointField position;
    labelList proc, cell;
    scalarField wallDist;
    locateAtoms(atoms, 0, position, proc, cell, wallDist);

    double** v = dem.v();
    double* r = dem.radius();
    double* m = dem.rmass();
    scalarField radius(atoms.size()), mass(atoms.size());
    vectorField velocity(atoms.size());
    forAll(atoms, k)
    {
        const label i = atoms[k];
        radius[k] = demUnits::length*r[i];
        mass[k] = demUnits::mass*m[i];
        velocity[k] = demUnits::velocity*vector(v[i][0], v[i][1], v[i][2]);
    }
    particleRecords rec;
    rec.gather
    (
        proc, cell, position, radius, mass, velocity,
        scalarField(atoms.size(), 0), vectorField(atoms.size(), Zero)
    );

    // Two-way: the fluid at these particles averaged over their kernels,
    // as at every exchange (a deposit of their own; the fluid's fields do
    // not change)
    if (props_.twoWay() && !insertedSampler_.valid())
    {
        insertedSampler_ =
            depositKernel::New(props_, mesh_, locator_, UInterp_);
    }
    depositKernel* sampler = insertedSampler_.get();
    if (sampler)
    {
        scalarField solidVolume(mesh_.nCells(), 0), Kc(mesh_.nCells(), 0);
        vectorField Fc(mesh_.nCells(), Zero);
        sampler->deposit
        (
            rec.position, rec.cell, rec.radius, rec.dragCoeff, rec.dragForce, solidVolume, Kc, Fc
        );
    }

    scalar tauMin = GREAT;
    const List<FixedList<scalar, 7>> answer =
        fluidForces(rec, sampler, tauMin);
    List<FixedList<scalar, 7>> perAtom(atoms.size(), FixedList<scalar, 7>(0.0));
    rec.answer(answer, perAtom);

    const label nOutside =
        returnReduce(setAtomForces(atoms, proc, perAtom, false), sumOp<label>());
    checkRelaxationTime(returnReduce(tauMin, minOp<scalar>()));

    Info<< "Coupling: " << returnReduce(atoms.size(), sumOp<label>())
        << " particles inserted at DEM step " << dem.timeStep()
        << " get their fluid forces from this step";
    if (nOutside)
    {
        Info<< " (" << nOutside << " outside the fluid: body forces only)";
    }
    Info<< endl;

    const scalar seconds = clock.timeIncrement();
    couplingSeconds_ += seconds;
    insertedSeconds_ += seconds;
}


void Foam::demCoupling::updateForces()
{
    try
    {
        clockTime clock;

        if (!props_.kernelSamplesU())
        {
            UInterp_.update();
        }

        // On the owning ranks: the records' forces
        scalar tauMin = GREAT;
        const List<FixedList<scalar, 7>> answer =
            fluidForces(records_, deposit_.get(), tauMin);
        const scalar forcesSeconds = clock.timeIncrement();
        stageSeconds_[forcesStage] += forcesSeconds;

        // Back on the particles' ranks
        const label n = engine_().nLocal();
        List<FixedList<scalar, 7>> perParticle(n, FixedList<scalar, 7>(0.0));
        records_.answer(answer, perParticle);
        const label nOutside = returnReduce
        (
            setAtomForces(identity(n), proc_, perParticle, true),
            sumOp<label>()
        );

        // Particles of the script may differ from those of the settings
        checkRelaxationTime(returnReduce(tauMin, minOp<scalar>()));

        Info<< "Coupling: " << returnReduce(n, sumOp<label>())
            << " particles, " << nOutside << " outside the fluid, "
            << returnReduce(locator_.nGlobalSearches(), sumOp<label>())
            << " global searches" << endl;

        const scalar backSeconds = clock.timeIncrement();
        stageSeconds_[backStage] += backSeconds;
        couplingSeconds_ += forcesSeconds + backSeconds;
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << "Coupling step failed: " << e.what() << exit(FatalError);
    }
}


void Foam::demCoupling::evolve()
{
    try
    {
        clockTime clock;

        liggghtsEngine& dem = engine_();
        const label nTotal = returnReduce(label(dem.nLocal()), sumOp<label>());

        if (props_.twoWay())
        {
            // The fluid fraction of the old time, before the deposit
            // below changes it (oldTime() stores it once per time step)
            voidfraction_->oldTime();
        }

        // This step's time folder will be written (a write time, or the
        // end time as known at this step, which the solver always writes;
        // an end decided later, e.g. by a runTimeControl function object,
        // gets no rebuild): no stale DEM state in
        // it, and no particle that an outflow counted but has not deleted
        // yet (it would be kept by the restart and lost after a resume:
        // slot-coater study resumed at 112, 117 and 119 us, not write
        // times, one such particle lost at 121 us)
        const Time& runTime = mesh_.time();
        const bool atEnd =
            runTime.value() >= runTime.endTime().value() - 0.5*runTime.deltaTValue();
        if (runTime.writeTime() || atEnd)
        {
            restart_.invalidate();
            dem.reneighbourAt(dem.timeStep() + props_.couplingInterval());
        }

        // The feed's particles due at this step, before the run (counted
        // as coupling work)
        if (feed_.valid() && feed_->due(dem.timeStep()))
        {
            // updateForces keeps the interpolator current unless a kernel
            // samples the fluid
            if (props_.kernelSamplesU())
            {
                UInterp_.update();
            }
            feed_->insert(dem, UInterp_);
            couplingSeconds_ += clock.timeIncrement();
        }

        // The run's time less that of coupling the particles it inserted
        // (counted as coupling work)
        const scalar insertedBefore = insertedSeconds_;
        dem.run(props_.couplingInterval());
        demSeconds_ +=
            clock.timeIncrement() - (insertedSeconds_ - insertedBefore);
        particleSteps_ += scalar(nTotal)*props_.couplingInterval();
        if (feed_.valid())
        {
            feed_->checkInserted(dem);
        }

        // An analysis due: the locating gives it the wall distances too
        ++nCouplingSteps_;
        const bool analyse =
            contacts_.valid() && nCouplingSteps_ % contacts_->interval() == 0;
        scalarField wallDist;
        gatherRecords(analyse ? props_.releaseGap() : 0, wallDist);
        if (analyse)
        {
            analyseContacts(wallDist);
        }

        couplingSeconds_ += clock.timeIncrement();
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << "Coupling step failed: " << e.what() << exit(FatalError);
    }
}


void Foam::demCoupling::write
(
    const bool fieldsWritten,
    const string& fieldsError
)
{
    // The start time of a resumed run keeps the output it was resumed
    // from; a fresh start has no DEM state worth saving at its start
    const Time& runTime = mesh_.time();
    const bool atStart = runTime.timeIndex() == runTime.startTimeIndex();
    if (atStart && restart_.resume())
    {
        return;
    }
    // Files OpenFOAM could not write (atomicFileOperation: errors that
    // show only when a file is flushed and closed)
    using fileOperations::atomicFileOperation;
    auto failedFile = []()
    {
        const DynamicList<fileName>& failed = atomicFileOperation::failures();
        return failed.empty() ? string() : string(": " + failed.first());
    };
    if
    (
        !returnReduce
        (
            fieldsWritten && atomicFileOperation::failures().empty(),
            andOp<bool>()
        )
    )
    {
        restart_.abandonWrite
        (
            "the fluid fields could not be written" + failedFile()
          + (fieldsError.empty() ? string() : " (" + fieldsError + ")")
        );
    }

    if (!atStart)
    {
        restart_.invalidate();
    }

    try
    {
        countNewParticles();

        // Wall distances for the touching flag and, if the analysis is
        // on, for its range; every write has its analysis (the particles'
        // agglomerate sizes)
        pointField position;
        labelList proc, cell;
        scalarField wallDist;
        locateLocal
        (
            contacts_.valid()
          ? max(touchTolerance_, props_.releaseGap()) : touchTolerance_,
            position, proc, cell, wallDist
        );
        const scalar analysisBefore = analysisSeconds_;
        analyseContacts(wallDist);
        writeAnalysisSeconds_ += analysisSeconds_ - analysisBefore;

        liggghtsEngine& dem = engine_();
        const int n = dem.nLocal();
        double** v = dem.v();
        double* r = dem.radius();
        const double* contacts =
            dem.hasPairStyle() ? dem.computePerAtom("colloidContacts") : nullptr;

        const int* tag = dem.tag();

        particleCloudWriter::particles out;
        out.proc = proc;
        out.cell = cell;
        out.position = position;
        out.id.setSize(n);
        out.velocity.setSize(n);
        out.diameter.setSize(n);
        out.nContacts.setSize(n);
        out.touchingWall.setSize(n);
        out.agglomerateSize =
            contacts_.valid() ? contacts_->agglomerateSize(n) : labelList(n, 1);
        out.withAgglomerates = contacts_.valid();
        for (int i = 0; i < n; ++i)
        {
            const scalar radius = demUnits::length*r[i];
            out.id[i] = tag[i];
            out.velocity[i] =
                demUnits::velocity*vector(v[i][0], v[i][1], v[i][2]);
            out.diameter[i] = 2*radius;
            out.nContacts[i] = contacts ? label(std::lround(contacts[i])) : 0;
            out.touchingWall[i] =
                (wallDist[i] <= (1 + touchTolerance_)*radius) ? 1 : 0;
        }
        out.agglomerateId =
            contacts_.valid() ? contacts_->agglomerateId(n) : out.id;

        const label nPresent = returnReduce(label(n), sumOp<label>());
        bool cloudWritten = true;
        string cloudError;
        const label nWritten = particleCloudWriter::write
        (
            mesh_, cloudName_, out, cloudWritten, cloudError
        );
        if
        (
            !returnReduce
            (
                cloudWritten && atomicFileOperation::failures().empty(),
                andOp<bool>()
            )
        )
        {
            restart_.abandonWrite
            (
                "the particles (lagrangian/" + word(cloudName_)
              + ") could not be written" + failedFile()
              + (cloudError.empty() ? string() : " (" + cloudError + ")")
            );
        }

        // The searches of this output are not those of a coupling step
        locator_.nGlobalSearches();

        // Removed: counted by the DEM's outflow fixes (massflow/mesh with
        // delete_atoms yes), independently of the two other counts; each
        // fix's count too (an outlet, and e.g. an inlet that takes the
        // particles diffusing back up out of the fluid)
        const std::vector<std::pair<std::string, double>> removedPerFix =
            dem.fixVectors("massflow/mesh", 5);
        label nRemoved = 0;
        for (const auto& idCount : removedPerFix)
        {
            nRemoved += label(std::lround(idCount.second));
        }

        Info<< "Particles: present " << nPresent
            << ", inserted " << nInserted_
            << ", removed " << nRemoved << "; written " << nWritten
            << " (lagrangian/" << cloudName_ << "), "
            << nPresent - nWritten << " outside the fluid" << endl;
        if (!removedPerFix.empty())
        {
            Info<< "Removed per outflow fix:";
            for (size_t i = 0; i < removedPerFix.size(); ++i)
            {
                Info<< (i ? ", " : " ") << removedPerFix[i].first.c_str()
                    << ' ' << label(std::lround(removedPerFix[i].second));
            }
            Info<< endl;
        }
        if (contacts_.valid())
        {
            Info<< "Contacts: " << contacts_->summary().c_str() << endl;
        }

        if (nPresent != nInserted_ - nRemoved)
        {
            const dictionary& demDict = props_.subDict("DEM");
            if (!props_.allowLostParticles())
            {
                FatalIOErrorInFunction(demDict)
                    << "At time " << runTime.timeName() << " s, "
                    << nInserted_ - nRemoved - nPresent << " particles were"
                    << " lost by the DEM (present " << nPresent
                    << " != inserted " << nInserted_ << " - removed "
                    << nRemoved << "), not through a massflow/mesh outflow:"
                    << " they left the DEM box or were deleted (e.g."
                    << " 'thermo_modify lost ignore' in the DEM script).  Set"
                    << " allowLostParticles yes in " << demDict.name()
                    << " to go on without them" << exit(FatalIOError);
            }
            WarningInFunction
                << "present " << nPresent << " != inserted " << nInserted_
                << " - removed " << nRemoved << ": particles were lost"
                << " other than through a massflow/mesh outflow"
                << " (allowLostParticles yes in " << demDict.name() << ")"
                << endl;
        }

        if (!atStart)
        {
            const string problem =
                restart_.write(dem, nInserted_, contacts_.get(), demGrid_);
            if (!problem.empty())
            {
                restart_.abandonWrite(problem);
            }
        }
        atomicFileOperation::clearFailures();

        if (demSeconds_ > 0)
        {
            const scalar total = demSeconds_ + couplingSeconds_;
            Info<< "Timing (master, wall clock): DEM " << demSeconds_
                << " s, coupling " << couplingSeconds_ << " s; "
                << particleSteps_/total/Pstream::nProcs()
                << " particle-steps per second per rank" << endl;
        }
        if (nCouplingSteps_ > 0)
        {
            // A stage that takes longer on the master than on the fastest
            // rank is the master waiting there for the others (collective:
            // the same count on every rank)
            FixedList<scalar, nStages + 1> fastest;
            fastest[0] = demSeconds_;
            for (label i = 0; i < nStages; ++i)
            {
                fastest[i + 1] = stageSeconds_[i];
            }
            FixedList<scalar, nStages + 1> slowest(fastest);
            const FixedList<scalar, nStages + 1> master(fastest);
            for (label i = 0; i <= nStages; ++i)
            {
                reduce(fastest[i], minOp<scalar>());
                reduce(slowest[i], maxOp<scalar>());
            }
            static const char* names[nStages + 1] =
                {"DEM", "locate", "records", "deposit", "forces", "back"};
            Info<< "Coupling stages [s] (master, fastest, slowest rank):";
            for (label i = 0; i <= nStages; ++i)
            {
                Info<< ' ' << names[i] << ' ' << master[i] << ' '
                    << fastest[i] << ' ' << slowest[i]
                    << (i == 0 ? ";" : i < nStages ? "," : "");
            }
            Info<< endl;
        }
        if (Pstream::parRun())
        {
            // (collective: every rank writes)
            const scalar gathered =
                returnReduce(nRecordsGathered_, sumOp<scalar>());
            const scalar away = returnReduce(nRecordsAway_, sumOp<scalar>());
            Info<< "Records: " << 100*away/max(gathered, scalar(1))
                << " % of the particles were on another rank than their"
                << " cells (mean over the coupling steps): the coupling's"
                << " traffic is for them" << endl;
        }
        if (nAnalyses_ > 0)
        {
            Info<< "Contact analysis: " << nAnalyses_ << " analyses, "
                << analysisSeconds_ << " s: "
                << analysisSeconds_ - writeAnalysisSeconds_
                << " s in the coupling's time, "
                << writeAnalysisSeconds_ << " s at writes (the wall"
                << " distances come with the locating)" << endl;
        }
        if (dem.nFixesOfStyle("colloid/implicit") > 0)
        {
            // the plugin's statistics since it was set up (global vector;
            // the time is the master's)
            Info<< "Implicit update of lubrication and drag: "
                << dem.sumFixVector("colloid/implicit", 1)
                << " conjugate-gradient iterations per DEM step on average,"
                << " at most " << dem.sumFixVector("colloid/implicit", 2)
                << ", not converged " << dem.sumFixVector("colloid/implicit", 3)
                << "; " << dem.sumFixVector("colloid/implicit", 4) << " s; "
                << dem.sumFixVector("colloid/implicit", 5)
                << " particles in the solve across ranks per update; "
                << 100*dem.sumFixVector("colloid/implicit", 6)
                << " % of the lubricated pairs damped explicitly" << endl;
        }
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << "Writing particles failed: " << e.what() << exit(FatalError);
    }
}
