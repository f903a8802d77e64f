#include "particleRecords.H"
#include "PstreamBuffers.H"
#include "UIndirectList.H"

template<class Type>
void Foam::particleRecords::answer
(
    const List<Type>& perRecord,
    List<Type>& perLocalParticle
) const
{
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();

    // This rank's own records are copied, not sent to itself through the
    // buffers
    label start = 0;
    for (label proci = 0; proci < me; ++proci)
    {
        start += nFrom_[proci];
    }
    {
        const labelList& idx = sentIndex_[me];
        forAll(idx, k)
        {
            perLocalParticle[idx[k]] = perRecord[recordOf_[start + k]];
        }
    }
    if (!Pstream::parRun())
    {
        return;
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    start = 0;
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (proci != me && nFrom_[proci])
        {
            UOPstream os(proci, buffers);
            os << UIndirectList<Type>
            (
                perRecord,
                SubList<label>(recordOf_, nFrom_[proci], start)
            );
        }
        start += nFrom_[proci];
    }
    labelList sizes;
    buffers.finishedSends(sizes);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (proci != me && sizes[proci])
        {
            UIPstream is(proci, buffers);
            const List<Type> values(is);
            const labelList& idx = sentIndex_[proci];
            forAll(idx, k)
            {
                perLocalParticle[idx[k]] = values[k];
            }
        }
    }
}
