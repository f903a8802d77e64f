/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: model names and combinations, see
   register_colloid_models.h.
------------------------------------------------------------------------- */

#include "register_colloid_models.h"
#include "fix_colloid_implicit.h"
#include "fix_colloid_insert.h"
#include "fix_colloid_reneighbor.h"
#include "register_variant.h"

using namespace LIGGGHTS;

extern "C" void registerColloidModels()
{
    static bool done = false;
    if (done) return;
    done = true;

    // the names the input script uses; ids and names come from the
    // COHESION_MODEL / NORMAL_MODEL declarations of the plugin's headers
    ContactModels::Factory & models = ContactModels::Factory::instance();
    #define COHESION_MODEL(identifier, name, id) models.addCohesionModel(#name, id);
    #include "cohesion_model_colloid.h"
    #undef COHESION_MODEL
    #define NORMAL_MODEL(identifier, name, id) models.addNormalModel(#name, id);
    #include "normal_model_walton_braun.h"
    #undef NORMAL_MODEL
    #define TANGENTIAL_MODEL(identifier, name, id) models.addTangentialModel(#name, id);
    #include "tangential_model_walton_braun.h"
    #undef TANGENTIAL_MODEL

    Colloid::registerHookeVariants();
    Colloid::registerHertzVariants();
    Colloid::registerWaltonBraunVariants();
}

extern "C" void colloidImplicitUpdate(void *lmp)
{
    LAMMPS_NS::FixColloidImplicit::attach(static_cast<LAMMPS_NS::LAMMPS *>(lmp));
}

extern "C" void colloidDragCallback(void *lmp, void (*callback)(void *), void *context)
{
    LAMMPS_NS::FixColloidImplicit::setDragCallback(static_cast<LAMMPS_NS::LAMMPS *>(lmp), callback, context);
}

extern "C" void colloidFirstKick(void *lmp, int on)
{
    LAMMPS_NS::FixColloidImplicit::setFirstKick(static_cast<LAMMPS_NS::LAMMPS *>(lmp), on != 0);
}

extern "C" void colloidReneighborAt(void *lmp, long long step)
{
    LAMMPS_NS::FixColloidReneighbor::at(static_cast<LAMMPS_NS::LAMMPS *>(lmp), step);
}

extern "C" int colloidInsertAtoms(void *lmp, int n, const double *x, const double *v,
                                  double radius, double density, int type)
{
    LAMMPS_NS::FixColloidInsert *fix =
        LAMMPS_NS::FixColloidInsert::attach(static_cast<LAMMPS_NS::LAMMPS *>(lmp));
    if (n == 0) return 0;
    return fix->queue(n, x, v, radius, density, type) ? 0 : -1;
}

extern "C" long long colloidInsertedAtoms(void *lmp)
{
    return LAMMPS_NS::FixColloidInsert::attach(static_cast<LAMMPS_NS::LAMMPS *>(lmp))->created();
}

namespace {

// registers the models when the library is loaded
struct RegisterAtLoad
{
    RegisterAtLoad() { registerColloidModels(); }
} registerAtLoad;

}
