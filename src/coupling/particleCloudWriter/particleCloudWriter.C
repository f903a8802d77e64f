#include "particleCloudWriter.H"
#include "contactCellFields.H"
#include "passiveParticleCloud.H"
#include "IOField.H"
#include "PstreamBuffers.H"
#include "listPick.H"
#include "DynamicList.H"
#include "atomicFileOperation.H"

namespace
{


// Append the elements of b to a
template<class Type>
void append(Foam::DynamicList<Type>& a, const Foam::UList<Type>& b)
{
    for (const Type& value : b)
    {
        a.append(value);
    }
}


// Write one per-particle field of the cloud; false if it failed
template<class Type>
bool writeField
(
    const Foam::passiveParticleCloud& cloud,
    const Foam::word& name,
    const Foam::List<Type>& values
)
{
    Foam::IOField<Type> field
    (
        cloud.fieldIOobject(name, Foam::IOobject::NO_READ),
        values
    );
    return field.write(values.size() > 0) || values.empty();
}

} // End anonymous namespace


Foam::label Foam::particleCloudWriter::write
(
    const fvMesh& mesh,
    const word& cloudName,
    const particles& local,
    bool& ok,
    string& error
)
{
    const label nProcs = Pstream::nProcs();

    // Local particles by the fluid rank that owns their cell
    List<DynamicList<label>> toProc(nProcs);
    forAll(local.proc, i)
    {
        if (local.proc[i] >= 0)
        {
            toProc[local.proc[i]].append(i);
        }
    }

    // The particles of this rank's cells
    DynamicList<label> cell, id, nContacts, touchingWall, agglomerateSize;
    DynamicList<label> agglomerateId;
    DynamicList<point> position;
    DynamicList<vector> velocity;
    DynamicList<scalar> diameter;

    auto receive = [&](Istream& is)
    {
        labelList c, i, nc, tw, as, ai;
        pointField x;
        vectorField v;
        scalarField d;
        is >> c >> i >> x >> v >> d >> nc >> tw >> as >> ai;
        append(cell, c);
        append(id, i);
        append(position, x);
        append(velocity, v);
        append(diameter, d);
        append(nContacts, nc);
        append(touchingWall, tw);
        append(agglomerateSize, as);
        append(agglomerateId, ai);
    };

    if (!Pstream::parRun())
    {
        const labelList& idx = toProc[0];
        append(cell, listPick(local.cell, idx));
        append(id, listPick(local.id, idx));
        append(position, listPick(local.position, idx));
        append(velocity, listPick(local.velocity, idx));
        append(diameter, listPick(local.diameter, idx));
        append(nContacts, listPick(local.nContacts, idx));
        append(touchingWall, listPick(local.touchingWall, idx));
        append(agglomerateSize, listPick(local.agglomerateSize, idx));
        append(agglomerateId, listPick(local.agglomerateId, idx));
    }
    else
    {
        PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
        for (label proci = 0; proci < nProcs; ++proci)
        {
            const labelList& idx = toProc[proci];
            if (idx.size())
            {
                UOPstream os(proci, buffers);
                os  << listPick(local.cell, idx) << listPick(local.id, idx)
                    << listPick(local.position, idx) << listPick(local.velocity, idx)
                    << listPick(local.diameter, idx)
                    << listPick(local.nContacts, idx)
                    << listPick(local.touchingWall, idx)
                    << listPick(local.agglomerateSize, idx)
                    << listPick(local.agglomerateId, idx);
            }
        }
        labelList sizes;
        buffers.finishedSends(sizes);
        for (label proci = 0; proci < nProcs; ++proci)
        {
            if (sizes[proci])
            {
                UIPstream is(proci, buffers);
                receive(is);
            }
        }
    }

    // OpenFOAM's particles, located from their known cell; origId carries
    // the DEM id (origProcId 0: the id alone is unique)
    IDLList<passiveParticle> list;
    forAll(position, k)
    {
        passiveParticle* p = new passiveParticle(mesh, position[k], cell[k]);
        p->origProc() = 0;
        p->origId() = id[k];
        list.append(p);

        // The cell the particle settled in: for a point on a face it can
        // be the neighbour of the one it was located in, and the cell
        // fields count it where the cloud holds it
        cell[k] = p->cell();
    }

    passiveParticleCloud cloud(mesh, cloudName, list);
    ok = fileOperations::atomicFileOperation::catching
    (
        [&cloud, &list]() { return cloud.write() || list.empty(); },
        error
    );

    labelList touchingParticle(nContacts.size());
    forAll(nContacts, k)
    {
        touchingParticle[k] = nContacts[k] > 0 ? 1 : 0;
    }
    ok = ok && fileOperations::atomicFileOperation::catching
    (
        [&]()
        {
            return
                writeField<vector>(cloud, "U", velocity)
             && writeField<scalar>(cloud, "d", diameter)
             && writeField<label>(cloud, "nContacts", nContacts)
             && writeField<label>(cloud, "touchingParticle", touchingParticle)
             && writeField<label>(cloud, "touchingWall", touchingWall)
             && writeField<label>(cloud, "agglomerateSize", agglomerateSize)
             && writeField<label>(cloud, "agglomerateId", agglomerateId)
             && writeContactCellFields
                (
                    mesh, cell, nContacts, touchingWall, agglomerateSize,
                    local.withAgglomerates
                );
        },
        error
    );

    return returnReduce(label(position.size()), sumOp<label>());
}
