#include "satelliteKernel.H"
#include "couplingProperties.H"
#include "addToRunTimeSelectionTable.H"
#include "processorPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "cyclicPolyPatch.H"
#include "PstreamBuffers.H"
#include "mathematicalConstants.H"
#include "UPtrList.H"

namespace Foam
{
    defineTypeNameAndDebug(satelliteKernel, 0);
    addToRunTimeSelectionTable(depositKernel, satelliteKernel, dictionary);
}


Foam::satelliteKernel::satelliteKernel
(
    const couplingProperties& props,
    const fvMesh& mesh,
    const particleLocator& locator,
    const cellPointInterpolator&
)
:
    mesh_(mesh),
    locator_(locator),
    kernelRadius_(props.kernelRadius()),
    satellites_(nShells_*nDirections_),
    procPatchOfNeighbour_(Pstream::nProcs(), -1),
    nRecords_(0)
{
    // Equal-volume shells: the point of shell k at the radius that halves
    // the shell's volume; directions on a Fibonacci lattice (equal areas)
    const scalar golden = constant::mathematical::pi*(3 - sqrt(5.0));
    label k = 0;
    for (label shell = 0; shell < nShells_; ++shell)
    {
        const scalar radius = cbrt((shell + 0.5)/nShells_);
        for (label j = 0; j < nDirections_; ++j)
        {
            const scalar z = 1 - (2*j + 1.0)/nDirections_;
            const scalar rho = sqrt(max(0.0, 1 - z*z));
            const scalar phi = golden*(j + shell*nDirections_);
            satellites_[k++] =
                radius*vector(rho*cos(phi), rho*sin(phi), z);
        }
    }

    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if
        (
            isA<processorPolyPatch>(pp)
         && !isA<processorCyclicPolyPatch>(pp)
        )
        {
            procPatchOfNeighbour_
            [
                refCast<const processorPolyPatch>(pp).neighbProcNo()
            ] = pp.index();
        }
    }
}


Foam::Ostream& Foam::operator<<(Ostream& os, const depositShare& t)
{
    os  << t.p << token::SPACE << t.weight << token::SPACE << t.volume
        << token::SPACE << t.dragCoeff << token::SPACE << t.force
        << token::SPACE << t.originProc << token::SPACE << t.originIndex
        << token::SPACE << t.originCell << token::SPACE << t.face;
    return os;
}


Foam::Istream& Foam::operator>>(Istream& is, depositShare& t)
{
    is  >> t.p >> t.weight >> t.volume >> t.dragCoeff >> t.force
        >> t.originProc >> t.originIndex >> t.originCell >> t.face;
    return is;
}


void Foam::satelliteKernel::add
(
    const depositShare& t,
    const label celli,
    scalarField& solidVolume,
    scalarField& dragCoeff,
    vectorField& dragForce
)
{
    solidVolume[celli] += t.volume;
    dragCoeff[celli] += t.dragCoeff;
    dragForce[celli] += t.force;

    sampleCell_.append(celli);
    sampleWeight_.append(t.weight);
    sampleProc_.append(t.originProc);
    sampleIndex_.append(t.originIndex);
}


