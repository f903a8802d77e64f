/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: contacts and agglomerates, see
   colloid_contact_analysis.h.
------------------------------------------------------------------------- */

#include "colloid_contact_analysis.h"
#include "colloid_contact_analysis_api.h"

#include <algorithm>
#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <mpi.h>
#include <unordered_set>
#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_property_atom.h"
#include "force.h"
#include "input.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"

using namespace LAMMPS_NS;

namespace {

const char labelFix[] = "colloidAgglomerate";

uint64_t pairKey(int a, int b)
{
    const uint64_t lo = static_cast<uint32_t>(std::min(a, b));
    const uint64_t hi = static_cast<uint32_t>(std::max(a, b));
    return (lo << 32) | hi;
}

// splitmix64: spreads consecutive ids evenly over the ranks
uint64_t mix(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30))*0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27))*0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

// Every rank sends out[r] to rank r; returns what it received, with the
// sending rank of each block of 'width' values in from
std::vector<uint64_t> exchange(MPI_Comm world, const std::vector<std::vector<uint64_t>> &out,
                               int width, std::vector<int> *from = NULL)
{
    const int nprocs = static_cast<int>(out.size());
    std::vector<int> sendCounts(nprocs), recvCounts(nprocs), sendDispl(nprocs), recvDispl(nprocs);
    std::vector<uint64_t> sendBuf;
    for (int p = 0; p < nprocs; p++)
    {
        sendCounts[p] = static_cast<int>(out[p].size());
        sendDispl[p] = static_cast<int>(sendBuf.size());
        sendBuf.insert(sendBuf.end(), out[p].begin(), out[p].end());
    }
    MPI_Alltoall(sendCounts.data(), 1, MPI_INT, recvCounts.data(), 1, MPI_INT, world);
    int total = 0;
    for (int p = 0; p < nprocs; p++)
    {
        recvDispl[p] = total;
        total += recvCounts[p];
    }
    std::vector<uint64_t> in(total);
    MPI_Alltoallv(sendBuf.data(), sendCounts.data(), sendDispl.data(), MPI_UINT64_T,
                  in.data(), recvCounts.data(), recvDispl.data(), MPI_UINT64_T, world);
    if (from)
    {
        from->clear();
        for (int p = 0; p < nprocs; p++)
            for (int k = 0; k < recvCounts[p]/width; k++) from->push_back(p);
    }
    return in;
}

// The rank in world of MPI_COMM_WORLD's rank 0: in a coupled run the
// solver's master, which writes the analysis (the coupling may give
// LIGGGHTS its ranks in another order, to match the fluid's parts); in a
// LIGGGHTS run of its own, rank 0
int masterRank(MPI_Comm world)
{
    MPI_Group worldGroup, demGroup;
    MPI_Comm_group(MPI_COMM_WORLD, &worldGroup);
    MPI_Comm_group(world, &demGroup);
    const int zero = 0;
    int master = MPI_UNDEFINED;
    MPI_Group_translate_ranks(worldGroup, 1, &zero, demGroup, &master);
    MPI_Group_free(&worldGroup);
    MPI_Group_free(&demGroup);
    return master == MPI_UNDEFINED ? 0 : master;
}

// the values of every rank, on the master
template<class T>
std::vector<T> gatherOnMaster(MPI_Comm world, const std::vector<T> &mine, MPI_Datatype type)
{
    int nprocs, me;
    MPI_Comm_size(world, &nprocs);
    MPI_Comm_rank(world, &me);
    const int master = masterRank(world);
    const int n = static_cast<int>(mine.size());
    std::vector<int> counts(nprocs), displ(nprocs);
    MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, master, world);
    int total = 0;
    for (int p = 0; p < nprocs; p++)
    {
        displ[p] = total;
        total += counts[p];
    }
    std::vector<T> all(me == master ? total : 0);
    MPI_Gatherv(mine.data(), n, type, all.data(), counts.data(), displ.data(), type, master, world);
    return all;
}

