#include "averagedFluid.H"
#include "fvCFD.H"
#include "constrainHbyA.H"
#include "clockTime.H"

Foam::averagedFluid::averagedFluid
(
    fvMesh& mesh,
    volVectorField& U,
    volScalarField& p,
    const demCoupling& coupling
)
:
    mesh_(U.mesh()),
    coupling_(coupling),
    U_(U),
    p_(p),
    pimple_(mesh),
    phi_
    (
        IOobject
        (
            "phi",
            U.mesh().time().timeName(),
            U.mesh(),
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        fvc::flux(coupling.voidfraction()*U)
    ),
    pRefCell_(0),
    pRefValue_(0),
    nu_("nu", dimViscosity, coupling.nu()),
    deferred_
    (
        IOobject("deferredDrag", U.mesh().time().timeName(), U.mesh()),
        U.mesh(),
        dimensionedVector("zero", dimAcceleration, Zero)
    ),
    seconds_(0)
{
    setRefCell(p_, pimple_.dict(), pRefCell_, pRefValue_);
    mesh_.setFluxRequired(p_.name());
}


Foam::tmp<Foam::volVectorField> Foam::averagedFluid::pressureTerm() const
{
    if (coupling_.modelB())
    {
        return -fvc::grad(p_);
    }
    return -coupling_.voidfraction()*fvc::grad(p_);
}


Foam::tmp<Foam::volVectorField> Foam::averagedFluid::exchangeSource() const
{
    return
        coupling_.Fexchange()
      + coupling_.Kexchange()*U_.oldTime()
      + deferred_;
}


Foam::tmp<Foam::fvVectorMatrix> Foam::averagedFluid::momentum()
{
    const volScalarField& eps = coupling_.voidfraction();

    // The exchange source is part of the matrix's explicit side, so that
    // HbyA carries rAU S cell by cell: where the drag (and so rAU) jumps by
    // orders of magnitude between neighbouring cells, a source taken to the
    // faces separately (as buoyancy in OpenFOAM's buoyant solvers) would be
    // weighted by the neighbour's rAU
    tmp<fvVectorMatrix> tUEqn
    (
        fvm::ddt(eps, U_)
      + fvm::div(phi_, U_)
      - fvm::laplacian(eps*nu_, U_)
      - fvc::div(eps*nu_*dev2(T(fvc::grad(U_))))
      + fvm::Sp(coupling_.Kexchange(), U_)
     ==
        exchangeSource()
    );
    fvVectorMatrix& UEqn = tUEqn.ref();

    UEqn.relax();

    if (pimple_.momentumPredictor())
    {
        Foam::solve(UEqn == pressureTerm());
    }
    return tUEqn;
}


void Foam::averagedFluid::correctPressure(fvVectorMatrix& UEqn)
{
    const volScalarField& eps = coupling_.voidfraction();
    const surfaceScalarField epsf(fvc::interpolate(eps));

    const volScalarField rAU(1.0/UEqn.A());
    const surfaceScalarField rAUf(fvc::interpolate(rAU));

    // HbyA includes rAU S; at fixed-U boundaries (walls, inlets) it is U's
    // own value, so no fluid crosses a wall
    const volVectorField HbyA(constrainHbyA(rAU*UEqn.H(), U_, p_));

    // eps U = eps HbyA - Dp grad p
    const surfaceScalarField phiHbyA
    (
        "phiHbyA",
        epsf*fvc::flux(HbyA)
        // Rhie-Chow's time-step correction (as in OpenFOAM's compressible
        // solvers, with eps in place of rho): without it the cell
        // velocities decouple from the fluxes at small time steps
      + fvc::interpolate(eps*rAU)*fvc::ddtCorr(eps, U_, phi_)
    );
    const surfaceScalarField Dp
    (
        "Dp",
        coupling_.modelB() ? rAUf*epsf : rAUf*sqr(epsf)
    );

    while (pimple_.correctNonOrthogonal())
    {
        fvScalarMatrix pEqn
        (
            fvm::laplacian(Dp, p_) == fvc::div(phiHbyA) + fvc::ddt(eps)
        );
        pEqn.setReference(pRefCell_, pRefValue_);
        pEqn.solve(mesh_.solver(p_.select(pimple_.finalInnerIter())));

        if (pimple_.finalNonOrthogonalIter())
        {
            phi_ = phiHbyA - pEqn.flux();

            U_ = HbyA + rAU*pressureTerm();
            U_.correctBoundaryConditions();
        }
    }

    // Continuity of the fluid phase
    const volScalarField contErr(fvc::ddt(eps) + fvc::div(phi_));
    Info<< "time step continuity errors : sum local = "
        << mesh_.time().deltaTValue()
          *mag(contErr)().weightedAverage(mesh_.V()).value()
        << endl;

    p_.relax();
}


void Foam::averagedFluid::solve()
{
    clockTime clock;

    while (pimple_.loop())
    {
        tmp<fvVectorMatrix> tUEqn(momentum());

        while (pimple_.correct())
        {
            correctPressure(tUEqn.ref());
        }
    }

    // The implicit drag term Kexchange (U^n - U^{n+1}) of this step is not
    // an exchange with the particles: give its momentum back at the next
    // step, so that over the run the fluid receives exactly the particles'
    // reaction (up to the last step's term)
    deferred_ = coupling_.Kexchange()*(U_ - U_.oldTime());
    Info<< "Fluid: implicit drag term " << -fvc::domainIntegrate(deferred_).value()
        << " m^4/s^2 (returned next step), exchange "
        << fvc::domainIntegrate(coupling_.Fexchange()).value() << " m^4/s^2"
        << endl;

    seconds_ += clock.timeIncrement();
}
