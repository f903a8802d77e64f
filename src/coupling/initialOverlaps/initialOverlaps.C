#include "initialOverlaps.H"
#include "demUnits.H"
#include "pointField.H"
#include "scalarField.H"
#include "labelList.H"
#include "DynamicList.H"
#include "PstreamBuffers.H"
#include "HashTable.H"
#include "FixedList.H"
#include "OStringStream.H"
#include "boundBox.H"

#include <algorithm>

namespace
{

// Particles as the check sees them: centre [um], radius [um], id, and
// whether the check is about it (all, or those just inserted)
struct sphereSet
{
    Foam::DynamicList<Foam::point> x;
    Foam::DynamicList<Foam::scalar> r;
    Foam::DynamicList<Foam::label> id;
    Foam::DynamicList<bool> checked;

    void append
    (
        const Foam::point& p,
        const Foam::scalar radius,
        const Foam::label i,
        const bool check
    )
    {
        x.append(p);
        r.append(radius);
        id.append(i);
        checked.append(check);
    }
};

// Overlap limits, as fractions of the smaller radius
constexpr Foam::scalar stopFraction = 0.1;
constexpr Foam::scalar warnFraction = 0.01;

// A pair found overlapping: ids, centres [um], overlap / smaller radius
struct overlapPair
{
    Foam::label a, b;
    Foam::point xa, xb;
    Foam::scalar fraction;
};

} // End anonymous namespace