long sumOnMaster(MPI_Comm world, long mine)
{
    long sum = 0;
    MPI_Reduce(&mine, &sum, 1, MPI_LONG, MPI_SUM, masterRank(world), world);
    return sum;
}

}

/* ---------------------------------------------------------------------- */

ColloidContactAnalysis::ColloidContactAnalysis(LAMMPS *lmp, const Settings &settings)
:
    Pointers(lmp),
    settings_(settings),
    first_(true),
    labels_(NULL)
{
    if (!(settings.touchingGap >= 0) || !(settings.agglomerateGap >= 0))
        error->all(FLERR, "colloid contact analysis: the touching and agglomerate gaps must be >= 0");
    if (settings_.releaseGap < 0) settings_.releaseGap = settings_.touchingGap;
    if (!(settings_.releaseGap >= settings_.touchingGap))
        error->all(FLERR, "colloid contact analysis: the release gap must be >= the touching gap");
    if (modify->find_fix(labelFix) < 0)
    {
        // scalar, not in restart files, forwarded to ghosts, no reverse comm
        char line[128];
        snprintf(line, sizeof(line), "fix %s all property/atom %s scalar no yes no -1", labelFix, labelFix);
        input->one(line);
    }
    labels_ = static_cast<FixPropertyAtom *>(
        modify->find_fix_property(labelFix, "property/atom", "scalar", 0, 0, "colloid contact analysis"));
    checkReach();   // the particles there are; each analysis checks again
}

/* ---------------------------------------------------------------------- */

// A pair within the gaps looked at must be in the neighbour list whatever
// the atoms moved since it was built (up to half the skin); collective
void ColloidContactAnalysis::checkReach() const
{
    double rMax = 0, rMaxAll = 0;
    for (int i = 0; i < atom->nlocal; i++) rMax = std::max(rMax, atom->radius[i]);
    MPI_Allreduce(&rMax, &rMaxAll, 1, MPI_DOUBLE, MPI_MAX, world);
    const double gap = std::max(settings_.releaseGap, settings_.agglomerateGap);
    if (gap*rMaxAll <= 0.5*neighbor->skin) return;
    char msg[512];
    snprintf(msg, sizeof(msg), "colloid contact analysis: the release or agglomerate gap "
             "(%g of the largest radius %g: %g) exceeds half the neighbour skin (%g): "
             "lower the gap or raise the skin ('neighbor' in the DEM script)",
             gap, rMaxAll, gap*rMaxAll, 0.5*neighbor->skin);
    error->all(FLERR, msg);
}

/* ---------------------------------------------------------------------- */

int ColloidContactAnalysis::owner(uint64_t key) const
{
    return static_cast<int>(mix(key) % static_cast<uint64_t>(comm->nprocs));
}

// Records of 'width' values, each led by its key, sent to the keys'
// owners: those this rank owns, from every rank (and the sending rank of
// each in from)
std::vector<uint64_t> ColloidContactAnalysis::sendToOwners(const std::vector<uint64_t> &records,
                                                           int width, std::vector<int> *from) const
{
    std::vector<std::vector<uint64_t>> out(comm->nprocs);
    for (size_t k = 0; k < records.size(); k += width)
    {
        std::vector<uint64_t> &o = out[owner(records[k])];
        o.insert(o.end(), records.begin() + k, records.begin() + k + width);
    }
    return exchange(world, out, width, from);
}

namespace {
// flags of a (key, flags) record sent to the key's owner
const uint64_t touchingNow = 1;   // below the touching gap (else: within the release gap)
const uint64_t counting = 2;      // the rank that counts the pair (a pair with a ghost is
                                  // seen by two; the other asks whether it is a contact)
}

