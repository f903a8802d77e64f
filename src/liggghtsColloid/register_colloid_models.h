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
------------------------------------------------------------------------- */

#ifndef COLLOID_REGISTER_COLLOID_MODELS_H
#define COLLOID_REGISTER_COLLOID_MODELS_H

extern "C" __attribute__((visibility("default"))) void registerColloidModels();

#endif
