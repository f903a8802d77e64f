/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: the normal model "walton_braun" with
   "tangential history" or "tangential walton_braun", dry (cohesion off)
   and with every colloid cohesion variant.
------------------------------------------------------------------------- */

#include "register_variant.h"

void LIGGGHTS::Colloid::registerWaltonBraunVariants()
{
    using namespace ContactModels;
    registerVariant<WALTON_BRAUN, TANGENTIAL_HISTORY, COHESION_OFF, ROLLING_OFF, SURFACE_DEFAULT>();
    registerColloidCohesionVariants<WALTON_BRAUN, TANGENTIAL_HISTORY>();
    registerVariant<WALTON_BRAUN, TANGENTIAL_WALTON_BRAUN, COHESION_OFF, ROLLING_OFF, SURFACE_DEFAULT>();
    registerColloidCohesionVariants<WALTON_BRAUN, TANGENTIAL_WALTON_BRAUN>();
}
