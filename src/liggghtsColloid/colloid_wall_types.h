/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: the atom types of the walls of a
   fix wall/gran (the primitive wall's type, or each mesh's type), for the
   start-up checks that need the particle-wall property of a type pair.
------------------------------------------------------------------------- */

#ifndef COLLOID_WALL_TYPES_H
#define COLLOID_WALL_TYPES_H

#include <vector>
#include "fix_mesh_surface.h"
#include "fix_wall_gran.h"

namespace LIGGGHTS {
namespace Colloid {

inline std::vector<int> wallTypes(LAMMPS_NS::FixWallGran *wall)
{
    std::vector<int> types;
    if (!wall) return types;
    if (wall->is_mesh_wall())
    {
        for (int k = 0; k < wall->n_meshes(); k++)
            types.push_back(wall->mesh_list()[k]->atomTypeWall());
    }
    else
    {
        types.push_back(wall->atom_type_wall());
    }
    return types;
}

}
}

#endif