// The keys of the received (key, flags) records that are contacts now:
// touching, or within the release gap and a contact at the last analysis
std::vector<uint64_t> ColloidContactAnalysis::contactsNow(const std::unordered_map<uint64_t, double> &active,
                                                      const std::vector<uint64_t> &keyFlags) const
{
    std::vector<uint64_t> now;
    for (size_t k = 0; k < keyFlags.size(); k += 2)
    {
        const uint64_t key = keyFlags[k], flags = keyFlags[k + 1];
        if ((flags & counting) && ((flags & touchingNow) || active.count(key))) now.push_back(key);
    }
    return now;
}

// Contacts now against the histories: formed (new keys), broken (keys no
// longer there) with the durations of those whose start is known
void ColloidContactAnalysis::update(std::unordered_map<uint64_t, double> &active,
                                    const std::vector<uint64_t> &now, double t,
                                    long &formed, long &broken, std::vector<double> &durations)
{
    const std::unordered_set<uint64_t> present(now.begin(), now.end());
    for (auto it = active.begin(); it != active.end();)
    {
        if (present.count(it->first))
        {
            ++it;
            continue;
        }
        broken++;
        if (!std::isnan(it->second)) durations.push_back(t - it->second);
        it = active.erase(it);
    }
    for (uint64_t k : present)
    {
        if (active.count(k)) continue;
        active[k] = first_ ? std::numeric_limits<double>::quiet_NaN() : t;
        if (!first_) formed++;
    }
}

/* ---------------------------------------------------------------------- */

