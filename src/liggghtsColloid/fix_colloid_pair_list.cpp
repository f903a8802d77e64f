/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: see fix_colloid_pair_list.h.
------------------------------------------------------------------------- */

#include "fix_colloid_pair_list.h"

#include <algorithm>
#include <mpi.h>
#include "atom.h"
#include "colloid_append_fix.h"
#include "colloid_neighbour_trim.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

const char fixId[] = "colloid_pair_list";
const char fixStyle[] = "colloid/pair_list";

}

FixColloidPairList *FixColloidPairList::attach(LAMMPS *lmp, double range)
{
    FixColloidPairList *fix = Colloid::colloidAttachFix<FixColloidPairList>(lmp, fixId, fixStyle);
    fix->range_ = range;
    fix->attached_ = true;
    return fix;
}

FixColloidPairList::FixColloidPairList(LAMMPS *lmp, int narg, char **arg)
: Fix(lmp, narg, arg),
  range_(0.0),
  attached_(false),
  active_(false),
  reported_(false),
  warned_(false)
{
    scalar_flag = 1;
    global_freq = 1;
    extscalar = 1;
}

int FixColloidPairList::setmask()
{
    return PRE_FORCE;
}

// Modify::init follows the pair style's: a run trims only if its pair
// style attached the fix, and only if LIGGGHTS checks the displacements
// at every step (or rebuilds at every step): with "neigh_modify delay 10"
// (LIGGGHTS' default) or "every 5" a particle can move more than half the
// skin before the rebuild, and the trimmed list would lose forces that
// the untrimmed one's margin (f - 1)(Ri + Rj) - range still covers
void FixColloidPairList::init()
{
    active_ = attached_;
    attached_ = false;
    if (!active_) return;
    const bool everyStep = neighbor->every == 1 && neighbor->delay <= 1 && !neighbor->build_once;
    if (everyStep) return;
    active_ = false;
    if (comm->me == 0 && !warned_)
    {
        char msg[512];
        snprintf(msg, sizeof(msg),
            "colloid pair list: not trimmed to the colloid range (the pair loop walks pairs up "
            "to twice it): neigh_modify delay %d every %d%s lets a particle move more than half "
            "the skin before a rebuild; 'neigh_modify delay 0 every 1 check yes' trims it",
            neighbor->delay, neighbor->every, neighbor->build_once ? " once yes" : "");
        error->warning(FLERR, msg);
    }
    warned_ = true;
}

void FixColloidPairList::setup_pre_force(int)
{
    trimIfBuilt();
}

void FixColloidPairList::pre_force(int)
{
    trimIfBuilt();
}

double FixColloidPairList::keptGap() const
{
    return std::max(range_, 0.5*neighbor->skin) + neighbor->skin;
}

// Collective: every rank builds at the same steps
void FixColloidPairList::trimIfBuilt()
{
    if (!active_ || neighbor->ago != 0) return;
    Pair *pair = force->pair;
    NeighList *list = pair ? pair->list : NULL;
    if (!list) return;
    NeighList *history = pair->listgranhistory;

    double **x = atom->x;
    const double *radius = atom->radius;
    const double reach = keptGap();
    double before = 0.0, after = 0.0;
    for (int ii = 0; ii < list->inum; ii++)
    {
        const int i = list->ilist[ii];
        const double xi = x[i][0], yi = x[i][1], zi = x[i][2], ri = radius[i];
        const int n = list->numneigh[i];
        // the pair's gap is at most reach: |xi - xj| <= ri + rj + reach
        const int kept = Colloid::trimNeighbourRow(list->firstneigh[i],
            history ? history->firstneigh[i] : NULL,
            history && history->dnum > 0 ? history->firstdouble[i] : NULL,
            history ? history->dnum : 0, n,
            [&](int entry)
            {
                const int j = entry & NEIGHMASK;
                const double dx = xi - x[j][0], dy = yi - x[j][1], dz = zi - x[j][2];
                const double cut = ri + radius[j] + reach;
                return dx*dx + dy*dy + dz*dz <= cut*cut;
            });
        list->numneigh[i] = kept;
        before += n;
        after += kept;
    }

    if (reported_) return;
    reported_ = true;
    double local[2] = {before, after}, all[2];
    MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_SUM, world);
    if (comm->me == 0)
    {
        char line[512];
        snprintf(line, sizeof(line),
            "colloid pair list: pairs kept to a gap of %g (run length units: the colloid "
            "range %g or half the skin, the larger, plus the skin %g); of the %.0f pairs "
            "LIGGGHTS listed (to %g x the radius sum + skin) %.0f are kept\n",
            reach, range_, neighbor->skin, all[0], neighbor->contactDistanceFactor, all[1]);
        if (screen) fputs(line, screen);
        if (logfile) fputs(line, logfile);
    }
}

double FixColloidPairList::compute_scalar()
{
    NeighList *list = force->pair ? force->pair->list : NULL;
    double listed = 0.0, all = 0.0;
    if (list)
        for (int ii = 0; ii < list->inum; ii++) listed += list->numneigh[list->ilist[ii]];
    MPI_Allreduce(&listed, &all, 1, MPI_DOUBLE, MPI_SUM, world);
    return all;
}
