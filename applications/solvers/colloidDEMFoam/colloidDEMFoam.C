/*---------------------------------------------------------------------------*\
Application
    colloidDEMFoam

Description
    CFD-DEM solver for dilute colloidal suspensions.  The fluid velocity U
    is a steady field read from the start time (computed beforehand, e.g.
    by simpleFoam) and is not solved (one-way coupling).  A LIGGGHTS DEM
    instance runs in the same process; each time step is one coupling step
    of couplingInterval DEM steps (see constant/couplingProperties).

    Output: the fluid fields in the time folders, the particles in
    VTK/particles_<timeIndex>.vtk, the DEM log in log.liggghts.

    LIGGGHTS contact models of the project's plugin are registered when
    the plugin library is loaded, e.g. with
        libs ("libliggghtsColloid.so");
    in system/controlDict (loaded before the DEM script is read).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "demCoupling.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "One-way coupled CFD-DEM for colloidal suspensions:"
        " steady fluid from the start time, LIGGGHTS in-process."
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "createFields.H"

    demCoupling coupling(U, g);

    coupling.write();

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.loop())
    {
        Info<< "Time = " << runTime.timeName() << nl << endl;

        coupling.evolve();

        runTime.write();

        if (runTime.writeTime())
        {
            coupling.write();
        }

        Info<< "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
            << "  ClockTime = " << runTime.elapsedClockTime() << " s"
            << nl << endl;
    }

    Info<< "End\n" << endl;

    return 0;
}
