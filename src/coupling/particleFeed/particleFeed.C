/*---------------------------------------------------------------------------*\
    colloidFoam: particles fed with the liquid through an inflow patch.
    See particleFeed.H.
\*---------------------------------------------------------------------------*/

#include "particleFeed.H"
#include "colloidModels/counterRandom.H"
#include "demUnits.H"
#include "keywordCheck.H"
#include "wallPolyPatch.H"
#include "boundBox.H"
#include "mathematicalConstants.H"
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace colloid::counterRandom;

// The feed's stream of random numbers (apart from the Brownian ones)
const std::uint64_t feedStream = 0x3c6ef372fe94f82bULL;

// The swept depth's allowance over the faces' largest inward velocity:
// the interpolated velocity inside a face may exceed the face values
const Foam::scalar depthAllowance = 1.25;

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

Foam::scalar Foam::particleFeed::inflow() const
{
    const polyPatch& pp = mesh_.boundaryMesh()[patchi_];
    const vectorField& Ub = U_.boundaryField()[patchi_];
    scalar Q = 0;
    forAll(pp, facei)
    {
        Q -= Ub[facei] & pp.faceAreas()[facei];
    }
    return returnReduce(Q, sumOp<scalar>());
}


Foam::scalar Foam::particleFeed::particleVolume() const
{
    return 4.0/3.0*constant::mathematical::pi*pow3(radius_);
}


Foam::scalar Foam::particleFeed::maxInwardVelocity() const
{
    const polyPatch& pp = mesh_.boundaryMesh()[patchi_];
    const vectorField& Ub = U_.boundaryField()[patchi_];
    scalar u = 0;
    forAll(pp, facei)
    {
        const vector& S = pp.faceAreas()[facei];
        u = max(u, -(Ub[facei] & S)/mag(S));
    }
    return returnReduce(u, maxOp<scalar>());
}


