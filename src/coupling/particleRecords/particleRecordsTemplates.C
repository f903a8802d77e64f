#include "particleRecords.H"
#include "PstreamBuffers.H"

template<class Type>
void Foam::particleRecords::answer
(
    const List<Type>& perRecord,
    List<Type>& perLocalParticle
) const
{
    const label nProcs = Pstream::nProcs();

    if (!Pstream::parRun())
    {
        forAll(sentIndex_[0], k)
        {
            perLocalParticle[sentIndex_[0][k]] = perRecord[k];
        }
        return;
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    label start = 0;
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (nFrom_[proci])
        {
            UOPstream os(proci, buffers);
            os << SubList<Type>(perRecord, nFrom_[proci], start);
            start += nFrom_[proci];
        }
    }
    labelList sizes;
    buffers.finishedSends(sizes);

    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (sizes[proci])
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
