/* MPI traffic counter for benchmarks/commVolume (not part of the product).
 *
 * Preloaded into a run (LD_PRELOAD), it intercepts MPI's sending calls
 * through the profiling interface (PMPI) and counts, per communicator,
 * the calls and the bytes this rank sends: point-to-point (blocking and
 * non-blocking sends, the send half of send-receives) and collectives
 * (this rank's contribution: its send buffer, once per call).  At
 * MPI_Finalize each rank writes one line per communicator to
 * $MPI_TRAFFIC_PREFIX.<rank>:
 *
 *     comm <world|other> size <ranks> p2pCalls <n> p2pBytes <b> collCalls <n> collBytes <b>
 *
 * (the size is taken when a communicator is first seen: LIGGGHTS' is
 * freed before MPI_Finalize).
 * colloidDEMFoam runs LIGGGHTS on a communicator of its own (a duplicate
 * of MPI_COMM_WORLD, or a split with its ranks reordered) and OpenFOAM
 * (fluid, coupling) on MPI_COMM_WORLD itself: "other" is the DEM's
 * traffic, "world" the rest.  Counted: the calls these runs make in their
 * steps; not counted: non-blocking collectives and persistent requests
 * (neither LIGGGHTS 3.8 nor OpenFOAM v1912 uses them here).
 */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

#define maxComms 16

typedef struct
{
    MPI_Comm comm;
    int size;
    long long p2pCalls, p2pBytes, collCalls, collBytes;
} commCount;

static commCount counts[maxComms];
static int nCounts = 0;

static commCount* countOf(MPI_Comm comm)
{
    for (int i = 0; i < nCounts; ++i)
    {
        if (counts[i].comm == comm)
        {
            return &counts[i];
        }
    }
    if (nCounts == maxComms)
    {
        return &counts[maxComms - 1];   /* lumped: reported as is */
    }
    counts[nCounts].comm = comm;
    PMPI_Comm_size(comm, &counts[nCounts].size);
    return &counts[nCounts++];
}

static long long bytesOf(int count, MPI_Datatype type)
{
    int size = 0;
    if (type != MPI_DATATYPE_NULL)
    {
        PMPI_Type_size(type, &size);
    }
    return (long long)count*size;
}

/* Bytes of a list of counts (the v-variants of collectives) */
static long long bytesOfCounts(const int* counts, MPI_Comm comm, MPI_Datatype type)
{
    int size;
    PMPI_Comm_size(comm, &size);
    long long bytes = 0;
    for (int i = 0; i < size; ++i)
    {
        bytes += bytesOf(counts[i], type);
    }
    return bytes;
}

static void p2p(MPI_Comm comm, int count, MPI_Datatype type)
{
    commCount* c = countOf(comm);
    c->p2pCalls += 1;
    c->p2pBytes += bytesOf(count, type);
}

static void coll(MPI_Comm comm, long long bytes)
{
    commCount* c = countOf(comm);
    c->collCalls += 1;
    c->collBytes += bytes;
}

int MPI_Send(const void* b, int n, MPI_Datatype t, int d, int tag, MPI_Comm c)
{ p2p(c, n, t); return PMPI_Send(b, n, t, d, tag, c); }

int MPI_Ssend(const void* b, int n, MPI_Datatype t, int d, int tag, MPI_Comm c)
{ p2p(c, n, t); return PMPI_Ssend(b, n, t, d, tag, c); }

int MPI_Bsend(const void* b, int n, MPI_Datatype t, int d, int tag, MPI_Comm c)
{ p2p(c, n, t); return PMPI_Bsend(b, n, t, d, tag, c); }

int MPI_Rsend(const void* b, int n, MPI_Datatype t, int d, int tag, MPI_Comm c)
{ p2p(c, n, t); return PMPI_Rsend(b, n, t, d, tag, c); }

int MPI_Isend(const void* b, int n, MPI_Datatype t, int d, int tag, MPI_Comm c, MPI_Request* r)
{ p2p(c, n, t); return PMPI_Isend(b, n, t, d, tag, c, r); }

int MPI_Issend(const void* b, int n, MPI_Datatype t, int d, int tag, MPI_Comm c, MPI_Request* r)
{ p2p(c, n, t); return PMPI_Issend(b, n, t, d, tag, c, r); }

int MPI_Irsend(const void* b, int n, MPI_Datatype t, int d, int tag, MPI_Comm c, MPI_Request* r)
{ p2p(c, n, t); return PMPI_Irsend(b, n, t, d, tag, c, r); }

int MPI_Sendrecv(const void* sb, int sn, MPI_Datatype st, int d, int stag,
                 void* rb, int rn, MPI_Datatype rt, int s, int rtag,
                 MPI_Comm c, MPI_Status* status)
{
    p2p(c, sn, st);
    return PMPI_Sendrecv(sb, sn, st, d, stag, rb, rn, rt, s, rtag, c, status);
}

int MPI_Sendrecv_replace(void* b, int n, MPI_Datatype t, int d, int stag,
                         int s, int rtag, MPI_Comm c, MPI_Status* status)
{
    p2p(c, n, t);
    return PMPI_Sendrecv_replace(b, n, t, d, stag, s, rtag, c, status);
}