void Foam::particleFeed::gatherPatch()
{
    const polyPatch& pp = mesh_.boundaryMesh()[patchi_];
    const pointField& points = mesh_.points();

    // This rank's faces: centre, inward normal, and the face as a fan of
    // triangles from its lexicographically smallest point (the same
    // triangles however a decomposition rotated the face's points)
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    List<pointField> allCentres(nProcs), allTri(nProcs), allWalls(nProcs);
    List<vectorField> allInward(nProcs);
    List<labelList> allTriStart(nProcs);
    {
        DynamicList<point> tri;
        labelList triStart(pp.size() + 1, 0);
        vectorField inward(pp.size());
        forAll(pp, facei)
        {
            const face& f = pp[facei];
            inward[facei] = -pp.faceAreas()[facei]/mag(pp.faceAreas()[facei]);
            label first = 0;
            forAll(f, j)
            {
                const point& a = points[f[j]];
                const point& b = points[f[first]];
                if (a.x() < b.x() || (a.x() == b.x() && (a.y() < b.y()
                 || (a.y() == b.y() && a.z() < b.z()))))
                {
                    first = j;
                }
            }
            for (label j = 1; j + 1 < f.size(); ++j)
            {
                tri.append(points[f[first]]);
                tri.append(points[f[(first + j) % f.size()]]);
                tri.append(points[f[(first + j + 1) % f.size()]]);
            }
            triStart[facei + 1] = tri.size()/3;
        }
        allCentres[me] = pp.faceCentres();
        allInward[me] = inward;
        allTri[me] = tri;
        allTriStart[me] = triStart;
    }

    // Its edges where a wall patch meets it
    {
        // (the faces of the cell next to the edge's patch face that hold
        // both its points: no edge addressing of the whole mesh)
        DynamicList<point> walls;
        for (label e = pp.nInternalEdges(); e < pp.nEdges(); ++e)
        {
            const edge meshEdge
            (
                pp.meshPoints()[pp.edges()[e][0]],
                pp.meshPoints()[pp.edges()[e][1]]
            );
            const label celli =
                mesh_.faceOwner()[pp.start() + pp.edgeFaces()[e][0]];
            bool onWall = false;
            for (const label facei : mesh_.cells()[celli])
            {
                if (!mesh_.isInternalFace(facei))
                {
                    const label patchj = mesh_.boundaryMesh().whichPatch(facei);
                    const face& f = mesh_.faces()[facei];
                    onWall = onWall
                     || (
                            patchj != patchi_
                         && isA<wallPolyPatch>(mesh_.boundaryMesh()[patchj])
                         && f.found(meshEdge[0]) && f.found(meshEdge[1])
                        );
                }
            }
            if (onWall)
            {
                const edge& ed = pp.edges()[e];
                walls.append(pp.localPoints()[ed[0]]);
                walls.append(pp.localPoints()[ed[1]]);
            }
        }
        allWalls[me] = walls;
    }

    // Every rank's, on every rank (a patch is small beside the particles)
    Pstream::gatherList(allCentres);
    Pstream::scatterList(allCentres);
    Pstream::gatherList(allInward);
    Pstream::scatterList(allInward);
    Pstream::gatherList(allTri);
    Pstream::scatterList(allTri);
    Pstream::gatherList(allTriStart);
    Pstream::scatterList(allTriStart);
    Pstream::gatherList(allWalls);
    Pstream::scatterList(allWalls);

    // The faces in the order of their centres: the same list, and so the
    // same random positions, on any number of ranks
    DynamicList<FixedList<label, 2>> faces;     // (rank, local face)
    for (label proci = 0; proci < nProcs; ++proci)
    {
        forAll(allCentres[proci], facei)
        {
            faces.append(FixedList<label, 2>({proci, facei}));
        }
    }
    std::sort
    (
        faces.begin(),
        faces.end(),
        [&allCentres](const FixedList<label, 2>& a, const FixedList<label, 2>& b)
        {
            const point& p = allCentres[a[0]][a[1]];
            const point& q = allCentres[b[0]][b[1]];
            return p.x() < q.x() || (p.x() == q.x() && (p.y() < q.y()
                || (p.y() == q.y() && p.z() < q.z())));
        }
    );

    DynamicList<point> gTri;
    DynamicList<label> gTriFace;
    faceProc_.setSize(faces.size());
    faceLocal_.setSize(faces.size());
    faceInward_.setSize(faces.size());
    forAll(faces, g)
    {
        const label proci = faces[g][0];
        const label facei = faces[g][1];
        faceProc_[g] = proci;
        faceLocal_[g] = facei;
        faceInward_[g] = allInward[proci][facei];
        for
        (
            label t = allTriStart[proci][facei];
            t < allTriStart[proci][facei + 1];
            ++t
        )
        {
            for (label c = 0; c < 3; ++c)
            {
                gTri.append(allTri[proci][3*t + c]);
            }
            gTriFace.append(g);
        }
    }
    triPoints_.transfer(gTri);
    triFace_.transfer(gTriFace);
    wallEdges_.clear();
    for (const pointField& walls : allWalls)
    {
        wallEdges_.append(walls);
    }

    triCumArea_.setSize(triFace_.size());
    scalar sum = 0;
    forAll(triFace_, t)
    {
        const point& a = triPoints_[3*t];
        sum += 0.5*mag((triPoints_[3*t + 1] - a) ^ (triPoints_[3*t + 2] - a));
        triCumArea_[t] = sum;
    }
}


Foam::scalar Foam::particleFeed::wallDistance(const point& p) const
{
    scalar d = GREAT;
    for (label e = 0; e + 1 < wallEdges_.size(); e += 2)
    {
        const point& a = wallEdges_[e];
        const vector ab = wallEdges_[e + 1] - a;
        const scalar t = min(max(((p - a) & ab)/max(magSqr(ab), VSMALL), 0), 1);
        d = min(d, mag(p - (a + t*ab)));
    }
    return d;
}


bool Foam::particleFeed::due(const long step) const
{
    return step > 0 && step % stepsPerInsertion_ == 0;
}


