/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: the colloid cohesion variants with the
   stock normal model "hertz" and "tangential history".
------------------------------------------------------------------------- */

#include "register_variant.h"

void LIGGGHTS::Colloid::registerHertzVariants()
{
    using namespace ContactModels;
    registerColloidCohesionVariants<HERTZ, TANGENTIAL_HISTORY>();
}