void Foam::satelliteKernel::depositPoint
(
    const depositShare& t,
    const label celli,
    scalarField& solidVolume,
    scalarField& dragCoeff,
    vectorField& dragForce,
    List<DynamicList<depositShare>>& toProc,
    List<DynamicList<depositShare>>& toOrigin
)
{
    const vectorField& Cf = mesh_.faceCentres();

    depositShare here(t);
    label lastCell = celli;
    label exitFace = -1;
    label target = locator_.walkFrom(here.p, celli, lastCell, exitFace);

    // Across translational cyclic patches: the point's image, from the
    // cell behind the matching face (a few crossings at most)
    for (label crossing = 0; crossing < 3 && target < 0 && exitFace >= 0; ++crossing)
    {
        const polyPatch& pp =
            mesh_.boundaryMesh()[mesh_.boundaryMesh().whichPatch(exitFace)];
        if (!isA<cyclicPolyPatch>(pp))
        {
            break;
        }
        const cyclicPolyPatch& cpp = refCast<const cyclicPolyPatch>(pp);
        if (!cpp.parallel())
        {
            break;      // rotational: treated as outside the fluid
        }
        const label nbrFace = cpp.neighbPatch().start() + exitFace - pp.start();
        here.p += Cf[nbrFace] - Cf[exitFace];
        target = locator_.walkFrom
        (
            here.p, mesh_.faceOwner()[nbrFace], lastCell, exitFace
        );
    }

    if (target < 0 && exitFace >= 0)
    {
        const polyPatch& pp =
            mesh_.boundaryMesh()[mesh_.boundaryMesh().whichPatch(exitFace)];
        if (isA<processorPolyPatch>(pp) && !isA<processorCyclicPolyPatch>(pp))
        {
            here.face = exitFace - pp.start();
            toProc[refCast<const processorPolyPatch>(pp).neighbProcNo()]
                .append(here);
            return;
        }
    }
    if (target < 0 && exitFace < 0)
    {
        // The walk did not settle (concave polyhedra): search this mesh
        // part.  (A point beyond a wall, inlet or outlet face is outside
        // the fluid: no search, most kernel points near walls are.)
        target = locator_.findCell(here.p, -1);
    }
    if (target >= 0)
    {
        add(t, target, solidVolume, dragCoeff, dragForce);
    }
    else if (t.originProc == Pstream::myProcNo())
    {
        // Outside the fluid: the particle's own cell keeps the volume
        add(t, t.originCell, solidVolume, dragCoeff, dragForce);
    }
    else
    {
        toOrigin[t.originProc].append(t);
    }
}


void Foam::satelliteKernel::depositShares
(
    const pointField& x,
    const labelList& cell,
    const scalarField& r,
    const scalarField& K,
    const vectorField& F,
    scalarField& solidVolume,
    scalarField& dragCoeff,
    vectorField& dragForce
)
{
    nRecords_ = x.size();
    sampleCell_.clear();
    sampleWeight_.clear();
    sampleProc_.clear();
    sampleIndex_.clear();

    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    const scalar share = 1.0/satellites_.size();

    List<DynamicList<depositShare>> toProc(nProcs);
    List<DynamicList<depositShare>> toOrigin(nProcs);

    DynamicList<vector> crossedNormal(8);
    DynamicList<scalar> crossedDist(8);

    forAll(x, i)
    {
        const scalar vol = 4.0/3.0*constant::mathematical::pi*pow3(r[i]);
        const label celli = cell[i];

        const scalar R = max(r[i], kernelRadius_);

        depositShare t{x[i], 1.0, vol, K[i], F[i], me, i, celli, -1};

        // Face planes of the cell that the kernel sphere crosses: outward
        // normal and the centre's distance inside the plane
        crossedNormal.clear();
        crossedDist.clear();
        for (const cellPlane& plane : locator_.planes(celli))
        {
            const scalar inside = -((x[i] - plane.centre) & plane.normal);
            if (inside < R)
            {
                crossedNormal.append(plane.normal);
                crossedDist.append(inside);
            }
        }

        if (crossedNormal.empty())
        {
            add(t, celli, solidVolume, dragCoeff, dragForce);
            continue;
        }

        t.weight = share;
        t.volume *= share;
        t.dragCoeff *= share;
        t.force *= share;
        const bool convex = locator_.convex(celli);
        for (const vector& s : satellites_)
        {
            t.p = x[i] + R*s;

            // In a convex cell a point inside the crossed planes is inside
            // the cell (the other planes are beyond the sphere): no walk
            bool inCell = convex;
            forAll(crossedNormal, k)
            {
                if (inCell && R*(s & crossedNormal[k]) > crossedDist[k])
                {
                    inCell = false;
                }
            }
            if (inCell)
            {
                add(t, celli, solidVolume, dragCoeff, dragForce);
                continue;
            }

            depositPoint
            (
                t, celli, solidVolume, dragCoeff, dragForce, toProc, toOrigin
            );
        }
    }

    if (!Pstream::parRun())
    {
        return;
    }

    // Points that left through processor patches: continue the walk on the
    // neighbour from the cell behind the same face.  A point may cross more
    // than one processor boundary: repeat until none is in transit.
    const label maxRounds = 10;
    for (label round = 0; round < maxRounds; ++round)
    {
        label nInTransit = 0;
        forAll(toProc, proci)
        {
            nInTransit += toProc[proci].size();
        }
        if (!returnReduce(nInTransit, sumOp<label>()))
        {
            break;
        }

        PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
        for (label proci = 0; proci < nProcs; ++proci)
        {
            if (toProc[proci].size())
            {
                UOPstream os(proci, buffers);
                os << toProc[proci];
                toProc[proci].clear();
            }
        }
        labelList sizes;
        buffers.finishedSends(sizes);

        for (label proci = 0; proci < nProcs; ++proci)
        {
            if (!sizes[proci])
            {
                continue;
            }
            UIPstream is(proci, buffers);
            const List<depositShare> arrived(is);

            const polyPatch& pp =
                mesh_.boundaryMesh()[procPatchOfNeighbour_[proci]];
            for (const depositShare& t : arrived)
            {
                const label start = pp.faceCells()[t.face];
                if (round == maxRounds - 1)
                {
                    // Give up walking: the cell behind the face
                    add(t, start, solidVolume, dragCoeff, dragForce);
                    continue;
                }
                depositPoint
                (
                    t, start, solidVolume, dragCoeff, dragForce,
                    toProc, toOrigin
                );
            }
        }
    }

    // Shares outside the fluid, back to their particles' cells
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (toOrigin[proci].size())
        {
            UOPstream os(proci, buffers);
            os << toOrigin[proci];
        }
    }
    labelList sizes;
    buffers.finishedSends(sizes);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (sizes[proci])
        {
            UIPstream is(proci, buffers);
            for (const depositShare& t : List<depositShare>(is))
            {
                add(t, t.originCell, solidVolume, dragCoeff, dragForce);
            }
        }
    }
}