void Foam::particleFeed::insert
(
    liggghtsEngine& dem,
    const cellPointInterpolator& UInterp
)
{
    const label k = label(dem.timeStep()/stepsPerInsertion_);
    const scalar T = interval_;
    const scalar R = solidsFraction_*inflow()/particleVolume();     // [1/s]
    const label N =
        label(std::floor(k*R*T)) - label(std::floor((k - 1)*R*T));
    if (N <= 0)
    {
        Info<< "Feed: 0 particles (" << nPlaced_ << " placed by this run)"
            << endl;
        return;
    }
    const scalar D = depthAllowance*maxInwardVelocity()*T;
    if (D > cellDepth_)
    {
        FatalErrorInFunction
            << "Keyword 'interval' in " << dictName_ << " is " << interval_
            << " s: the liquid now moves up to " << D << " m into the fluid"
            << " in it, deeper than the cells next to patch "
            << mesh_.boundaryMesh()[patchi_].name() << " (" << cellDepth_
            << " m; the inflow has grown since the start-up)"
            << exit(FatalError);
    }

    // The DEM box's periods [m] (zero: not periodic)
    double lo[3], hi[3];
    bool periodic[3];
    dem.box(lo, hi, periodic);
    vector period(Zero);
    for (direction c = 0; c < 3; ++c)
    {
        period[c] = periodic[c] ? demUnits::length*(hi[c] - lo[c]) : 0;
    }
    auto minImage = [&period](vector d)
    {
        for (direction c = 0; c < 3; ++c)
        {
            if (period[c] > 0)
            {
                d[c] -= period[c]*std::round(d[c]/period[c]);
            }
        }
        return d;
    };

    // This rank's particles that a candidate could come close to
    double** x = dem.x();
    const double* r = dem.radius();
    scalar rMax = radius_;
    for (int i = 0; i < dem.nLocal(); ++i)
    {
        rMax = max(rMax, demUnits::length*r[i]);
    }
    boundBox reach(triPoints_, false);
    reach.min() -= vector::one*(D + radius_ + rMax + minimumGap_);
    reach.max() += vector::one*(D + radius_ + rMax + minimumGap_);
    DynamicList<point> near;
    DynamicList<scalar> nearR;
    const point centre = reach.centre();
    for (int i = 0; i < dem.nLocal(); ++i)
    {
        // the image nearest the patch
        const point p = centre
          + minImage(demUnits::length*point(x[i][0], x[i][1], x[i][2]) - centre);
        if (reach.contains(p))
        {
            near.append(p);
            nearR.append(demUnits::length*r[i]);
        }
    }

    const polyPatch& pp = mesh_.boundaryMesh()[patchi_];
    const label me = Pstream::myProcNo();
    const std::uint64_t kKey = mix64(key_ ^ std::uint64_t(k));
    const label maxCandidates = 100*N + 1000;
    DynamicList<point> placed;
    DynamicList<vector> placedU;
    label nClipped = 0;
    label j = 0;
    while (placed.size() < N && j < maxCandidates)
    {
        // A round of candidates, the same on every rank
        const label M = min(2*(N - placed.size()) + 16, maxCandidates - j);
        pointField cand(M), onPatch(M);
        labelList candFace(M);
        scalarField depth(M);
        for (label m = 0; m < M; ++m)
        {
            const std::uint64_t n = 4*std::uint64_t(j + m);
            const scalar area =
                uniformOpen(counterWord(kKey, n))*triCumArea_.last();
            const label t = min
            (
                label(std::upper_bound(triCumArea_.begin(), triCumArea_.end(), area)
              - triCumArea_.begin()),
                triCumArea_.size() - 1
            );
            scalar a = uniformOpen(counterWord(kKey, n + 1));
            scalar b = uniformOpen(counterWord(kKey, n + 2));
            if (a + b > 1)
            {
                a = 1 - a;
                b = 1 - b;
            }
            const point& p0 = triPoints_[3*t];
            onPatch[m] =
                p0 + a*(triPoints_[3*t + 1] - p0) + b*(triPoints_[3*t + 2] - p0);
            candFace[m] = triFace_[t];
            depth[m] = uniformOpen(counterWord(kKey, n + 3))*D;
            cand[m] = onPatch[m] + depth[m]*faceInward_[candFace[m]];
        }

        // The liquid's velocity there (the rank of the face's cell), and
        // whether a particle of some rank is too close
        vectorField Uc(M, Zero);
        labelList blocked(M, 0);
        for (label m = 0; m < M; ++m)
        {
            if (faceProc_[candFace[m]] == me)
            {
                const label celli =
                    mesh_.faceOwner()[pp.start() + faceLocal_[candFace[m]]];
                Uc[m] = UInterp.interpolate(cand[m], celli);
            }
            forAll(near, i)
            {
                if
                (
                    magSqr(minImage(cand[m] - near[i]))
                  < sqr(radius_ + nearR[i] + minimumGap_)
                )
                {
                    blocked[m] = 1;
                    break;
                }
            }
        }
        Pstream::listCombineGather(Uc, plusEqOp<vector>());
        Pstream::listCombineScatter(Uc);
        Pstream::listCombineGather(blocked, maxEqOp<label>());
        Pstream::listCombineScatter(blocked);

        // Accepted in order: in the swept region, clear of walls, of the
        // particles present and of those placed before
        for (label m = 0; m < M && placed.size() < N; ++m)
        {
            const scalar un = Uc[m] & faceInward_[candFace[m]];
            if (un*T > D)
            {
                ++nClipped;
            }
            if (!(depth[m] < un*T) || blocked[m])
            {
                continue;
            }
            if (wallDistance(onPatch[m]) < radius_ + minimumGap_)
            {
                continue;
            }
            bool clear = true;
            for (const point& q : placed)
            {
                if (magSqr(minImage(cand[m] - q)) < sqr(2*radius_ + minimumGap_))
                {
                    clear = false;
                    break;
                }
            }
            if (clear)
            {
                placed.append(cand[m]);
                placedU.append(Uc[m]);
            }
        }
        j += M;
    }

    std::vector<double> xs(3*placed.size()), vs(3*placed.size());
    forAll(placed, a)
    {
        for (direction c = 0; c < 3; ++c)
        {
            xs[3*a + c] = placed[a][c]/demUnits::length;
            vs[3*a + c] = placedU[a][c]/demUnits::velocity;
        }
    }
    if
    (
        !dem.queueAtoms
        (
            xs, vs, radius_/demUnits::length, density_/demUnits::density,
            int(atomType_)
        )
    )
    {
        FatalErrorInFunction
            << "Keyword 'atomType' in " << dictName_ << " is " << atomType_
            << ": the DEM has no such atom type (its script's create_box or"
            << " read_data defines them)" << exit(FatalError);
    }
    nQueued_ = placed.size();

    Info<< "Feed: " << nQueued_ << " particles (" << nPlaced_ + nQueued_
        << " placed by this run)";
    if (placed.size() < N)
    {
        Info<< "; " << N - placed.size() << " of the " << N << " due did"
            << " not fit in " << j << " candidates (minimumGap "
            << minimumGap_ << " m, solidsFraction " << solidsFraction_
            << "): the region below the patch is crowded";
    }
    if (nClipped)
    {
        Info<< "; " << nClipped << " candidates where the liquid moves"
            << " faster than " << depthAllowance << " x the patch's"
            << " fastest face (their swept region is cut short)";
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::particleFeed::particleFeed
(
    const dictionary& dict,
    const volVectorField& U,
    const scalar diameter,
    const scalar density,
    const label couplingInterval,
    const scalar demTimeStep
)
:
    mesh_(U.mesh()),
    U_(U),
    patchi_(-1),
    solidsFraction_(0),
    minimumGap_(0),
    interval_(0),
    stepsPerInsertion_(0),
    key_(0),
    atomType_(1),
    radius_(0.5*diameter),
    density_(density),
    cellDepth_(GREAT),
    dictName_(dict.name()),
    nPlaced_(0),
    nQueued_(0)
{
    keywordCheck
    (
        dict,
        {"patch", "solidsFraction", "minimumGap", "interval", "seed", "atomType"},
        true
    );

    const word patchName = dict.get<word>("patch");
    patchi_ = mesh_.boundaryMesh().findPatchID(patchName);
    if (patchi_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'patch' in " << dict.name() << " is " << patchName
            << "; allowed: a patch of the mesh, "
            << mesh_.boundaryMesh().names() << exit(FatalIOError);
    }

    solidsFraction_ = dict.get<scalar>("solidsFraction");
    if (!(solidsFraction_ > 0 && solidsFraction_ <= 0.5))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'solidsFraction' in " << dict.name() << " is "
            << solidsFraction_ << "; allowed range: (0, 0.5]"
            << exit(FatalIOError);
    }

    minimumGap_ = dict.get<scalar>("minimumGap");
    if (!(minimumGap_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'minimumGap' in " << dict.name() << " is "
            << minimumGap_ << "; allowed range: >= 0 m"
            << exit(FatalIOError);
    }

    interval_ = dict.get<scalar>("interval");
    const scalar couplingStep = couplingInterval*demTimeStep;
    const label every = label(std::round(interval_/couplingStep));
    if (every < 1 || mag(every*couplingStep - interval_) > 1e-6*couplingStep)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'interval' in " << dict.name() << " is " << interval_
            << " s; allowed: a whole number (1 or more) of coupling steps of "
            << couplingStep << " s (DEM timeStep x couplingInterval)"
            << exit(FatalIOError);
    }
    stepsPerInsertion_ = every*couplingInterval;

    const label seed = dict.get<label>("seed");
    if (seed < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'seed' in " << dict.name() << " is " << seed
            << "; allowed range: integer 1 to 2e9" << exit(FatalIOError);
    }
    key_ = mix64(mix64(std::uint64_t(seed)) ^ feedStream);

    atomType_ = dict.lookupOrDefault<label>("atomType", 1);
    if (atomType_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'atomType' in " << dict.name() << " is " << atomType_
            << "; allowed range: an atom type of the DEM, 1 or more"
            << exit(FatalIOError);
    }

    gatherPatch();

    const scalar Q = inflow();
    if (!(Q > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'patch' in " << dict.name() << " is " << patchName
            << ": the liquid does not flow in through it (inflow " << Q
            << " m^3/s); allowed: a patch with inflow"
            << exit(FatalIOError);
    }

    // The swept depth stays within the patch's cells: the candidates'
    // velocity is interpolated in the cell next to their face
    const polyPatch& pp = mesh_.boundaryMesh()[patchi_];
    scalar cellDepth = GREAT;
    forAll(pp, facei)
    {
        const vector n = pp.faceAreas()[facei]/mag(pp.faceAreas()[facei]);
        const label celli = mesh_.faceOwner()[pp.start() + facei];
        cellDepth = min
        (
            cellDepth,
            2*((pp.faceCentres()[facei] - mesh_.cellCentres()[celli]) & n)
        );
    }
    reduce(cellDepth, minOp<scalar>());
    cellDepth_ = cellDepth;
    const scalar uMax = maxInwardVelocity();
    const scalar D = depthAllowance*uMax*interval_;
    if (D > cellDepth)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'interval' in " << dict.name() << " is " << interval_
            << " s: the liquid moves up to " << D << " m into the fluid in"
            << " it (" << depthAllowance << " x its fastest inflow " << uMax
            << " m/s), deeper than the cells next to patch " << patchName
            << " (" << cellDepth << " m); allowed range: interval <= "
            << cellDepth/(depthAllowance*uMax) << " s"
            << exit(FatalIOError);
    }

    Info<< "Feed: through patch " << patchName << ", inflow " << Q
        << " m^3/s at solids fraction " << solidsFraction_ << ": "
        << solidsFraction_*Q/particleVolume()*interval_ << " particles every " << interval_
        << " s, at least " << minimumGap_ << " m from particles and walls ("
        << wallEdges_.size()/2 << " wall edges)" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::particleFeed::checkInserted(const liggghtsEngine& dem)
{
    if (!nQueued_)
    {
        return;
    }
    const long created = dem.queuedAtomsCreated();
    if (created != nQueued_)
    {
        FatalErrorInFunction
            << "The feed through patch "
            << mesh_.boundaryMesh()[patchi_].name() << " placed " << nQueued_
            << " particles, of which the DEM created " << created
            << ": the others lie outside the DEM's box; make the box hold"
            << " the fluid's cells next to the patch (" << dictName_ << ")"
            << exit(FatalError);
    }
    nPlaced_ += created;
    nQueued_ = 0;
}


// ************************************************************************* //
