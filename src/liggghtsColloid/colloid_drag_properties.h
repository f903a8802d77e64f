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
                        added by the implicit update (at a fresh start
                        with the set-up's half step, colloidFirstKick);
                        the coupling reads it and sets it to zero at each
                        exchange [nN us]
     colloidDragSet     scalar  1 once the coupling has set the three above
                        for the atom, 0 for an atom inserted since: the
                        implicit update then calls the coupling's drag
                        callback (register_colloid_models.h) before it
                        reads them, so that an inserted particle feels the
                        fluid from its first step
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
static const char *const assigned = "colloidDragSet";

}

#endif
