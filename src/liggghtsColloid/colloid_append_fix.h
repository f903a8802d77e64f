/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: appending a fix the plugin creates by code.

   LIGGGHTS' fix factory cannot be extended from a plugin
   (Modify::fix_map is private), so the plugin's fixes are not created by
   a "fix" command: colloidAppendFix() appends one to Modify's public fix
   list the way Modify::add_fix does (the fix list grows by 16, fmask
   with it).
------------------------------------------------------------------------- */

#ifndef COLLOID_APPEND_FIX_H
#define COLLOID_APPEND_FIX_H

#include <cstring>
#include <string>
#include "fix.h"
#include "lammps.h"
#include "memory.h"
#include "modify.h"

namespace Colloid {

inline void colloidAppendFix(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::Fix *fix)
{
    LAMMPS_NS::Modify *modify = lmp->modify;
    if (modify->nfix == modify->maxfix)
    {
        modify->maxfix += 16;
        modify->fix = (LAMMPS_NS::Fix **) lmp->memory->srealloc(modify->fix,
            modify->maxfix*sizeof(LAMMPS_NS::Fix *), "modify:fix");
        lmp->memory->grow(modify->fmask, modify->maxfix, "modify:fmask");
    }
    modify->fix[modify->nfix] = fix;
    modify->fmask[modify->nfix] = fix->setmask();
    modify->nfix++;
}

//- The fix of lmp with this id, created with the given style (group all,
//  no arguments) and appended if lmp has none
template<class FixType>
FixType *colloidAttachFix(LAMMPS_NS::LAMMPS *lmp, const char *fixId, const char *fixStyle)
{
    LAMMPS_NS::Modify *modify = lmp->modify;
    for (int i = 0; i < modify->nfix; i++)
        if (std::strcmp(modify->fix[i]->id, fixId) == 0)
            return dynamic_cast<FixType *>(modify->fix[i]);

    std::string id(fixId), style(fixStyle);
    char group[] = "all";
    char *arg[3] = {&id[0], group, &style[0]};
    FixType *fix = new FixType(lmp, 3, arg);
    colloidAppendFix(lmp, fix);
    return fix;
}

}

#endif
