/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: see fix_colloid_reneighbor.h.
------------------------------------------------------------------------- */

#include "fix_colloid_reneighbor.h"
#include "colloid_append_fix.h"
#include <cstring>
#include "modify.h"

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
    Modify *modify = lmp->modify;
    for (int i = 0; i < modify->nfix; i++)
        if (std::strcmp(modify->fix[i]->id, fixId) == 0)
            return dynamic_cast<FixColloidReneighbor*>(modify->fix[i]);

    char id[sizeof(fixId)], group[] = "all", style[sizeof(fixStyle)];
    std::strcpy(id, fixId);
    std::strcpy(style, fixStyle);
    char *arg[3] = {id, group, style};
    FixColloidReneighbor *fix = new FixColloidReneighbor(lmp, 3, arg);
    Colloid::colloidAppendFix(lmp, fix);
    return fix;
}

void FixColloidReneighbor::at(LAMMPS *lmp, bigint step)
{
    attach(lmp)->next_reneighbor = step;
}
