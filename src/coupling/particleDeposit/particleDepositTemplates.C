#include "particleDeposit.H"
#include "PstreamBuffers.H"

template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::particleDeposit::sample
(
    const GeometricField<Type, fvPatchField, volMesh>& field
) const
{
    tmp<Field<Type>> tresult(new Field<Type>(nRecords_, Zero));
    Field<Type>& result = tresult.ref();

    const label me = Pstream::myProcNo();
    const label nProcs = Pstream::nProcs();

    // Points of other ranks' particles: their weighted values go back
    List<DynamicList<label>> backIndex(nProcs);
    List<DynamicList<Type>> backValue(nProcs);

    forAll(sampleCell_, j)
    {
        const Type value = sampleWeight_[j]*field[sampleCell_[j]];
        if (sampleProc_[j] == me)
        {
            result[sampleIndex_[j]] += value;
        }
        else
        {
            backIndex[sampleProc_[j]].append(sampleIndex_[j]);
            backValue[sampleProc_[j]].append(value);
        }
    }

    if (Pstream::parRun())
    {
        PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
        for (label proci = 0; proci < nProcs; ++proci)
        {
            if (backIndex[proci].size())
            {
                UOPstream os(proci, buffers);
                os << labelList(backIndex[proci]) << List<Type>(backValue[proci]);
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
                const List<Type> values(is);
                forAll(idx, k)
                {
                    result[idx[k]] += values[k];
                }
            }
        }
    }

    return tresult;
}
