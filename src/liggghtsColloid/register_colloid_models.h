/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: entry point.

   registerColloidModels() adds the plugin's model names to LIGGGHTS'
   contact-model factory and registers every model combination the project
   uses with the pair-style and wall factories. It must run before the
   pair_style, fix wall/gran or read_restart command that names a plugin
   model; a static initialiser in the library already calls it when the
   library is loaded, and calling it again does nothing. A program that
   links the plugin should call it once anyway: the call makes the link
   dependency explicit, so the linker cannot drop the library.

   colloidImplicitUpdate(lmp) sets up, in the LIGGGHTS instance lmp (a
   LAMMPS_NS::LAMMPS*, as lammps_open gives it), the implicit update of
   lubrication and drag (fix_colloid_implicit.h) that takes the drag from
   the per-atom properties of colloid_drag_properties.h. A pair style with
   a lubrication model sets it up itself; a CFD coupling calls this after
   the input script and its own fixes, before the first run.

   colloidDragCallback(lmp, callback, context) gives that update a hook
   for particles inserted during a run: at every step (and set-up) in
   which some atom has the property colloidDragSet 0
   (colloid_drag_properties.h), the update calls callback(context) on
   every rank of lmp, before it reads the drag; the callback sets the
   drag properties of those atoms and their colloidDragSet to 1 (it may
   communicate: all ranks call it). Without it such atoms have the
   property values they were inserted with (no drag) until the coupling
   sets them. A NULL callback removes the hook; the hook outlives the
   fix's re-creation by colloidImplicitUpdate.

   colloidFirstKick(lmp, on): with on = 1, the set-up of the next run
   command (a run of N > 0 steps, with "pre yes") is the particles' first
   half kick (a fresh start): the update hands its drag impulse to the
   coupling with those of the steps. Call it again with on = 0 after that
   run. Any other set-up (of a run 0, or one LIGGGHTS makes for particles
   that have already taken steps) replaces forces whose impulse was
   counted in full with their step, and counts nothing.

   colloidReneighborAt(lmp, step) rebuilds the neighbour lists of lmp at
   the given DEM step (fix_colloid_reneighbor.h: what a fix does at the
   rebuild, e.g. massflow/mesh deleting the particles it counted, is
   done before a restart is written after that step).  The first call
   creates the fix: make it before the first run (step -1: none yet).

   colloidInsertAtoms(lmp, n, x, v, radius, density, type) queues n
   spheres of the given radius, density (the mass from them) and atom
   type, in group all, without rotation, at the positions x and
   velocities v (3n values each, LIGGGHTS units), with ids in list order
   after the largest present, for the first step of the next run
   (fix_colloid_insert.h; every rank passes the same list).  It returns
   0, or -1 for an atom type the DEM does not have.  colloidInsertedAtoms
   (lmp) gives the number created from the last queue on all ranks (-1
   before that step; fewer than n for positions outside the box).  The
   first call of colloidInsertAtoms (n may be 0) creates the fix: make it
   before the first run.
------------------------------------------------------------------------- */

#ifndef COLLOID_REGISTER_COLLOID_MODELS_H
#define COLLOID_REGISTER_COLLOID_MODELS_H

extern "C" __attribute__((visibility("default"))) void registerColloidModels();
extern "C" __attribute__((visibility("default"))) void colloidImplicitUpdate(void *lmp);
extern "C" __attribute__((visibility("default"))) void colloidDragCallback
(
    void *lmp,
    void (*callback)(void *context),
    void *context
);
extern "C" __attribute__((visibility("default"))) void colloidFirstKick(void *lmp, int on);
extern "C" __attribute__((visibility("default"))) void colloidReneighborAt
(
    void *lmp,
    long long step
);
extern "C" __attribute__((visibility("default"))) int colloidInsertAtoms
(
    void *lmp,
    int n,
    const double *x,
    const double *v,
    double radius,
    double density,
    int type
);
extern "C" __attribute__((visibility("default"))) long long colloidInsertedAtoms(void *lmp);

#endif
