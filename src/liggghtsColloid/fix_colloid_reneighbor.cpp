/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: see fix_colloid_reneighbor.h.
------------------------------------------------------------------------- */

#include "fix_colloid_reneighbor.h"
#include "colloid_append_fix.h"

using namespace LAMMPS_NS;

namespace {

const char fixId[] = "colloid_reneighbor";
const char fixStyle[] = "colloid/reneighbor";

}

FixColloidReneighbor::FixColloidReneighbor(LAMMPS *lmp, int narg, char **arg)
: Fix(lmp, narg, arg)
{
    force_reneighbor = 1;
    next_reneighbor = -1;
}

int FixColloidReneighbor::setmask()
{
    return 0;
}

FixColloidReneighbor *FixColloidReneighbor::attach(LAMMPS *lmp)
{
    return Colloid::colloidAttachFix<FixColloidReneighbor>(lmp, fixId, fixStyle);
}

void FixColloidReneighbor::at(LAMMPS *lmp, bigint step)
{
    attach(lmp)->next_reneighbor = step;
}
