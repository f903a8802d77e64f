/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: contacts and agglomerates of the particles,
   analysed between runs (a CFD coupling calls it every few coupling steps).

   Touching: two particles whose gap (centre distance minus both radii) is
   below touchingGap times the smaller radius; a particle and a wall by the
   caller's flag (the DEM has no wall distance of its own). A contact, once
   formed, lasts until the gap reaches releaseGap times the smaller radius
   (>= touchingGap; the same by default): a pair held at the touching gap
   whose gap wavers across it (Brownian motion, a pair rolling in shear)
   is one contact, not many short ones. An agglomerate is a connected
   cluster of at least two particles bonded by contacts and by gaps below
   agglomerateGap times the smaller radius (touchingGap by default).

   What each analysis gives (all ranks together, on the master: the rank that is
   MPI_COMM_WORLD's rank 0, the coupled solver's master):
   - particle-particle and particle-wall contacts, and those formed and
     broken since the last analysis; the duration of each contact that
     ended (from the analysis that first saw it to the one that no longer
     did: resolution one analysis interval; contacts present at the first
     analysis have no known start and give no duration);
   - particles with 0, 1, 2, ... pair contacts (binary against multiple);
   - agglomerates: count, size distribution, largest; per local particle
     its agglomerate's size (1: none) and id (its smallest atom id).

   Parallel: pairs come from the pair style's neighbour list (newton off:
   a pair with a ghost is seen by both ranks and counted once, by the atom
   with the smaller id); contact histories live on the rank a hash of the
   pair assigns, and decide whether a pair between the touching and the
   release gap is a contact (both ranks of a pair with a ghost ask), so
   they survive atoms moving between ranks (and, saved
   with a restart, a resumed run of as many ranks); clusters by
   propagating the smallest id over bonds, with the ghosts' values
   forwarded (periodic images included) until no rank changes one. No
   rank gathers the particles.
------------------------------------------------------------------------- */

#ifndef COLLOID_CONTACT_ANALYSIS_H
#define COLLOID_CONTACT_ANALYSIS_H

#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>
#include "pointers.h"

namespace LAMMPS_NS {

class __attribute__((visibility("default"))) ColloidContactAnalysis : protected Pointers
{
public:
    struct Settings
    {
        double touchingGap = 0.01;      // of the smaller radius
        double releaseGap = -1;         // of it; >= touchingGap (< 0: touchingGap)
        double agglomerateGap = 0.01;   // of the smaller radius
    };

    // Global figures of one analysis (complete on the master)
    struct Result
    {
        long particles = 0;
        long pairContacts = 0, wallContacts = 0;
        long pairFormed = 0, pairBroken = 0, wallFormed = 0, wallBroken = 0;
        std::vector<long> byContacts;           // particles with k pair contacts
        std::vector<double> pairDurations;      // [time units] ended since last
        std::vector<double> wallDurations;
        std::map<long, long> agglomerateSizes;  // size (>= 2) -> count
        long agglomerates = 0, agglomerated = 0, largest = 0;
    };

    // Creates the per-atom property the cluster search forwards to ghosts
    // (fix id colloidAgglomerate): call before the first run
    ColloidContactAnalysis(LAMMPS *lmp, const Settings &settings);

    // One analysis at time t [time units]; touchingWall: per local atom
    // 1 touching a wall, 2 within the release gap of one (a contact
    // already formed lasts), 0 neither; or NULL (no wall contacts). Needs
    // a pair style with a neighbour list that is valid for the current
    // positions (between runs) and reaches the release gap: the largest
    // gap the analysis looks at (release or agglomerate gap times the
    // largest radius) must be within half the neighbour skin, else it
    // stops with an error (the constructor checks the atoms there are).
    Result analyse(double t, const int *touchingWall);

    // Per local atom, from the last analysis: pair contacts, agglomerate
    // size (1 outside any) and id (smallest atom id of the agglomerate)
    const std::vector<int> &contacts() const { return contacts_; }
    const std::vector<long> &agglomerateSize() const { return size_; }
    const std::vector<long> &agglomerateId() const { return label_; }

    // The contact histories this rank owns (key, start) to a file of its
    // own, for a restart: a resumed run has as many ranks, so the same
    // owners. Returns 0, or the errno of the failure (a full disk shows
    // at the close). Not collective.
    int saveHistories(const char *file) const;

    // Back from saveHistories' file, before the first analysis of a
    // resumed run: contacts present then keep their start (their
    // durations are complete), and that analysis counts what formed and
    // broke since the write. Returns 0, ENOENT when there is no file, or
    // EINVAL when it is not one written by as many ranks. Not collective.
    int loadHistories(const char *file);

private:
    Settings settings_;
    bool first_;
    class FixPropertyAtom *labels_;

    // contact histories of the keys this rank owns: start time (NaN when
    // unknown: present at the first analysis)
    std::unordered_map<uint64_t, double> pairs_, walls_;

    std::vector<int> contacts_;
    std::vector<long> size_, label_;

    // bonds (i local, j local or ghost) of the cluster search
    std::vector<std::pair<int, int>> bonds_;

    void checkReach() const;
    int owner(uint64_t key) const;
    std::vector<uint64_t> sendToOwners(const std::vector<uint64_t> &records, int width,
                                       std::vector<int> *from = NULL) const;
    std::vector<uint64_t> contactsNow(const std::unordered_map<uint64_t, double> &active,
                                      const std::vector<uint64_t> &keyFlags) const;
    void update(std::unordered_map<uint64_t, double> &active, const std::vector<uint64_t> &now,
                double t, long &formed, long &broken, std::vector<double> &durations);
    void findAgglomerates(Result &result);
};

}

#endif