ColloidContactAnalysis::Result ColloidContactAnalysis::analyse(double t, const int *touchingWall)
{
    NeighList *list = force->pair ? force->pair->list : NULL;
    if (!list)
        error->all(FLERR, "colloid contact analysis: needs a pair style with a neighbour list "
                          "(pair_style gran ...), set up by a run");

    const int nlocal = atom->nlocal;
    double **x = atom->x;
    const double *r = atom->radius;
    const int *tag = atom->tag;

    checkReach();

    // every pair within the release gap: one touching is a contact; one
    // between the touching and the release gap is if it was at the last
    // analysis, which the key's owner knows
    struct Held { uint64_t key; int i, j; };
    std::vector<Held> held;
    contacts_.assign(nlocal, 0);
    bonds_.clear();
    std::vector<uint64_t> pairRecords, wallRecords;
    for (int ii = 0; ii < list->inum; ii++)
    {
        const int i = list->ilist[ii];
        if (i >= nlocal) continue;
        const int *jlist = list->firstneigh[i];
        for (int jj = 0; jj < list->numneigh[i]; jj++)
        {
            const int j = jlist[jj] & NEIGHMASK;
            const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
            const double gap = std::sqrt(dx*dx + dy*dy + dz*dz) - r[i] - r[j];
            const double rMin = std::min(r[i], r[j]);
            const bool touching = gap < settings_.touchingGap*rMin;
            if (touching || gap < settings_.agglomerateGap*rMin) bonds_.push_back(std::make_pair(i, j));
            if (gap >= settings_.releaseGap*rMin) continue;
            // a pair with a ghost is in both ranks' lists: counted by the
            // atom with the smaller id
            const uint64_t key = pairKey(tag[i], tag[j]);
            const bool counts = j < nlocal || tag[i] < tag[j];
            if (touching)
            {
                contacts_[i]++;
                if (j < nlocal) contacts_[j]++;
            }
            else held.push_back({key, i, j});
            if (counts || !touching)
            {
                pairRecords.push_back(key);
                pairRecords.push_back((touching ? touchingNow : 0) | (counts ? counting : 0));
            }
        }
    }
    if (touchingWall)
        for (int i = 0; i < nlocal; i++)
            if (touchingWall[i])
            {
                wallRecords.push_back(static_cast<uint64_t>(tag[i]));
                wallRecords.push_back((touchingWall[i] == 1 ? touchingNow : 0) | counting);
            }

    Result result;
    long pairFormed = 0, pairBroken = 0, wallFormed = 0, wallBroken = 0;
    std::vector<double> pairDurations, wallDurations;
    std::vector<int> from;
    const std::vector<uint64_t> pairIn = sendToOwners(pairRecords, 2, &from);
    const std::vector<uint64_t> pairsNow = contactsNow(pairs_, pairIn);
    const std::vector<uint64_t> wallsNow = contactsNow(walls_, sendToOwners(wallRecords, 2));

    // the held pairs that are contacts, back to the ranks that asked
    const std::unordered_set<uint64_t> isContact(pairsNow.begin(), pairsNow.end());
    std::vector<std::vector<uint64_t>> reply(comm->nprocs);
    for (size_t k = 0; k < pairIn.size(); k += 2)
        if (!(pairIn[k + 1] & touchingNow) && isContact.count(pairIn[k])) reply[from[k/2]].push_back(pairIn[k]);
    const std::vector<uint64_t> heldContacts = exchange(world, reply, 1);
    const std::unordered_set<uint64_t> stillInContact(heldContacts.begin(), heldContacts.end());
    for (const Held &h : held)
    {
        if (!stillInContact.count(h.key)) continue;
        contacts_[h.i]++;
        if (h.j < nlocal) contacts_[h.j]++;
        bonds_.push_back(std::make_pair(h.i, h.j));
    }

    update(pairs_, pairsNow, t, pairFormed, pairBroken, pairDurations);
    update(walls_, wallsNow, t, wallFormed, wallBroken, wallDurations);
    first_ = false;

    result.particles = sumOnMaster(world, nlocal);
    result.pairContacts = sumOnMaster(world, static_cast<long>(pairsNow.size()));
    result.wallContacts = sumOnMaster(world, static_cast<long>(wallsNow.size()));
    result.pairFormed = sumOnMaster(world, pairFormed);
    result.pairBroken = sumOnMaster(world, pairBroken);
    result.wallFormed = sumOnMaster(world, wallFormed);
    result.wallBroken = sumOnMaster(world, wallBroken);
    result.pairDurations = gatherOnMaster(world, pairDurations, MPI_DOUBLE);
    result.wallDurations = gatherOnMaster(world, wallDurations, MPI_DOUBLE);

    int most = 0, mostAll = 0;
    for (int c : contacts_) most = std::max(most, c);
    MPI_Allreduce(&most, &mostAll, 1, MPI_INT, MPI_MAX, world);
    std::vector<long> byContacts(mostAll + 1, 0);
    for (int c : contacts_) byContacts[c]++;
    result.byContacts.assign(mostAll + 1, 0);
    MPI_Reduce(byContacts.data(), result.byContacts.data(), mostAll + 1, MPI_LONG, MPI_SUM, masterRank(world), world);

    findAgglomerates(result);
    return result;
}

/* ---------------------------------------------------------------------- */

