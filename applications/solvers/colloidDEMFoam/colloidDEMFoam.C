/*---------------------------------------------------------------------------*\
Application
    colloidDEMFoam

Description
    CFD-DEM solver for colloidal suspensions.  A LIGGGHTS DEM instance runs
    in the same process; each time step is one coupling step of
    couplingInterval DEM steps (see constant/couplingProperties).

    couplingMode oneWay: the fluid velocity U is a steady field read from
    the start time (computed beforehand, e.g. by simpleFoam), never solved.

    couplingMode twoWay: after each DEM interval the fluid is solved with
    the particles' fluid fraction and drag impulse (averagedFluid: locally
    averaged Navier-Stokes, Model A or B, PIMPLE), and the forces of the
    next interval are taken from it.

    Output: the fluid fields (two-way: with voidfraction) and the particles
    (lagrangian cloud <time>/lagrangian/particles, per rank) in the time
    folders, the DEM log in log.liggghts.

    LIGGGHTS contact models of the project's plugin are registered when
    the plugin library is loaded, e.g. with
        libs ("libliggghtsColloid.so");
    in system/controlDict (loaded before the DEM script is read).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "demCoupling.H"
#include "averagedFluid.H"
#include "atomicFileOperation.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "CFD-DEM for colloidal suspensions, LIGGGHTS in-process:"
        " one-way (steady fluid from the start time) or two-way (locally"
        " averaged fluid solved with the particles)."
    );

    #include "setRootCase.H"
    #include "createTime.H"

    // Every file written under a temporary name, renamed when complete
    fileOperations::atomicFileOperation::install();

    #include "createMesh.H"
    #include "createFields.H"

    demCoupling coupling(U, g, pPtr.get());

    autoPtr<averagedFluid> fluid;
    if (coupling.twoWay())
    {
        fluid.reset(new averagedFluid(mesh, U, pPtr(), coupling));
    }

    coupling.write();

    // Progress: from this start (a resumed run counts from where it
    // resumed) to the end time
    const scalar startTime = runTime.value();
    const scalar endTime = runTime.endTime().value();
    const scalar startClock = runTime.elapsedClockTime();
    bool written = true;

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.loop())
    {
        Info<< "Time = " << runTime.timeName() << nl << endl;

        // DEM interval with the forces of the fluid at the old time, then
        // (two-way) the particles' fluid fraction and drag impulse
        coupling.evolve();

        if (fluid.valid())
        {
            fluid->solve();
        }

        // Forces of the next interval from the (new) fluid
        coupling.updateForces();

        // A field that cannot be written (a full disk) is handled by the
        // coupling's write, which removes the incomplete time folder
        string writeError;
        const bool fieldsWritten =
            fileOperations::atomicFileOperation::catching
            (
                [&runTime]() { return runTime.write(); },
                writeError
            );

        written = runTime.writeTime();
        if (written)
        {
            coupling.write(fieldsWritten, writeError);
            if (fluid.valid())
            {
                Info<< "Timing (master, wall clock): fluid solve "
                    << fluid->seconds() << " s" << endl;
            }
        }

        const scalar done =
            (runTime.value() - startTime)/max(endTime - startTime, VSMALL);
        const scalar seconds = runTime.elapsedClockTime() - startClock;
        Info<< "Progress: " << runTime.timeName() << " of " << endTime
            << " s (" << label(100*done) << " %), "
            << coupling.particleSteps()/max(seconds, 1) << " particle-steps/s,"
            << " ETA "
            << label(min(seconds*(1 - done)/max(done, VSMALL), scalar(1e9)))
            << " s"
            << nl
            << "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
            << "  ClockTime = " << runTime.elapsedClockTime() << " s"
            << nl << endl;
    }

    // The end time is always written, also when it is not a write time
    // (e.g. a shortened run), so that the run can be looked at and resumed
    if (!written)
    {
        string writeError;
        const bool fieldsWritten =
            fileOperations::atomicFileOperation::catching
            (
                [&runTime]() { return runTime.writeNow(); },
                writeError
            );
        coupling.write(fieldsWritten, writeError);
    }

    Info<< "End\n" << endl;

    return 0;
}