int MPI_Bcast(void* b, int n, MPI_Datatype t, int root, MPI_Comm c)
{
    int rank;
    PMPI_Comm_rank(c, &rank);
    coll(c, rank == root ? bytesOf(n, t) : 0);
    return PMPI_Bcast(b, n, t, root, c);
}

int MPI_Reduce(const void* sb, void* rb, int n, MPI_Datatype t, MPI_Op op, int root, MPI_Comm c)
{ coll(c, bytesOf(n, t)); return PMPI_Reduce(sb, rb, n, t, op, root, c); }

int MPI_Allreduce(const void* sb, void* rb, int n, MPI_Datatype t, MPI_Op op, MPI_Comm c)
{ coll(c, bytesOf(n, t)); return PMPI_Allreduce(sb, rb, n, t, op, c); }

int MPI_Scan(const void* sb, void* rb, int n, MPI_Datatype t, MPI_Op op, MPI_Comm c)
{ coll(c, bytesOf(n, t)); return PMPI_Scan(sb, rb, n, t, op, c); }

int MPI_Exscan(const void* sb, void* rb, int n, MPI_Datatype t, MPI_Op op, MPI_Comm c)
{ coll(c, bytesOf(n, t)); return PMPI_Exscan(sb, rb, n, t, op, c); }

int MPI_Gather(const void* sb, int sn, MPI_Datatype st, void* rb, int rn,
               MPI_Datatype rt, int root, MPI_Comm c)
{ coll(c, bytesOf(sn, st)); return PMPI_Gather(sb, sn, st, rb, rn, rt, root, c); }

int MPI_Gatherv(const void* sb, int sn, MPI_Datatype st, void* rb,
                const int* rn, const int* displs, MPI_Datatype rt, int root, MPI_Comm c)
{ coll(c, bytesOf(sn, st)); return PMPI_Gatherv(sb, sn, st, rb, rn, displs, rt, root, c); }

int MPI_Allgather(const void* sb, int sn, MPI_Datatype st, void* rb, int rn,
                  MPI_Datatype rt, MPI_Comm c)
{ coll(c, bytesOf(sn, st)); return PMPI_Allgather(sb, sn, st, rb, rn, rt, c); }

int MPI_Allgatherv(const void* sb, int sn, MPI_Datatype st, void* rb,
                   const int* rn, const int* displs, MPI_Datatype rt, MPI_Comm c)
{ coll(c, bytesOf(sn, st)); return PMPI_Allgatherv(sb, sn, st, rb, rn, displs, rt, c); }

int MPI_Scatter(const void* sb, int sn, MPI_Datatype st, void* rb, int rn,
                MPI_Datatype rt, int root, MPI_Comm c)
{
    int rank, size;
    PMPI_Comm_rank(c, &rank);
    PMPI_Comm_size(c, &size);
    coll(c, rank == root ? size*bytesOf(sn, st) : 0);
    return PMPI_Scatter(sb, sn, st, rb, rn, rt, root, c);
}

int MPI_Scatterv(const void* sb, const int* sn, const int* displs, MPI_Datatype st,
                 void* rb, int rn, MPI_Datatype rt, int root, MPI_Comm c)
{
    int rank;
    PMPI_Comm_rank(c, &rank);
    coll(c, rank == root ? bytesOfCounts(sn, c, st) : 0);
    return PMPI_Scatterv(sb, sn, displs, st, rb, rn, rt, root, c);
}

int MPI_Reduce_scatter(const void* sb, void* rb, const int* rn, MPI_Datatype t,
                       MPI_Op op, MPI_Comm c)
{
    coll(c, bytesOfCounts(rn, c, t));
    return PMPI_Reduce_scatter(sb, rb, rn, t, op, c);
}

int MPI_Alltoall(const void* sb, int sn, MPI_Datatype st, void* rb, int rn,
                 MPI_Datatype rt, MPI_Comm c)
{
    int size;
    PMPI_Comm_size(c, &size);
    coll(c, size*bytesOf(sn, st));
    return PMPI_Alltoall(sb, sn, st, rb, rn, rt, c);
}

int MPI_Alltoallv(const void* sb, const int* sn, const int* sdispls, MPI_Datatype st,
                  void* rb, const int* rn, const int* rdispls, MPI_Datatype rt, MPI_Comm c)
{
    coll(c, bytesOfCounts(sn, c, st));
    return PMPI_Alltoallv(sb, sn, sdispls, st, rb, rn, rdispls, rt, c);
}

int MPI_Finalize(void)
{
    const char* prefix = getenv("MPI_TRAFFIC_PREFIX");
    if (prefix)
    {
        int rank;
        PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
        char name[4096];
        snprintf(name, sizeof(name), "%s.%d", prefix, rank);
        FILE* f = fopen(name, "w");
        if (f)
        {
            for (int i = 0; i < nCounts; ++i)
            {
                fprintf
                (
                    f,
                    "comm %s size %d p2pCalls %lld p2pBytes %lld"
                    " collCalls %lld collBytes %lld\n",
                    counts[i].comm == MPI_COMM_WORLD ? "world" : "other",
                    counts[i].size, counts[i].p2pCalls, counts[i].p2pBytes,
                    counts[i].collCalls, counts[i].collBytes
                );
            }
            fclose(f);
        }
    }
    return PMPI_Finalize();
}