void ColloidContactAnalysis::findAgglomerates(Result &result)
{
    const int nlocal = atom->nlocal;
    const int *tag = atom->tag;
    double *label = labels_->vector_atom;

    // smallest id over the bonds: locally to a fixed point, then the
    // ghosts' values forwarded, until no rank changes a value
    for (int i = 0; i < nlocal; i++) label[i] = tag[i];
    int changedAnywhere = 1;
    while (changedAnywhere)
    {
        labels_->do_forward_comm();
        int changed = 0;
        bool sweep = true;
        while (sweep)
        {
            sweep = false;
            for (const auto &b : bonds_)
            {
                const double m = std::min(label[b.first], label[b.second]);
                if (label[b.first] > m)
                {
                    label[b.first] = m;
                    sweep = true;
                }
                if (b.second < nlocal && label[b.second] > m)
                {
                    label[b.second] = m;
                    sweep = true;
                }
            }
            changed = changed || sweep;
        }
        MPI_Allreduce(&changed, &changedAnywhere, 1, MPI_INT, MPI_MAX, world);
    }

    // sizes: each bonded particle's cluster counted on the rank that owns
    // the cluster's id, and sent back to the ranks that asked
    std::vector<char> bonded(nlocal, 0);
    for (const auto &b : bonds_)
    {
        bonded[b.first] = 1;
        if (b.second < nlocal) bonded[b.second] = 1;
    }
    std::map<uint64_t, uint64_t> localCount;
    for (int i = 0; i < nlocal; i++)
        if (bonded[i]) localCount[static_cast<uint64_t>(label[i])]++;
    std::vector<std::vector<uint64_t>> out(comm->nprocs);
    for (const auto &c : localCount)
    {
        std::vector<uint64_t> &o = out[owner(c.first)];
        o.push_back(c.first);
        o.push_back(c.second);
    }
    std::vector<int> from;
    const std::vector<uint64_t> in = exchange(world, out, 2, &from);
    std::map<uint64_t, uint64_t> total;
    for (size_t k = 0; k < in.size(); k += 2) total[in[k]] += in[k + 1];
    std::vector<std::vector<uint64_t>> reply(comm->nprocs);
    for (size_t k = 0; k < in.size(); k += 2)
    {
        reply[from[k/2]].push_back(in[k]);
        reply[from[k/2]].push_back(total[in[k]]);
    }
    const std::vector<uint64_t> answer = exchange(world, reply, 2);
    std::unordered_map<uint64_t, long> sizeOf;
    for (size_t k = 0; k < answer.size(); k += 2) sizeOf[answer[k]] = static_cast<long>(answer[k + 1]);

    size_.assign(nlocal, 1);
    label_.resize(nlocal);
    for (int i = 0; i < nlocal; i++)
    {
        label_[i] = static_cast<long>(label[i]);
        if (bonded[i]) size_[i] = sizeOf[static_cast<uint64_t>(label[i])];
    }

    // the size distribution, from the owners, on the master
    std::map<long, long> mine;
    for (const auto &c : total) mine[static_cast<long>(c.second)]++;
    std::vector<long> flat;
    for (const auto &c : mine)
    {
        flat.push_back(c.first);
        flat.push_back(c.second);
    }
    const std::vector<long> all = gatherOnMaster(world, flat, MPI_LONG);
    for (size_t k = 0; k < all.size(); k += 2)
    {
        result.agglomerateSizes[all[k]] += all[k + 1];
        result.agglomerates += all[k + 1];
        result.agglomerated += all[k]*all[k + 1];
        result.largest = std::max(result.largest, all[k]);
    }
}

/* ---------------------------------------------------------------------- */

namespace {
const char historyHeader[] = "colloidContactHistories";
}

// Text, one contact a line: p (pair) or w (wall), its key, its start
// (%.17g: the same double back; nan when unknown)
int ColloidContactAnalysis::saveHistories(const char *file) const
{
    FILE *out = std::fopen(file, "w");
    if (!out) return errno ? errno : EIO;
    std::fprintf(out, "%s 1 %d\n", historyHeader, comm->nprocs);
    for (const auto &c : pairs_) std::fprintf(out, "p %" PRIu64 " %.17g\n", c.first, c.second);
    for (const auto &c : walls_) std::fprintf(out, "w %" PRIu64 " %.17g\n", c.first, c.second);
    const bool bad = std::ferror(out);
    errno = 0;
    if (std::fclose(out) != 0 || bad) return errno ? errno : EIO;
    return 0;
}