void Foam::satelliteKernel::sampleFields
(
    const volScalarField& s,
    const UPtrList<const volVectorField>& v,
    scalarField& sAtRecords,
    List<vectorField>& vAtRecords
) const
{
    const label nv = v.size();
    sAtRecords.setSize(nRecords_);
    sAtRecords = 0;
    vAtRecords.setSize(nv);
    for (vectorField& f : vAtRecords)
    {
        f.setSize(nRecords_);
        f = Zero;
    }

    const label me = Pstream::myProcNo();
    const label nProcs = Pstream::nProcs();

    // Points of other ranks' particles: their weighted values go back,
    // per point the scalar and then each vector's components
    const label width = 1 + 3*nv;
    List<DynamicList<label>> backIndex(nProcs);
    List<DynamicList<scalar>> backValue(nProcs);

    forAll(sampleCell_, j)
    {
        const label celli = sampleCell_[j];
        const scalar w = sampleWeight_[j];
        if (sampleProc_[j] == me)
        {
            const label i = sampleIndex_[j];
            sAtRecords[i] += w*s[celli];
            for (label k = 0; k < nv; ++k)
            {
                vAtRecords[k][i] += w*v[k][celli];
            }
        }
        else
        {
            const label proci = sampleProc_[j];
            backIndex[proci].append(sampleIndex_[j]);
            backValue[proci].append(w*s[celli]);
            for (label k = 0; k < nv; ++k)
            {
                const vector value = w*v[k][celli];
                backValue[proci].append(value.x());
                backValue[proci].append(value.y());
                backValue[proci].append(value.z());
            }
        }
    }

    if (!Pstream::parRun())
    {
        return;
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (backIndex[proci].size())
        {
            UOPstream os(proci, buffers);
            os << backIndex[proci] << backValue[proci];
        }
    }
    labelList sizes;
    buffers.finishedSends(sizes);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (sizes[proci])
        {
            UIPstream is(proci, buffers);
            const labelList idx(is);
            const scalarList values(is);
            forAll(idx, m)
            {
                const scalar* value = &values[m*width];
                sAtRecords[idx[m]] += value[0];
                for (label k = 0; k < nv; ++k)
                {
                    vAtRecords[k][idx[m]] +=
                        vector(value[1 + 3*k], value[2 + 3*k], value[3 + 3*k]);
                }
            }
        }
    }
}
