/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: spheres the coupling chose, added in the
   first step of the next run (register_colloid_models.h,
   colloidInsertAtoms).

   Why not LIGGGHTS' own insertion: insert/stream moves the particles it
   inserts at one prescribed velocity, whatever the forces, until they
   pass its face.  Fed through a fluid inlet, a particle released next to
   a no-slip wall slows down with the liquid and the next one, still
   moved at the feed velocity, pushes it (measured in the slot coater:
   fed pairs pushed to a 4 nm gap and stuck; its README, "feed").  The
   coupling's feed (particleFeed) instead places the particles where the
   liquid that entered since its last insertion now is, free and with the
   liquid's velocity; this fix creates them.

   Where: in pre_exchange of a rebuild of the neighbour lists forced at
   the run's first step (force_reneighbor), as LIGGGHTS' insertion fixes
   do: after the contact histories have stored their partners by id
   (fix contacthistory comes first), before the atoms are exchanged and
   the ghosts rebuilt.  Atoms created between runs would take the ghosts'
   slots before the next set-up saved their histories, and the full
   set-up they would need runs the exchange before the outflow fix has
   deleted the particles it counted.

   Every rank queues the same list and creates the atoms whose positions
   (after the periodic wrap) lie in its subdomain, in group all, with ids
   following the largest present at that step (after the fixes before it
   have inserted or deleted theirs) in list order: the same ids on any
   number of ranks (LIGGGHTS' tag_extend numbers them rank by rank).  The fix is created
   by code before the first run (colloid_append_fix.h), so that every run
   lists it.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_COLLOID_INSERT_H
#define LMP_FIX_COLLOID_INSERT_H

#include "fix.h"
#include <vector>

namespace LAMMPS_NS {

class FixColloidInsert : public Fix {
public:
    FixColloidInsert(LAMMPS *lmp, int narg, char **arg);

    int setmask();
    void pre_exchange();

    //- The fix of lmp, created (appended) if it has none
    static FixColloidInsert *attach(LAMMPS *lmp);

    //- Queue n spheres for the next step (see register_colloid_models.h);
    //  false for an atom type the DEM does not have
    bool queue(int n, const double *x, const double *v, double radius,
               double density, int type);

    //- Spheres created from the last queue on all ranks (-1: not yet)
    long long created() const { return created_; }

private:
    std::vector<double> x_, v_;
    double radius_, density_;
    int type_;
    long long created_;
};

}

#endif
