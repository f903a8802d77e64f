/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: the time-step limits of the models, printed
   at the start of a run and enforced.

   Each model gives the time scale of its stiffest explicitly integrated
   term for a pair of two particles like the lightest one present (the
   smallest over the particles, all processes); the run stops when
   dt > fraction x that time scale, unless the pair style says
   "timeStepCheck off" (expert override: a warning instead). Terms that are
   integrated implicitly (lubrication) are printed but not enforced. The
   time scales are the kernels' (src/colloidModels/timeStepLimits.H). The
   coupling's drag is implicit and its Stokes time the coupling's to
   check; LIGGGHTS' own explicit fix viscous is checked here.
------------------------------------------------------------------------- */

#ifndef COLLOID_TIME_STEP_H
#define COLLOID_TIME_STEP_H

#include <mpi.h>
#include <cstdio>
#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_viscous.h"
#include "input.h"
#include "lammps.h"
#include "update.h"
#include "variable.h"
#include "colloid_units.h"

namespace LIGGGHTS {
namespace Colloid {

// The per-type drag coefficients gamma [run units] of a LIGGGHTS fix
// viscous, a protected member: read through a pointer to member formed
// in a derived class (never instantiated)
struct ViscousGammaAccess : LAMMPS_NS::FixViscous
{
    static double *of(LAMMPS_NS::FixViscous *fix)
    {
        return fix->*(&ViscousGammaAccess::gamma);
    }
};

inline const double *viscousGamma(LAMMPS_NS::FixViscous *fix)
{
    return ViscousGammaAccess::of(fix);
}

class TimeStepCheck
{
public:
    // model: the model's name as in the input; enforce: timeStepCheck on
    TimeStepCheck(LAMMPS_NS::LAMMPS *lmp, const char *model, bool enforce)
    : lmp_(lmp), model_(model), enforce_(enforce)
    {}

    // Smallest over the particles of scale(mass [kg], radius [m], type) [s];
    // negative when there are no particles yet
    template<class Scale>
    double smallest(const Scale & scale) const
    {
        LAMMPS_NS::Atom *atom = lmp_->atom;
        double local = HUGE_VAL;
        for (int i = 0; i < atom->nlocal; i++)
        {
            const double t = scale(atom->rmass[i]*MicroUnits::mass, atom->radius[i]*MicroUnits::length, atom->type[i]);
            if (t < local) local = t;
        }
        double global = HUGE_VAL;
        MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MIN, lmp_->world);
        return global < HUGE_VAL ? global : -1.0;
    }

    // print the time scale [s]; stop if dt > fraction x it (fraction > 0)
    void limit(const char *what, double seconds, double fraction) const
    {
        if (seconds < 0.0) return;
        const double dt = lmp_->update->dt*MicroUnits::time;
        char msg[512], allowed[128] = " (integrated implicitly, not enforced)";
        if (fraction > 0.0)
            std::snprintf(allowed, sizeof(allowed), " (largest allowed dt: %g s)", fraction*seconds);
        std::snprintf(msg, sizeof(msg),
            "%s: time-step limit, %s: %g s; dt = %g s is %.3g of it%s",
            model_, what, seconds, dt, dt/seconds, allowed);
        print(msg);
        if (!(fraction > 0.0) || dt <= fraction*seconds) return;
        // Inside colloidDEMFoam (which defines colloid_timestep) the step
        // is the coupling's setting, in seconds; alone, LIGGGHTS' own
        char coupled[] = "colloid_timestep";
        if (lmp_->input->variable->find(coupled) >= 0)
            std::snprintf(msg, sizeof(msg),
                "%s: the time step %g s exceeds %g x the %s (%g s); set DEM { "
                "timeStep %g; } (seconds) or less in constant/couplingProperties, "
                "or, at your own risk, 'timeStepCheck off' on the pair_style (or "
                "fix wall/gran) line of the DEM script",
                model_, dt, fraction, what, seconds, fraction*seconds);
        else
            std::snprintf(msg, sizeof(msg),
                "%s: the time step %g s exceeds %g x the %s (%g s); use 'timestep %g' "
                "or less (run units us), or, at your own risk, 'timeStepCheck off' on "
                "the pair_style (or fix wall/gran) line",
                model_, dt, fraction, what, seconds, fraction*seconds/MicroUnits::time);
        if (enforce_)
            lmp_->error->all(FLERR, msg);
        else
            lmp_->error->warning(FLERR, msg);
    }

private:
    void print(const char *msg) const
    {
        if (lmp_->comm->me != 0) return;
        if (lmp_->screen) std::fprintf(lmp_->screen, "%s\n", msg);
        if (lmp_->logfile) std::fprintf(lmp_->logfile, "%s\n", msg);
    }

    LAMMPS_NS::LAMMPS *lmp_;
    const char *model_;
    bool enforce_;
};

}
}

#endif