int ColloidContactAnalysis::loadHistories(const char *file)
{
    FILE *in = std::fopen(file, "r");
    if (!in) return errno == ENOENT ? ENOENT : EINVAL;
    char word[64];
    int version = 0, nprocs = 0;
    if (std::fscanf(in, "%63s %d %d", word, &version, &nprocs) != 3
     || std::strcmp(word, historyHeader) != 0 || version != 1 || nprocs != comm->nprocs)
    {
        std::fclose(in);
        return EINVAL;
    }
    std::unordered_map<uint64_t, double> pairs, walls;
    char kind[8], start[64];
    uint64_t key = 0;
    int n;
    while ((n = std::fscanf(in, "%7s %" SCNu64 " %63s", kind, &key, start)) == 3)
    {
        const double t = std::strtod(start, NULL);   // "nan" reads as NaN
        if (kind[0] == 'p') pairs[key] = t;
        else if (kind[0] == 'w') walls[key] = t;
        else break;
    }
    const bool complete = (n == EOF) && !std::ferror(in);
    std::fclose(in);
    if (!complete) return EINVAL;
    pairs_.swap(pairs);
    walls_.swap(walls);
    first_ = false;
    return 0;
}

/* ----------------------------------------------------------------------
   C interface (colloid_contact_analysis_api.h)
------------------------------------------------------------------------- */

namespace {

struct Handle
{
    ColloidContactAnalysis analysis;
    ColloidContactAnalysis::Result last;
    std::vector<long> sizePairs;
    Handle(LAMMPS *lmp, const ColloidContactAnalysis::Settings &s) : analysis(lmp, s) {}
};

}

void *colloidContactAnalysisNew(void *lmp, double touchingGap, double releaseGap, double agglomerateGap)
{
    ColloidContactAnalysis::Settings s;
    s.touchingGap = touchingGap;
    s.releaseGap = releaseGap;
    s.agglomerateGap = agglomerateGap;
    return new Handle(static_cast<LAMMPS *>(lmp), s);
}

void colloidContactAnalysisFree(void *analysis)
{
    delete static_cast<Handle *>(analysis);
}

void colloidContactAnalyse(void *analysis, double t, const int *touchingWall,
                           ColloidContactCounts *counts)
{
    Handle &h = *static_cast<Handle *>(analysis);
    h.last = h.analysis.analyse(t, touchingWall);
    const ColloidContactAnalysis::Result &r = h.last;
    h.sizePairs.clear();
    for (const auto &s : r.agglomerateSizes)
    {
        h.sizePairs.push_back(s.first);
        h.sizePairs.push_back(s.second);
    }
    counts->particles = r.particles;
    counts->pairContacts = r.pairContacts;
    counts->wallContacts = r.wallContacts;
    counts->pairFormed = r.pairFormed;
    counts->pairBroken = r.pairBroken;
    counts->wallFormed = r.wallFormed;
    counts->wallBroken = r.wallBroken;
    counts->agglomerates = r.agglomerates;
    counts->agglomerated = r.agglomerated;
    counts->largest = r.largest;
}

int colloidContactByContacts(void *analysis, const long **values)
{
    const Handle &h = *static_cast<Handle *>(analysis);
    *values = h.last.byContacts.data();
    return static_cast<int>(h.last.byContacts.size());
}

int colloidContactDurations(void *analysis, int wall, const double **values)
{
    const Handle &h = *static_cast<Handle *>(analysis);
    const std::vector<double> &d = wall ? h.last.wallDurations : h.last.pairDurations;
    *values = d.data();
    return static_cast<int>(d.size());
}

int colloidContactAgglomerateSizes(void *analysis, const long **sizeCountPairs)
{
    const Handle &h = *static_cast<Handle *>(analysis);
    *sizeCountPairs = h.sizePairs.data();
    return static_cast<int>(h.sizePairs.size()/2);
}

const long *colloidContactAgglomerateSize(void *analysis)
{
    return static_cast<Handle *>(analysis)->analysis.agglomerateSize().data();
}

const long *colloidContactAgglomerateId(void *analysis)
{
    return static_cast<Handle *>(analysis)->analysis.agglomerateId().data();
}

int colloidContactSaveHistories(void *analysis, const char *file)
{
    return static_cast<Handle *>(analysis)->analysis.saveHistories(file);
}

int colloidContactLoadHistories(void *analysis, const char *file)
{
    return static_cast<Handle *>(analysis)->analysis.loadHistories(file);
}
