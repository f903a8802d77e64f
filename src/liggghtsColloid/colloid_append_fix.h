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

}

#endif
