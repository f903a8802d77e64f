/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: registration of one model combination with
   LIGGGHTS' pair-style and wall factories.

   LIGGGHTS compiles one PairStyles::Granular / Walls::Granular class per
   combination (normal, tangential, cohesion, rolling, surface) and looks it
   up by the combination's hash. A combination that is not registered falls
   back to the library's generic class, which does not know this plugin's
   models, so every combination the project uses is registered here.
------------------------------------------------------------------------- */

#ifndef COLLOID_REGISTER_VARIANT_H
#define COLLOID_REGISTER_VARIANT_H

// an installed header uses FixInsertStream without including it
#include "fix_insert_stream.h"
#include "contact_models.h"
#include "pair_gran_base.h"
#include "fix_wall_gran_base.h"
#include "granular_pair_style.h"
#include "granular_wall.h"

namespace LIGGGHTS {
namespace Colloid {

template<typename T>
PairStyles::IGranularPairStyle * createPair(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::PairGran *parent, const int64_t hash)
{
    return new T(lmp, parent, hash);
}

template<typename T>
Walls::IGranularWall * createWall(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::FixWallGran *parent, const int64_t hash)
{
    return new T(lmp, parent, hash);
}

template<int Normal, int Tangential, int Cohesion, int Rolling, int Surface>
void registerVariant()
{
    typedef ContactModels::GranStyle<Normal, Tangential, Cohesion, Rolling, Surface> Style;
    typedef ContactModels::ContactModel<Style> Model;
    PairStyles::Factory::instance().addStyle("gran", Style::HASHCODE, &createPair<PairStyles::Granular<Model> >);
    Walls::Factory::instance().addStyle("gran", Style::HASHCODE, &createWall<Walls::Granular<Model> >);
}

// every colloid cohesion variant (see cohesion_model_colloid.h) with one
// normal, tangential and rolling model, default surface
template<int Normal, int Tangential, int Rolling = ContactModels::ROLLING_OFF>
void registerColloidCohesionVariants()
{
    using namespace ContactModels;
    registerVariant<Normal, Tangential, COHESION_COLLOID_VDW, Rolling, SURFACE_DEFAULT>();
    registerVariant<Normal, Tangential, COHESION_COLLOID_DL, Rolling, SURFACE_DEFAULT>();
    registerVariant<Normal, Tangential, COHESION_COLLOID_LUB, Rolling, SURFACE_DEFAULT>();
    registerVariant<Normal, Tangential, COHESION_COLLOID_VDW_DL, Rolling, SURFACE_DEFAULT>();
    registerVariant<Normal, Tangential, COHESION_COLLOID_VDW_LUB, Rolling, SURFACE_DEFAULT>();
    registerVariant<Normal, Tangential, COHESION_COLLOID_DL_LUB, Rolling, SURFACE_DEFAULT>();
    registerVariant<Normal, Tangential, COHESION_COLLOID_VDW_DL_LUB, Rolling, SURFACE_DEFAULT>();
}

// one per normal model, each in its own translation unit (compile time)
void registerHookeVariants();
void registerHertzVariants();
void registerWaltonBraunVariants();

}
}

#endif
