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

    // One block of records per source rank, concatenated in rank order
    List<pointField> p(nProcs);
    List<labelList> c(nProcs);
    List<scalarField> r(nProcs), m(nProcs), K(nProcs);
    List<vectorField> v(nProcs), F(nProcs);

    // This rank's own block is copied, not sent to itself through the
    // buffers (most records stay on their rank: on 2 ranks the round trip
    // through the buffers cost as much as the rest of the exchange)
    {
        const label me = Pstream::myProcNo();
        const labelList& idx = sentIndex_[me];
        p[me] = listPick(localPosition, idx);
        c[me] = listPick(cellOnProc, idx);
        r[me] = listPick(localRadius, idx);
        m[me] = listPick(localMass, idx);
        v[me] = listPick(localVelocity, idx);
        K[me] = listPick(localDragCoeff, idx);
        F[me] = listPick(localDragForce, idx);
    }
    if (Pstream::parRun())
    {
        PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
        for (label proci = 0; proci < nProcs; ++proci)
        {
            const labelList& idx = sentIndex_[proci];
            if (proci != Pstream::myProcNo() && idx.size())
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
            if (proci != Pstream::myProcNo() && sizes[proci])
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
        nFrom_[proci] = p[proci].size();
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
    forAll(c, proci)
    {
        for (const label celli : c[proci])
        {
            nCells = max(nCells, celli + 1);
        }
    }
    labelList next(nCells + 1, 0);
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
    recordOf_.setSize(n);
    label j = 0;
    forAll(p, proci)
    {
        forAll(p[proci], i)
        {
            const label k = next[c[proci][i]]++;
            recordOf_[j++] = k;
            position[k] = p[proci][i];
            cell[k] = c[proci][i];
            radius[k] = r[proci][i];
            mass[k] = m[proci][i];
            velocity[k] = v[proci][i];
            dragCoeff[k] = K[proci][i];
            dragForce[k] = F[proci][i];
        }
    }
}
