/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: a C interface to the contact and
   agglomerate analysis (colloid_contact_analysis.h) for programs that do
   not include LIGGGHTS' headers (the OpenFOAM coupling). The handle is
   the analysis object; every call but the accessors is collective (all
   ranks of the LIGGGHTS instance). The global figures and lists are
   complete on the master (MPI_COMM_WORLD's rank 0) after
   colloidContactAnalyse; the per-atom arrays are each rank's local atoms,
   in LIGGGHTS' order, valid until the next run.
------------------------------------------------------------------------- */

#ifndef COLLOID_CONTACT_ANALYSIS_API_H
#define COLLOID_CONTACT_ANALYSIS_API_H

extern "C" {

struct ColloidContactCounts
{
    long particles;
    long pairContacts, wallContacts;
    long pairFormed, pairBroken, wallFormed, wallBroken;   // since the last analysis
    long agglomerates, agglomerated, largest;
};

// lmp: the LAMMPS_NS::LAMMPS instance; gaps as fractions of the smaller
// radius (releaseGap >= touchingGap: a contact lasts until the gap
// reaches it). Create before the first run.
__attribute__((visibility("default")))
void *colloidContactAnalysisNew(void *lmp, double touchingGap, double releaseGap, double agglomerateGap);

__attribute__((visibility("default")))
void colloidContactAnalysisFree(void *analysis);

// t: time in any unit (the durations come out in it); touchingWall: one
// flag per local atom (1 touching a wall, 2 within the release gap of
// one, 0 neither), or NULL
__attribute__((visibility("default")))
void colloidContactAnalyse(void *analysis, double t, const int *touchingWall,
                           struct ColloidContactCounts *counts);

// Rank 0, after an analysis: particles with k = 0, 1, ... pair contacts;
// the durations of the pair (wall = 0) or wall (1) contacts that ended
// since the last analysis; the agglomerate sizes as (size, count) pairs.
// Each returns the number of values and points *values at them.
__attribute__((visibility("default")))
int colloidContactByContacts(void *analysis, const long **values);
__attribute__((visibility("default")))
int colloidContactDurations(void *analysis, int wall, const double **values);
__attribute__((visibility("default")))
int colloidContactAgglomerateSizes(void *analysis, const long **sizeCountPairs);

// Per local atom: its agglomerate's size (1: in none)
__attribute__((visibility("default")))
const long *colloidContactAgglomerateSize(void *analysis);

// Per local atom: its agglomerate's id, the smallest atom id in it (its
// own id in none): the same on every rank, so that a post-processor
// groups the particles as the analysis did
__attribute__((visibility("default")))
const long *colloidContactAgglomerateId(void *analysis);

// The contact histories (the start of each contact) of this rank, to and
// from a file of its own, for a restart of as many ranks; load before the
// first analysis. Each returns 0 or an errno value (load: ENOENT when
// there is no file, EINVAL when it is not one of this number of ranks).
// Not collective.
__attribute__((visibility("default")))
int colloidContactSaveHistories(void *analysis, const char *file);
__attribute__((visibility("default")))
int colloidContactLoadHistories(void *analysis, const char *file);

}

#endif