void Foam::checkInitialOverlaps
(
    const liggghtsEngine& dem,
    const fileName& script,
    const boolList* inserted
)
{
    // How the log and the messages name the particles checked
    const bool initial = !inserted;
    const char* who = initial ? "Initial particles" : "Inserted particles";
    const char* what =
        initial
      ? "the DEM's initial particles"
      : "the particles the DEM inserted during the run";

    const int n = dem.nLocal();
    double** x = dem.x();
    const double* r = dem.radius();
    const int* tag = dem.tag();

    double boxLo[3], boxHi[3], subLo[3], subHi[3];
    bool periodic[3];
    dem.box(boxLo, boxHi, periodic);
    dem.subBox(subLo, subHi);

    scalar rMax = 0;
    for (int i = 0; i < n; ++i)
    {
        rMax = max(rMax, r[i]);
    }
    reduce(rMax, maxOp<scalar>());
    if (rMax <= 0)
    {
        return;
    }
    const scalar layer = 4*rMax;    // two largest diameters

    // This rank's particles, and those near its part of the box
    sphereSet local;
    sphereSet nearFaces;
    for (int i = 0; i < n; ++i)
    {
        const point p(x[i][0], x[i][1], x[i][2]);
        const bool check = initial || (*inserted)[i];
        local.append(p, r[i], tag[i], check);
        bool near = false;
        for (direction k = 0; k < 3; ++k)
        {
            near = near || p[k] - subLo[k] < layer || subHi[k] - p[k] < layer;
        }
        if (near)
        {
            nearFaces.append(p, r[i], tag[i], check);
        }
    }

    // Candidates: own particles, the other ranks' near-face particles
    sphereSet candidates(local);
    if (Pstream::parRun())
    {
        PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
        for (label proci = 0; proci < Pstream::nProcs(); ++proci)
        {
            if (proci != Pstream::myProcNo())
            {
                UOPstream os(proci, buffers);
                os << pointField(nearFaces.x) << scalarField(nearFaces.r)
                   << labelList(nearFaces.id) << boolList(nearFaces.checked);
            }
        }
        buffers.finishedSends();
        for (label proci = 0; proci < Pstream::nProcs(); ++proci)
        {
            if (proci != Pstream::myProcNo())
            {
                UIPstream is(proci, buffers);
                pointField px;
                scalarField pr;
                labelList pid;
                boolList pc;
                is >> px >> pr >> pid >> pc;
                forAll(px, j)
                {
                    candidates.append(px[j], pr[j], pid[j], pc[j]);
                }
            }
        }
    }

    // Periodic images of the candidates near the box's periodic faces
    for (direction k = 0; k < 3; ++k)
    {
        if (!periodic[k])
        {
            continue;
        }
        const scalar length = boxHi[k] - boxLo[k];
        const label nBefore = candidates.x.size();
        for (label j = 0; j < nBefore; ++j)
        {
            point p = candidates.x[j];
            if (p[k] - boxLo[k] < layer)
            {
                p[k] += length;
            }
            else if (boxHi[k] - p[k] < layer)
            {
                p[k] -= length;
            }
            else
            {
                continue;
            }
            candidates.append
            (
                p, candidates.r[j], candidates.id[j], candidates.checked[j]
            );
        }
    }

    // Candidates in cells of one largest diameter and a radius: every pair
    // with a gap below one largest radius is found (the smallest gap of
    // the report), and every overlapping one
    const scalar h = 3*rMax;
    auto cellOf = [&](const point& p)
    {
        return FixedList<label, 3>
        ({
            label(std::floor(p.x()/h)),
            label(std::floor(p.y()/h)),
            label(std::floor(p.z()/h))
        });
    };
    // After an insertion only the neighbourhood of the particles checked
    // matters: the box around them, one cell wider (every pair with a gap
    // below one largest radius is closer than h).  Without it every
    // insertion hashed all particles (0.36 s at 2e5 particles, a third of
    // the coupling's work in a 1000-step benchmark run with one
    // insertion); now the hashing and the pair search grow with the
    // particles inserted, the gathering above stays a pass over all.
    boundBox reach(boundBox::invertedBox);
    forAll(candidates.x, j)
    {
        if (candidates.checked[j])
        {
            reach.add(candidates.x[j]);
        }
    }
    if (reach.valid())
    {
        reach.min() -= point::uniform(h);
        reach.max() += point::uniform(h);
    }
    auto inReach = [&](const point& p)
    {
        return initial || reach.contains(p);
    };

    HashTable<DynamicList<label>, FixedList<label, 3>,
        FixedList<label, 3>::Hash<>> grid;
    forAll(candidates.x, j)
    {
        if (inReach(candidates.x[j]))
        {
            grid(cellOf(candidates.x[j])).append(j);
        }
    }

    // Each pair once: from the particle with the lower id, where it lives;
    // the smallest gap [DEM length] of this rank and its pair
    DynamicList<overlapPair> pairs;
    FixedList<scalar, 4> smallest({GREAT, -1, -1, 0});
    forAll(local.x, i)
    {
        if (!inReach(local.x[i]))
        {
            continue;
        }
        const FixedList<label, 3> c = cellOf(local.x[i]);
        for (label a = -1; a <= 1; ++a)
        for (label b = -1; b <= 1; ++b)
        for (label e = -1; e <= 1; ++e)
        {
            const auto iter =
                grid.cfind(FixedList<label, 3>({c[0] + a, c[1] + b, c[2] + e}));
            if (!iter.found())
            {
                continue;
            }
            for (const label j : *iter)
            {
                if
                (
                    candidates.id[j] <= local.id[i]
                 || !(local.checked[i] || candidates.checked[j])
                )
                {
                    continue;
                }
                const scalar dist = mag(candidates.x[j] - local.x[i]);
                const scalar rMin = min(local.r[i], candidates.r[j]);
                const scalar gap = dist - local.r[i] - candidates.r[j];
                if (gap < smallest[0])
                {
                    smallest = {gap, scalar(local.id[i]), scalar(candidates.id[j]), rMin};
                }
                const scalar fraction =
                    (local.r[i] + candidates.r[j] - dist)/rMin;
                if (fraction > warnFraction)
                {
                    pairs.append
                    ({
                        local.id[i], candidates.id[j],
                        local.x[i], candidates.x[j], fraction
                    });
                }
            }
        }
    }

    // The smallest gap of all ranks, in the log (seed 000's fill has no
    // contacts by construction: a fill should leave a stated gap)
    List<FixedList<scalar, 4>> each(Pstream::nProcs());
    each[Pstream::myProcNo()] = smallest;
    Pstream::gatherList(each);
    if (Pstream::master())
    {
        for (const FixedList<scalar, 4>& s : each)
        {
            if (s[0] < smallest[0])
            {
                smallest = s;
            }
        }
        if (smallest[0] < rMax)
        {
            Info<< who << ": smallest gap "
                << demUnits::length*smallest[0] << " m ("
                << 100*smallest[0]/smallest[3] << " % of the smaller radius),"
                << " between particles " << label(smallest[1]) << " and "
                << label(smallest[2]) << endl;
        }
        else
        {
            Info<< who << ": no two closer than one largest radius"
                << " (gap " << demUnits::length*rMax << " m)" << endl;
        }
    }

    // Report: counts over all ranks, the worst pairs of each rank
    label nWarn = 0, nStop = 0;
    for (const overlapPair& p : pairs)
    {
        (p.fraction > stopFraction ? nStop : nWarn)++;
    }
    reduce(nWarn, sumOp<label>());
    reduce(nStop, sumOp<label>());
    if (nWarn + nStop == 0)
    {
        return;
    }

    std::sort
    (
        pairs.begin(), pairs.end(),
        [](const overlapPair& p, const overlapPair& q)
        { return p.fraction > q.fraction; }
    );
    OStringStream list;
    for (label k = 0; k < min(label(5), pairs.size()); ++k)
    {
        const overlapPair& p = pairs[k];
        list<< nl << "    particles " << p.a << " at "
            << demUnits::length*p.xa << " m and " << p.b << " at "
            << demUnits::length*p.xb << " m: overlap "
            << 100*p.fraction << " % of the smaller radius"
            << (p.fraction > 1.9 ? " (centres nearly coincide)" : "");
    }
    List<string> lists(Pstream::nProcs());
    lists[Pstream::myProcNo()] = list.str();
    Pstream::gatherList(lists);     // text of at most 5 pairs per rank
    string text;
    for (const string& s : lists)
    {
        text += s;
    }
    // Every rank holds the message: the first to stop ends the run
    Pstream::scatter(text);

    if (nStop)
    {
        FatalErrorInFunction
            << nStop << " pairs of " << what << " (DEM script "
            << script << ") overlap by more than " << 100*stopFraction
            << " % of the smaller radius, the worst:" << text.c_str() << nl
            << "Place the particles apart (a fill with a minimum gap, or"
            << " the data file's coordinates)" << exit(FatalError);
    }
    WarningInFunction
        << nWarn << " pairs of " << what << " (DEM script "
        << script << ") overlap by more than " << 100*warnFraction
        << " % of the smaller radius (their elastic energy is released in"
        << " the first steps), the worst:" << text.c_str() << endl;
}
