/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: names of the per-atom properties through
   which the CFD coupling hands the fluid drag to the DEM, one place for
   the plugin and the coupling (src/coupling/demCoupling). Each is a
   "fix property/atom" created by the coupling; run units (micro).

   The drag on particle i over a DEM step is K_i (u_f,i - v_i') + F_i,
   v_i' the end-of-step velocity of the implicit update
   (fix_colloid_implicit.h):
     Ksl        scalar  K_i, drag coefficient [pg/us = 1e-9 kg/s]
     uf         vector  u_f,i, fluid velocity at the particle [um/us = m/s]
     dragforce  vector  F_i, explicit part (pressure gradient, buoyancy,
                        ...) [nN]
     colloidDragImpulse vector  sum over the steps of dt K_i (u_f,i - v_i'),
                        added by the implicit update; the coupling reads it
                        and sets it to zero at each exchange [nN us]
   The first three names are those of CFDEMcoupling (couple/cfd/force/...),
   whose explicit drag fix must not be used together with them.
------------------------------------------------------------------------- */

#ifndef COLLOID_DRAG_PROPERTIES_H
#define COLLOID_DRAG_PROPERTIES_H

namespace colloidDrag {

static const char *const coefficient = "Ksl";
static const char *const fluidVelocity = "uf";
static const char *const explicitForce = "dragforce";
static const char *const impulse = "colloidDragImpulse";

}

#endif
