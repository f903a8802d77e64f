/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: a rebuild of the neighbour lists at a step
   the coupling names.

   Why: a fix may act at the rebuild and keep, until then, state that a
   restart file does not hold.  LIGGGHTS' massflow/mesh with delete_atoms
   counts a particle when it crosses the outflow surface (post_integrate)
   and deletes it at the next rebuild (pre_exchange); its list of
   particles waiting to be deleted is not part of a restart.  A restart
   written between the two keeps those particles, counted and never
   deleted: after a resume they drift on and leave the box, and are lost.
   LAMMPS' own restart output rebuilds at every step it writes a restart
   (Neighbor::decide, restart_check); a coupling that writes with
   write_restart between runs asks for the same rebuild at the last step
   before each write with colloidReneighborAt (register_colloid_models.h).

   The fix does nothing else: force_reneighbor makes Neighbor::decide
   compare each step with its next_reneighbor.  It is created by code
   (colloid_append_fix.h), before the first run, so that the neighbour
   set-up of that run lists it.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_COLLOID_RENEIGHBOR_H
#define LMP_FIX_COLLOID_RENEIGHBOR_H

#include "fix.h"

namespace LAMMPS_NS {

class FixColloidReneighbor : public Fix {
public:
    FixColloidReneighbor(LAMMPS *lmp, int narg, char **arg);

    int setmask();

    //- The fix of lmp, created (appended) if it has none
    static FixColloidReneighbor *attach(LAMMPS *lmp);

    //- Rebuild the neighbour lists at the given step (-1: no step)
    static void at(LAMMPS *lmp, bigint step);
};

}

#endif
