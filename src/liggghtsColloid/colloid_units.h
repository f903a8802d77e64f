/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: the one place where LIGGGHTS run units are
   converted to and from the SI units of the physics kernels (colloidModels).

   The project runs LIGGGHTS with "units micro" because mesh walls refuse
   meshes smaller than 1e-4 length units, which rules out SI at micron scale.
   micro: length um, time us, mass pg (1e-15 kg), so
     velocity  um/us      = 1 m/s
     force     pg um/us^2 = 1e-9 N (nN)
     energy    pg um^2/us^2 = 1e-15 J (fJ)
     stiffness nN/um      = 1e-3 N/m
     viscosity pg/(um us) = 1e-3 Pa s (mPa s)
     voltage   V,  temperature K
------------------------------------------------------------------------- */

#ifndef COLLOID_UNITS_H
#define COLLOID_UNITS_H

#include <cstring>
#include "error.h"
#include "update.h"

namespace LIGGGHTS {
namespace Colloid {

struct MicroUnits
{
    static constexpr double length = 1e-6;        // m per um
    static constexpr double time = 1e-6;          // s per us
    static constexpr double mass = 1e-15;         // kg per pg
    static constexpr double velocity = length/time;                   // m/s per um/us
    static constexpr double force = mass*length/(time*time);          // N per nN
    static constexpr double energy = force*length;                    // J per fJ
    static constexpr double stiffness = force/length;                 // N/m per nN/um
    static constexpr double viscosity = mass/(length*time);           // Pa s per mPa s
    static constexpr double dampingCoeff = force/velocity;            // N s/m per nN us/um
};

// The models assume the micro unit system; any other one is refused, naming
// the model that needs it.
inline void requireMicroUnits(LAMMPS_NS::Update *update, LAMMPS_NS::Error *error, const char *model)
{
    if (std::strcmp(update->unit_style, "micro") != 0)
    {
        char msg[256];
        std::snprintf(msg, sizeof(msg),
            "%s: needs 'units micro' (um, us, pg), the run uses 'units %s'",
            model, update->unit_style);
        error->all(FLERR, msg);
    }
}

}
}

#endif
