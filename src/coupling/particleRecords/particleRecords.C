#include "particleRecords.H"
#include "PstreamBuffers.H"
#include "listPick.H"
#include "DynamicList.H"

void Foam::particleRecords::gather
(
    const labelList& proc,
    const labelList& cellOnProc,
    const pointField& localPosition,
    const scalarField& localRadius,
    const scalarField& localMass,
    const vectorField& localVelocity,
    const scalarField& localDragCoeff,
    const vectorField& localDragForce
)
{
    const label nProcs = Pstream::nProcs();

    List<DynamicList<label>> toProc(nProcs);
    forAll(proc, i)
    {
        if (proc[i] >= 0)
        {
            toProc[proc[i]].append(i);
        }
    }
    sentIndex_.setSize(nProcs);
    nSentAway_ = 0;
    forAll(toProc, proci)
    {
        if (proci != Pstream::myProcNo())
        {
            nSentAway_ += toProc[proci].size();
        }
        sentIndex_[proci].transfer(toProc[proci]);
    }
    nFrom_.setSize(nProcs);
    nFrom_ = 0;

    // The records received from the other ranks, one block per rank
    List<pointField> p(nProcs);
    List<labelList> c(nProcs);
    List<scalarField> r(nProcs), m(nProcs), K(nProcs);
    List<vectorField> v(nProcs), F(nProcs);

    // This rank's own block is read from the local lists below, not sent
    // to itself through the buffers (most records stay on their rank: on
    // 2 ranks the round trip through the buffers cost as much as the rest
    // of the exchange)
    const label me = Pstream::myProcNo();
    const labelList& own = sentIndex_[me];
    if (Pstream::parRun())
    {
        PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
        for (label proci = 0; proci < nProcs; ++proci)
        {
            const labelList& idx = sentIndex_[proci];
            if (proci != me && idx.size())
            {
                UOPstream os(proci, buffers);
                os  << listPick(localPosition, idx) << listPick(cellOnProc, idx)
                    << listPick(localRadius, idx) << listPick(localMass, idx)
                    << listPick(localVelocity, idx) << listPick(localDragCoeff, idx)
                    << listPick(localDragForce, idx);
            }
        }
        labelList sizes;
        buffers.finishedSends(sizes);
        for (label proci = 0; proci < nProcs; ++proci)
        {
            if (proci != me && sizes[proci])
            {
                UIPstream is(proci, buffers);
                is >> p[proci] >> c[proci] >> r[proci] >> m[proci]
                   >> v[proci] >> K[proci] >> F[proci];
            }
        }
    }

    label n = 0;
    forAll(p, proci)
    {
        nFrom_[proci] = (proci == me) ? own.size() : p[proci].size();
        n += nFrom_[proci];
    }
    position.setSize(n);
    cell.setSize(n);
    radius.setSize(n);
    mass.setSize(n);
    velocity.setSize(n);
    dragCoeff.setSize(n);
    dragForce.setSize(n);

    // In the order of their cells (a stable counting sort): the deposit,
    // the sampling and the forces then read the records and the cells'
    // data one after the other; in the received order each record's cell
    // data was a cache miss, and so was each record read in cell order
    label nCells = 0;
    for (const label i : own)
    {
        nCells = max(nCells, cellOnProc[i] + 1);
    }
    forAll(c, proci)
    {
        for (const label celli : c[proci])
        {
            nCells = max(nCells, celli + 1);
        }
    }
    labelList next(nCells + 1, 0);
    for (const label i : own)
    {
        ++next[cellOnProc[i] + 1];
    }
    forAll(c, proci)
    {
        for (const label celli : c[proci])
        {
            ++next[celli + 1];
        }
    }
    for (label celli = 0; celli < nCells; ++celli)
    {
        next[celli + 1] += next[celli];
    }

    // Each record to its place; recordOf_ in the order received (rank by
    // rank, this rank's own block at its rank)
    recordOf_.setSize(n);
    label j = 0;
    auto place = [&]
    (
        const point& pi, const label ci, const scalar ri, const scalar mi,
        const vector& vi, const scalar Ki, const vector& Fi
    )
    {
        const label k = next[ci]++;
        recordOf_[j++] = k;
        position[k] = pi;
        cell[k] = ci;
        radius[k] = ri;
        mass[k] = mi;
        velocity[k] = vi;
        dragCoeff[k] = Ki;
        dragForce[k] = Fi;
    };
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (proci == me)
        {
            for (const label i : own)
            {
                place
                (
                    localPosition[i], cellOnProc[i], localRadius[i],
                    localMass[i], localVelocity[i], localDragCoeff[i],
                    localDragForce[i]
                );
            }
        }
        else
        {
            forAll(p[proci], i)
            {
                place
                (
                    p[proci][i], c[proci][i], r[proci][i], m[proci][i],
                    v[proci][i], K[proci][i], F[proci][i]
                );
            }
        }
    }
}
