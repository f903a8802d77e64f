/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: the colloid pair style's neighbour list,
   trimmed to the colloid forces' range after every build.

   Why: LIGGGHTS has one contact distance factor f for pairs and walls.
   The colloid models raise it to 1 + range/r_min so that a wall reaches
   the smallest particle at the range ((f - 1) R); pairs are then listed
   to f (Ri + Rj) + skin, a gap of twice the range (equal radii) plus the
   skin, and the pair loop loads the position of every listed neighbour
   at every step for nothing beyond the range.  In the slot coater the
   far half holds all listed pairs, and the loop cost 5 times plain
   Hertz's at 2e5 particles (README, "cost against the particle count").

   What: at every step at which the list was built (Neighbor::ago == 0,
   in pre_force, before the pair forces), each row keeps, of the
   neighbours LIGGGHTS listed, those whose gap is at most

       reach + skin,   reach = max(range, skin/2),

   with their contact flags and history (colloid_neighbour_trim.h).  A
   pair farther apart at the build stays beyond the reach until the next
   build: with "neigh_modify delay 0 every 1 check yes" LIGGGHTS rebuilds
   before any atom has moved half the skin, so a gap closes by at most the
   skin (other settings: no trim, and a warning).  range is the largest
   outer cut-off of the colloid terms that are on; skin/2 is the largest
   gap the contact analysis may look at (colloid_contact_analysis.cpp,
   checkReach).  LIGGGHTS copies this list for a compute that asks for a
   granular list (compute contact/atom): such a compute sees the pairs
   within a gap of reach only (the coupling's, 1 % of the radius, does).
   The walls keep the full factor: their lists are the meshes' and
   primitive walls' own.

   Who attaches it: the pair style's colloid cohesion model at every
   run's init (before Modify's), with the range.  A run whose pair style
   attaches nothing (e.g. plain Hertz after a colloid run) leaves the list
   as LIGGGHTS built it.  Created by code (colloid_append_fix.h).

   Output: its global scalar, e.g. "thermo_style custom step
   f_colloid_pair_list", is the number of entries of the pair list, all
   ranks (a pair across a processor boundary counts on both).  The log
   says, at the first trim of the LIGGGHTS instance, how many were kept.
------------------------------------------------------------------------- */

#ifndef COLLOID_FIX_COLLOID_PAIR_LIST_H
#define COLLOID_FIX_COLLOID_PAIR_LIST_H

#include "fix.h"

namespace LAMMPS_NS {

class FixColloidPairList : public Fix
{
public:
    //- The fix of this LIGGGHTS instance (created if absent), set to trim
    //  the pair list to this range [run units] in the next run. Call
    //  before Modify::init (from the pair style's init).
    static FixColloidPairList *attach(LAMMPS *lmp, double range);

    FixColloidPairList(LAMMPS *lmp, int narg, char **arg);

    int setmask();
    void init();
    void setup_pre_force(int);
    void pre_force(int);
    double compute_scalar();

    //- The largest gap [run units] at which a pair is kept at a build
    double keptGap() const;

private:
    //- Trims the pair list if it was built at this step
    void trimIfBuilt();

    double range_;      // colloid forces' range [run units]
    bool attached_;     // attach() called since the last init
    bool active_;       // this run trims
    bool reported_;     // the log line was written
    bool warned_;       // the warning of an untrimmed list was written
};

}

#endif
