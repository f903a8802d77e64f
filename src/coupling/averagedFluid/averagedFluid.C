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
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        fvc::flux(coupling.voidfraction()*U)
    ),
    pRefCell_(0),
    pRefValue_(0),
    nu_
    (
        IOobject
        (
            "nu",
            U.mesh().time().timeName(),
            U.mesh(),
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        U.mesh(),
        dimensionedScalar("nu", dimViscosity, coupling.nu())
    ),
    fvOptions_(fv::options::New(mesh)),
    deferred_
    (
        IOobject
        (
            "deferredDrag",
            U.mesh().time().timeName(),
            U.mesh(),
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        U.mesh(),
        dimensionedVector("zero", dimAcceleration, Zero)
    ),
    seconds_(0)
{
    setRefCell(p_, pimple_.dict(), pRefCell_, pRefValue_);
    mesh_.setFluxRequired(p_.name());
}


Foam::tmp<Foam::volScalarField> Foam::averagedFluid::mobility
(
    const volScalarField& rAU
) const
{
    const volScalarField& eps = coupling_.voidfraction();
    return coupling_.modelB() ? rAU*eps : rAU*sqr(eps);
}


Foam::PtrList<Foam::surfaceScalarField> Foam::averagedFluid::faceConductances
(
    const volScalarField& rAU,
    const volVectorField& HbyA
) const
{
    const volScalarField M(mobility(rAU));
    PtrList<surfaceScalarField> fields(4);
    const word names[4] = {"aOwn", "aNei", "xOwn", "xNei"};
    forAll(fields, i)
    {
        fields.set
        (
            i,
            new surfaceScalarField
            (
                IOobject(names[i], mesh_.time().timeName(), mesh_),
                mesh_,
                dimensionedScalar
                (
                    names[i],
                    i < 2 ? M.dimensions()/dimLength : dimVelocity,
                    0
                )
            )
        );
    }
    surfaceScalarField& aOwn = fields[AOWN];
    surfaceScalarField& aNei = fields[ANEI];
    surfaceScalarField& xOwn = fields[XOWN];
    surfaceScalarField& xNei = fields[XNEI];

    const volVectorField X(coupling_.voidfraction()*HbyA);
    const surfaceScalarField& w = mesh_.weights();
    const surfaceScalarField& dc = mesh_.nonOrthDeltaCoeffs();
    const surfaceVectorField n(mesh_.Sf()/mesh_.magSf());
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();

    // Owner and neighbour centres lie (1 - w)/dc and w/dc from the face
    forAll(own, facei)
    {
        aOwn[facei] = M[own[facei]]*dc[facei]/(1 - w[facei]);
        aNei[facei] = M[nei[facei]]*dc[facei]/w[facei];
        xOwn[facei] = X[own[facei]] & n[facei];
        xNei[facei] = X[nei[facei]] & n[facei];
    }

    forAll(mesh_.boundary(), patchi)
    {
        const scalarField& pw = w.boundaryField()[patchi];
        const scalarField& pdc = dc.boundaryField()[patchi];
        const vectorField& pn = n.boundaryField()[patchi];
        const scalarField MP(M.boundaryField()[patchi].patchInternalField());
        const vectorField XP(X.boundaryField()[patchi].patchInternalField());

        if (mesh_.boundary()[patchi].coupled())
        {
            aOwn.boundaryFieldRef()[patchi] = MP*pdc/(1 - pw);
            aNei.boundaryFieldRef()[patchi] =
                M.boundaryField()[patchi].patchNeighbourField()*pdc/pw;
            xOwn.boundaryFieldRef()[patchi] = XP & pn;
            xNei.boundaryFieldRef()[patchi] =
                X.boundaryField()[patchi].patchNeighbourField() & pn;
        }
        else
        {
            // The boundary value is the neighbour, on the face itself
            aOwn.boundaryFieldRef()[patchi] = MP*pdc;
            aNei.boundaryFieldRef()[patchi] = 0;
            xOwn.boundaryFieldRef()[patchi] = XP & pn;
            xNei.boundaryFieldRef()[patchi] = X.boundaryField()[patchi] & pn;
        }
    }

    return fields;
}


void Foam::averagedFluid::seriesFluxes
(
    const PtrList<surfaceScalarField>& faces,
    surfaceScalarField& phiX,
    surfaceScalarField& Dp
) const
{
    const surfaceScalarField& aOwn = faces[AOWN];
    const surfaceScalarField& aNei = faces[ANEI];
    const surfaceScalarField& xOwn = faces[XOWN];
    const surfaceScalarField& xNei = faces[XNEI];

    const surfaceScalarField& dc = mesh_.nonOrthDeltaCoeffs();

    // Flux q through a face between cells P and N: from each side
    // q = x_P + a_P (p_P - p_f) = x_N + a_N (p_f - p_N), so
    // q = (a_N x_P + a_P x_N)/(a_P + a_N) + a_P a_N/(a_P + a_N) (p_P - p_N)
    phiX = (aNei*xOwn + aOwn*xNei)/(aOwn + aNei)*mesh_.magSf();
    phiX.setOriented();     // a flux: its sign follows the face normal
    Dp = aOwn*aNei/((aOwn + aNei)*dc);
    Dp.setOriented(false);  // a coefficient (the delta coefficients are
                            // oriented in OpenFOAM v1912)

    // Boundaries other than coupled ones: the boundary's own eps HbyA
    // (U's value at fixed-U patches) and the cell's mobility
    forAll(mesh_.boundary(), patchi)
    {
        if (!mesh_.boundary()[patchi].coupled())
        {
            phiX.boundaryFieldRef()[patchi] =
                xNei.boundaryField()[patchi]*mesh_.magSf().boundaryField()[patchi];
            Dp.boundaryFieldRef()[patchi] =
                aOwn.boundaryField()[patchi]/dc.boundaryField()[patchi];
        }
    }
}


Foam::tmp<Foam::volVectorField> Foam::averagedFluid::pressureTerm
(
    const PtrList<surfaceScalarField>& faces
) const
{
    const surfaceScalarField& aOwn = faces[AOWN];
    const surfaceScalarField& aNei = faces[ANEI];
    const surfaceScalarField& xOwn = faces[XOWN];
    const surfaceScalarField& xNei = faces[XNEI];

    // p on each face from the same two relations: the pressure between
    // two resistances in series, so that each cell's pressure drop is the
    // one its fluxes carry
    surfaceScalarField pf(fvc::interpolate(p_));
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    forAll(own, facei)
    {
        pf[facei] =
        (
            aOwn[facei]*p_[own[facei]] + aNei[facei]*p_[nei[facei]]
          + xOwn[facei] - xNei[facei]
        )/(aOwn[facei] + aNei[facei]);
    }
    forAll(mesh_.boundary(), patchi)
    {
        if (mesh_.boundary()[patchi].coupled())
        {
            const volScalarField::Patch& pp = p_.boundaryField()[patchi];
            const scalarField& aO = aOwn.boundaryField()[patchi];
            const scalarField& aN = aNei.boundaryField()[patchi];
            pf.boundaryFieldRef()[patchi] =
            (
                aO*pp.patchInternalField() + aN*pp.patchNeighbourField()
              + xOwn.boundaryField()[patchi] - xNei.boundaryField()[patchi]
            )/(aO + aN);
        }
        // Other boundaries: p's own boundary value
    }

    const volVectorField gradp(fvc::surfaceIntegrate(mesh_.Sf()*pf));

    if (coupling_.modelB())
    {
        return -gradp;
    }
    return -coupling_.voidfraction()*gradp;
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
      + fvOptions_(U_)
    );
    fvVectorMatrix& UEqn = tUEqn.ref();

    UEqn.relax();
    fvOptions_.constrain(UEqn);

    if (pimple_.momentumPredictor())
    {
        const volScalarField rAU(1.0/UEqn.A());
        const volVectorField HbyA(constrainHbyA(rAU*UEqn.H(), U_, p_));
        Foam::solve(UEqn == pressureTerm(faceConductances(rAU, HbyA)));
        fvOptions_.correct(U_);
    }
    return tUEqn;
}


void Foam::averagedFluid::correctPressure(fvVectorMatrix& UEqn)
{
    const volScalarField& eps = coupling_.voidfraction();

    const volScalarField rAU(1.0/UEqn.A());

    // HbyA includes rAU S; at fixed-U boundaries (walls, inlets) it is U's
    // own value, so no fluid crosses a wall
    const volVectorField HbyA(constrainHbyA(rAU*UEqn.H(), U_, p_));

    // eps U = eps HbyA - M grad p in each cell; on the faces the series
    // formulas: phi = phiX - Dp snGrad(p) |Sf|
    surfaceScalarField phiX
    (
        IOobject("phiX", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar("phiX", dimVolume/dimTime, 0)
    );
    surfaceScalarField Dp
    (
        IOobject("Dp", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar("Dp", mobility(rAU)().dimensions(), 0)
    );
    // The faces' conductances, once for the fluxes and the cells'
    // pressure term of this correction
    const PtrList<surfaceScalarField> faces(faceConductances(rAU, HbyA));
    seriesFluxes(faces, phiX, Dp);

    const surfaceScalarField phiHbyA
    (
        "phiHbyA",
        phiX
        // Rhie-Chow's time-step correction (as in OpenFOAM's compressible
        // solvers, with eps in place of rho): without it the cell
        // velocities decouple from the fluxes at small time steps
      + fvc::interpolate(eps*rAU)*fvc::ddtCorr(eps, U_, phi_)
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

            U_ = HbyA + rAU*pressureTerm(faces);
            U_.correctBoundaryConditions();
            fvOptions_.correct(U_);
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
