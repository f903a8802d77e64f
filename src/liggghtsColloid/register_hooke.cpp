/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: the colloid cohesion variants with the
   stock normal model "hooke" and "tangential history".
------------------------------------------------------------------------- */

#include "register_variant.h"

void LIGGGHTS::Colloid::registerHookeVariants()
{
    using namespace ContactModels;
    registerColloidCohesionVariants<HOOKE, TANGENTIAL_HISTORY>();
}
