/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: the colloid cohesion variants with the
   stock normal model "hertz" and "tangential history", without and
   with the rolling model "epsd2".
------------------------------------------------------------------------- */

#include "register_variant.h"

void LIGGGHTS::Colloid::registerHertzVariants()
{
    using namespace ContactModels;
    registerColloidCohesionVariants<HERTZ, TANGENTIAL_HISTORY>();
    // with LIGGGHTS' rolling resistance "epsd2" (a rolling spring capped
    // at the rolling-friction torque): the filtration's rollingFriction
    registerColloidCohesionVariants<HERTZ, TANGENTIAL_HISTORY, ROLLING_EPSD2>();
}
