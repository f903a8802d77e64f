/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: colloidal surface forces as a LIGGGHTS
   cohesion model, acting at a distance and in contact, particle-particle
   and particle-wall (mesh and primitive walls).

   Terms: van der Waals (vdw), electrostatic double layer (dl), normal
   lubrication (lub). LIGGGHTS allows one cohesion model per pair style, so
   each combination of terms is its own model, compiled separately: a term
   that is off is not in the code at all, and the neighbour range grows
   only with the terms that are on. Names as in the input script:
     cohesion colloid/vdw | colloid/dl | colloid/lub | colloid/vdw/dl
              | colloid/vdw/lub | colloid/dl/lub | colloid/vdw/dl/lub
   Keyword (fix wall/gran only): groundedWall on|off (default off): a
   grounded wall carries no double layer (seed 000: die and substrate).
   Keyword (pair_style): timeStepCheck on|off (default on), see
   checkTimeStep() and colloid_time_step.h.

   Van der Waals, double layer and lubrication at their outer cut-offs
   (property/global vdwFade, doubleLayerFade, lubricationFade): 0 (default)
   shifted, 1 faded (gapCutoffs.H, lubrication.H: uncut up to half the
   cut-off, so a shorter cut-off keeps the near field).

   Lubrication after a contact (property/global lubricationAfterContact,
   lub models): 0 (default) lubricates the separation as the approach; 1
   treats the film as ruptured once the overlap has exceeded the inner
   cut-off (the roughness: the solids touch through it), and applies no
   lubrication while the surfaces, out of contact again, separate, until
   their gap exceeds the outer cut-off (README, "Lubrication through a contact").  The state is
   per pair a contact-history value kept at a distance (as LIGGGHTS'
   capillary-bridge models keep theirs), and per particle against walls
   (fix property/atom colloidWallFilm: one wall film per particle).

   The forces are the kernels' of src/colloidModels (SI); this file only
   converts units (colloid_units.h) and applies the forces along the centre
   line. Lubrication is not applied here: its resistance c and the normal
   are handed to the implicit update of all damping forces
   (fix_colloid_implicit.h), which the pair style attaches at its init.
   Parameters (fix property/global, run units, see README.md) are read at
   every run's init and checked by the kernels.
------------------------------------------------------------------------- */

#ifdef COHESION_MODEL
// id = 16 + bit mask of the terms (1 vdw, 2 dl, 4 lub); the library uses
// ids below 16
COHESION_MODEL(COHESION_COLLOID_VDW,colloid/vdw,17)
COHESION_MODEL(COHESION_COLLOID_DL,colloid/dl,18)
COHESION_MODEL(COHESION_COLLOID_VDW_DL,colloid/vdw/dl,19)
COHESION_MODEL(COHESION_COLLOID_LUB,colloid/lub,20)
COHESION_MODEL(COHESION_COLLOID_VDW_LUB,colloid/vdw/lub,21)
COHESION_MODEL(COHESION_COLLOID_DL_LUB,colloid/dl/lub,22)
COHESION_MODEL(COHESION_COLLOID_VDW_DL_LUB,colloid/vdw/dl/lub,23)
#else

#ifndef COHESION_MODEL_COLLOID_H_
#define COHESION_MODEL_COLLOID_H_

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>
#include <cstdio>
#include <cstring>
#include <mpi.h>
#include "atom.h"
#include "comm.h"
#include "contact_models.h"
#include "cohesion_model_base.h"
#include "fix_colloid_implicit.h"
#include "fix_colloid_pair_list.h"
#include "fix_property_atom.h"
#include "fix_wall_gran.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"
#include "colloid_properties.h"
#include "colloid_time_step.h"
#include "colloid_units.h"
#include "colloid_wall_types.h"
#include "doubleLayer.H"
#include "lubrication.H"
#include "timeStepLimits.H"
#include "vanDerWaals.H"

namespace LIGGGHTS {
namespace ContactModels {

template<int Terms>
class ColloidCohesion : public CohesionModelBase
{
    static const bool vdwOn = Terms & 1;
    static const bool dlOn = Terms & 2;
    static const bool lubOn = Terms & 4;
    typedef Colloid::MicroUnits U;

public:
    ColloidCohesion(LAMMPS *lmp, IContactHistorySetup *hsetup, ContactModelBase *cmb, const char *name)
    : CohesionModelBase(lmp, hsetup, cmb),
      name_(name),
      isWall_(cmb->is_wall()),
      wall_(isWall_ ? dynamic_cast<FixWallGran*>(hsetup) : NULL),
      implicit_(NULL),
      filmOffset_(isWall_ ? -1 : hsetup->add_history_value("colloidFilmRuptured", "0")),
      filmRupture_(false),
      wallFilm_(NULL),
      groundedWall_(false),
      timeStepCheck_(true),
      vdwInnerCutoff_(0.0),
      nTypes_(0),
      rangeSI_(0.0)
    {}

    void registerSettings(Settings & settings)
    {
        if (dlOn) settings.registerOnOff("groundedWall", groundedWall_, false);
        settings.registerOnOff("timeStepCheck", timeStepCheck_, true);
    }

    void postSettings(IContactHistorySetup *, ContactModelBase *) {}

    void connectToProperties(PropertyRegistry & registry)
    {
        Colloid::requireMicroUnits(update, error, name_);
        Colloid::PropertyReader read(registry, modify, error, name_);
        nTypes_ = registry.max_type();
        rangeSI_ = 0.0;
        if (vdwOn) readVanDerWaals(read);
        if (dlOn && !(isWall_ && groundedWall_)) readDoubleLayer(read);
        if (lubOn) readLubrication(read);

        // pairs closer than factor*(Ri + Rj), walls closer than
        // (factor - 1)*R, reach surfacesClose(): wide enough for the
        // smallest particle against a wall covers every pair too
        const double rMin = registry.min_radius();
        if (!(rMin > 0.0))
        {
            char msg[256];
            std::snprintf(msg, sizeof(msg),
                "%s: the smallest particle radius is unknown (%g); create or "
                "declare the particles before the run", name_, rMin);
            error->all(FLERR, msg);
        }
        neighbor->register_contact_dist_factor(1.0 + rangeSI_/U::length/rMin);
        // pairs: the list trimmed to the range (fix_colloid_pair_list.h);
        // before the implicit update, which must stay the last fix
        if (!isWall_) FixColloidPairList::attach(lmp, rangeSI_/U::length);
        if (lubOn) attachImplicitUpdate();
        if (vdwOn) checkContactHoldsPull(read, rMin);
        if (isWall_) checkPrimitiveWallReach();
        else checkTimeStep();
    }

    void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
    void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
    void endSurfacesIntersect(SurfacesIntersectData &, ForceData &, ForceData &) {}

    // in contact (overlap): the kernels hold their inner cut-off values;
    // the normal model has already set the contact force sidata.Fn
    void surfacesIntersect(SurfacesIntersectData & sidata, ForceData & i_forces, ForceData & j_forces)
    {
        apply(sidata, sidata.r, i_forces, j_forces);
        if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_COHESION_MODEL;
    }

    void surfacesClose(SurfacesCloseData & scdata, ForceData & i_forces, ForceData & j_forces)
    {
        const double r = std::sqrt(scdata.rsq);
        const double h = (r - scdata.radsum)*U::length;
        if (h < rangeSI_)
        {
            apply(scdata, r, i_forces, j_forces);
            scdata.has_force_update = true;
        }
        // no history at a distance (the pair is not a contact partner),
        // except a ruptured film's until the gap exceeds the outer cut-off.
        // The flag is set at every step it is kept: a neighbour-list build
        // restores the history with the flags cleared, and the next one
        // keeps only flagged pairs' histories.
        double *film = filmState(scdata);
        const bool keep = film && *film != 0.0 && h < lub_.front().range();
        if (film && !keep) *film = 0.0;
        if (scdata.contact_flags)
        {
            if (keep) *scdata.contact_flags |= CONTACT_COHESION_MODEL;
            else *scdata.contact_flags &= ~CONTACT_COHESION_MODEL;
        }
    }

private:
    // r: centre distance, or centre-wall distance [run units]
    void apply(SurfacesCloseData & d, double r, ForceData & i_forces, ForceData & j_forces)
    {
        const double h = (r - d.radsum)*U::length;
        const double Ri = d.radi*U::length;
        const double Rj = d.is_wall ? colloid::wallRadius : d.radj*U::length;
        // unit normal from j (or the wall) to i
        const double en[3] = {d.delta[0]/r, d.delta[1]/r, d.delta[2]/r};

        double F = 0.0;  // [N], positive = repulsive
        if (vdwOn) F += vdw_[pairIndex(d.itype, d.jtype)].force(Ri, Rj, h);
        if (dlOn && !(d.is_wall && groundedWall_))
            F += dl_[pairIndex(d.itype, d.jtype)].force(Ri, Rj, h);
        if (lubOn && implicit_->collecting())
        {
            const double c = lub_.front().resistance(Ri, Rj, h)/U::dampingCoeff;
            if (c > 0.0 && !(filmRupture_ && filmRuptured(d, h, en)))
            {
                if (d.is_wall) implicit_->addWall(d.i, c, en, d.v_j);
                else implicit_->addPair(d.i, d.j, c, en, lub_.front().flowFactor(Ri, Rj, h));
            }
        }

        const double Fn = F/U::force;
        for (int k = 0; k < 3; k++)
        {
            i_forces.delta_F[k] += Fn*en[k];
            if (!d.is_wall) j_forces.delta_F[k] -= Fn*en[k];
        }
    }

    // The pair's history value of the film state (1: ruptured), NULL
    // without history (walls, or a pair style without it)
    double *filmState(SurfacesCloseData & d) const
    {
        return (lubOn && filmOffset_ >= 0 && d.contact_history) ? &d.contact_history[filmOffset_] : NULL;
    }

    // Updates the film state of the pair or wall contact at gap h [m] for
    // this step and tells whether the lubrication is off: the film has
    // ruptured (the overlap exceeded the inner cut-off, now or since the
    // gap last exceeded the outer cut-off), the surfaces no longer touch
    // and they separate.  (In contact the resistance stays c(h_in): the
    // liquid in the roughness; switching it off there too over-predicts
    // the measured rebound by up to 0.12 at St = 30-50.)
    // Walls: colloidWallFilm holds, per particle, the step after the last
    // one at which it was within the outer cut-off of a wall with its film
    // ruptured (0: none), so the state lapses when no wall is that close.
    bool filmRuptured(SurfacesCloseData & d, double h, const double *en)
    {
        const double hIn = lub_.front().parameters().innerCutoff;
        const double hOut = lub_.front().range();
        bool ruptured = h < -hIn;
        if (d.is_wall)
        {
            double & stamp = wallFilm_->vector_atom[d.i];
            const double now = static_cast<double>(update->ntimestep);
            ruptured = ruptured || stamp >= now;
            if (ruptured && h < hOut) stamp = now + 1.0;
        }
        else if (double *film = filmState(d))
        {
            ruptured = ruptured || *film != 0.0;
            if (ruptured) *film = 1.0;
        }
        // dh/dt >= 0: separating (en points from j, or the wall, to i)
        const double vn = (d.v_i[0] - d.v_j[0])*en[0] + (d.v_i[1] - d.v_j[1])*en[1]
                        + (d.v_i[2] - d.v_j[2])*en[2];
        return ruptured && vn >= 0.0 && h > 0.0;
    }

    // The wall films' per-particle state, created with the first wall
    // model that needs it
    void attachWallFilm()
    {
        const char *id = "colloidWallFilm";
        wallFilm_ = static_cast<FixPropertyAtom*>(
            modify->find_fix_property(id, "property/atom", "scalar", 0, 0, name_, false));
        if (wallFilm_) return;
        const char *args[] = {id, "all", "property/atom", id, "scalar", "yes", "no", "no", "0"};
        modify->add_fix(9, const_cast<char**>(args));
        wallFilm_ = static_cast<FixPropertyAtom*>(
            modify->find_fix_property(id, "property/atom", "scalar", 0, 0, name_));
    }

    // The pair style attaches the implicit update (before Modify's init);
    // a wall finds it there
    void attachImplicitUpdate()
    {
        if (!isWall_)
        {
            implicit_ = FixColloidImplicit::attach(lmp);
            return;
        }
        implicit_ = FixColloidImplicit::find(lmp);
        if (implicit_) return;
        char msg[512];
        std::snprintf(msg, sizeof(msg),
            "%s on fix wall/gran '%s': wall lubrication is part of the implicit "
            "update of all lubrication and drag, which the pair style sets up; "
            "use a pair_style gran with a colloid/.../lub cohesion model too",
            name_, wall_ ? wall_->id : "?");
        error->all(FLERR, msg);
    }

    // A primitive wall lists the particles within half the neighbour skin
    // of it (mesh walls use the contact distance factor), so a skin
    // shorter than twice the range would silently drop forces.  Checked
    // for the wall this model belongs to: walls without colloid forces
    // (e.g. frictionless side planes) need no such skin.
    void checkPrimitiveWallReach()
    {
        const double range = rangeSI_/U::length;
        if (!wall_ || wall_->is_mesh_wall() || 0.5*neighbor->skin >= range) return;
        char msg[512];
        std::snprintf(msg, sizeof(msg),
            "%s: primitive wall '%s' sees particles only within half the "
            "neighbour skin (%g um) of it, less than the range of the "
            "colloid forces (%g um); use 'neighbor %g bin' or larger, or a "
            "mesh wall", name_, wall_->id, 0.5*neighbor->skin, range, 2*range);
        error->all(FLERR, msg);
    }

    // The van der Waals pull at contact (held at its inner cut-off value
    // F0) presses a Walton-Braun contact (loadingStiffness K1) by F0/K1 at
    // rest, and by about twice that after an approach from afar; the run
    // stops where F0/K1 exceeds a quarter of the radius, for then particles
    // can pass through each other or a wall (e.g. A = 1e-18 J, K1 = 0.1
    // N/m: 5 radii). Checked, where loadingStiffness is defined, for the
    // particle types present, against each other (pair style) or this
    // fix's walls; rMin: smallest radius [run units]
    void checkContactHoldsPull(Colloid::PropertyReader & read, double rMin)
    {
        if (!modify->find_fix_property("loadingStiffness", "property/global", "peratomtypepair", 0, 0, name_, false))
            return;
        Colloid::TypePairTable K1;
        read.typePair("loadingStiffness", U::stiffness, -HUGE_VAL, HUGE_VAL, "N/m", K1);
        std::vector<int> local(nTypes_ + 1, 0), present(nTypes_ + 1, 0);
        for (int i = 0; i < atom->nlocal; i++) local[atom->type[i]] = 1;
        MPI_Allreduce(local.data(), present.data(), nTypes_ + 1, MPI_INT, MPI_MAX, world);
        std::vector<int> partners;
        if (isWall_) partners = Colloid::wallTypes(wall_);
        else for (int j = 1; j <= nTypes_; j++) if (present[j]) partners.push_back(j);

        const double R = rMin*U::length;
        for (int i = 1; i <= nTypes_; i++)
        {
            if (!present[i]) continue;
            for (int j : partners)
            {
                if (j < 1 || j > nTypes_) continue;
                const double F = std::fabs(vdw_[pairIndex(i, j)].force(R, isWall_ ? colloid::wallRadius : R, vdwInnerCutoff_));
                const double k = K1(i, j);
                // k <= 0 is the normal model's error
                if (!(k > 0.0) || F <= 0.25*R*k) continue;
                char msg[512];
                std::snprintf(msg, sizeof(msg),
                    "%s: the van der Waals pull at contact (%s, types %d-%d, radius %g m), "
                    "%g N, presses the Walton-Braun contact (loadingStiffness %g N/m) by "
                    "%g radii, more than the allowed 0.25; use loadingStiffness %g nN/um "
                    "or more, or a smaller hamakerConstant",
                    name_, isWall_ ? "particle-wall" : "particle-particle", i, j, R, F, k,
                    F/(k*R), F/(0.25*R)/U::stiffness);
                error->all(FLERR, msg);
            }
        }
    }

    // Limits for two of the lightest particles, printed by the pair style:
    // the van der Waals and double-layer "springs" |dF/dh| at their inner
    // cut-offs (dt <= 1/10 of sqrt(m*/k)); with lubrication the pair is
    // overdamped there and the explicit force needs only dt <= 1/10 of
    // c/k (the implicit update with an explicit spring is stable up to
    // dt = 2 c/k). The lubrication relaxation time m*/c is printed, not
    // enforced (implicit). LIGGGHTS' fix viscous applies its drag
    // explicitly: dt <= 1/10 of the relaxation time m/gamma.
    void checkTimeStep()
    {
        using namespace colloid::timeStep;
        Colloid::TimeStepCheck check(lmp, name_, timeStepCheck_);
        // time scale of a spring k [N/m] between two particles of mass m
        // and radius R at gap h, damped by lubrication if it is on
        auto springScale = [&](double m, double R, double k, double h)
        {
            if (!(k > 0.0)) return HUGE_VAL;
            const double spring = springTime(m/2, k);
            return lubOn ? std::max(spring, lub_.front().resistance(R, R, h)/k) : spring;
        };
        if (vdwOn)
        {
            const double t = check.smallest([&](double m, double R, int type)
            {
                const double A = vdw_[pairIndex(type, type)].parameters().hamakerConstant;
                return springScale(m, R, vanDerWaalsStiffness(A, R/2, vdwInnerCutoff_), vdwInnerCutoff_);
            });
            check.limit(lubOn ? "van der Waals spring at its inner cut-off, damped by lubrication"
                              : "van der Waals spring at its inner cut-off", t, 0.1);
        }
        if (dlOn)
        {
            const double t = check.smallest([&](double m, double R, int type)
            {
                // slope of the kernel's force (either form) over a small
                // fraction of the decay length
                const colloid::DoubleLayer & dl = dl_[pairIndex(type, type)];
                const double h0 = dl.parameters().innerCutoff;
                const double dh = 1e-7*std::min(h0, dl.debyeLength());
                const double k = (dl.force(R, R, h0) - dl.force(R, R, h0 + dh))/dh;
                return springScale(m, R, k, h0);
            });
            check.limit(lubOn ? "double-layer spring at its inner cut-off, damped by lubrication"
                              : "double-layer spring at its inner cut-off", t, 0.1);
        }
        if (lubOn)
        {
            const colloid::Lubrication & lub = lub_.front();
            const double t = check.smallest([&](double m, double R, int)
            {
                return m/2/lub.resistance(R, R, lub.parameters().innerCutoff);
            });
            check.limit("lubrication relaxation at its inner cut-off", t, 0.0);
        }
        for (int f = 0; f < modify->nfix; f++)
        {
            if (std::strcmp(modify->fix[f]->style, "viscous") != 0) continue;
            const double *gamma = Colloid::viscousGamma(static_cast<FixViscous*>(modify->fix[f]));
            const double t = check.smallest([&](double m, double, int type)
            {
                return gamma[type] > 0.0 ? m/(gamma[type]*U::dampingCoeff) : HUGE_VAL;
            });
            check.limit("relaxation time m/gamma of the explicit drag of fix viscous "
                        "(the drag through per-atom Ksl and uf is implicit, see README)", t, 0.1);
        }
    }

    int pairIndex(int itype, int jtype) const { return (itype - 1)*nTypes_ + (jtype - 1); }

    void readVanDerWaals(Colloid::PropertyReader & read)
    {
        static const char *const names[] = {
            "hamakerConstant", "hamakerConstant",
            "retardationWavelength", "vdwRetardationWavelength",
            "innerCutoff", "vdwInnerCutoff",
            "outerCutoff", "vdwOuterCutoff", NULL};
        colloid::VanDerWaalsParameters p;
        p.form = read.selector("vdwForm", 2, "0 (Derjaguin) or 1 (full Hamaker)") == 0
               ? colloid::VanDerWaalsForm::derjaguin : colloid::VanDerWaalsForm::hamaker;
        p.retardationWavelength = read.optionalScalar("vdwRetardationWavelength",
            p.retardationWavelength, U::length, -HUGE_VAL, HUGE_VAL, "m");
        p.innerCutoff = read.optionalScalar("vdwInnerCutoff", p.innerCutoff, U::length, -HUGE_VAL, HUGE_VAL, "m");
        // finite: it sets the neighbour range
        p.outerCutoff = read.scalar("vdwOuterCutoff", U::length, 0.0, 1e-3, "m");
        p.fade = read.selector("vdwFade", 2,
            "0 (shifted: F(h) - F(h_out)) or 1 (faded: F(h) up to half the "
            "outer cut-off, a smooth step to zero at it)") == 1;
        Colloid::TypePairTable A;
        read.typePair("hamakerConstant", U::energy, -HUGE_VAL, HUGE_VAL, "J", A);
        vdw_.clear();
        read.forEachTypePair(nTypes_, names, [&](int i, int j)
        {
            p.hamakerConstant = A(i, j);
            vdw_.push_back(colloid::VanDerWaals(p));
        });
        rangeSI_ = std::max(rangeSI_, p.outerCutoff);
        vdwInnerCutoff_ = p.innerCutoff;
    }

    void readDoubleLayer(Colloid::PropertyReader & read)
    {
        static const char *const names[] = {
            "concentration", "saltConcentration",
            "valence", "saltValence",
            "temperature", "liquidTemperature",
            "relativePermittivity", "relativePermittivity",
            "zeta1", "zetaPotential",
            "zeta2", "zetaPotential",
            "innerCutoff", "doubleLayerInnerCutoff",
            "outerCutoff", "doubleLayerOuterCutoff", NULL};
        colloid::DoubleLayerParameters p;
        p.form = read.selector("doubleLayerForm", 2,
                     "0 (linear superposition) or 1 (Hogg-Healy-Fuerstenau)") == 0
               ? colloid::DoubleLayerForm::linearSuperposition
               : colloid::DoubleLayerForm::hoggHealyFuerstenau;
        // no LIGGGHTS unit for amounts of substance: mol/m^3 (= mM) as in SI
        p.electrolyte.concentration = read.scalar("saltConcentration", 1.0, -HUGE_VAL, HUGE_VAL, "mol/m^3");
        const double valence = read.optionalScalar("saltValence", p.electrolyte.valence, 1.0, -HUGE_VAL, HUGE_VAL, "");
        p.electrolyte.valence = static_cast<int>(std::lround(valence));
        if (p.electrolyte.valence != valence)
            read.kernelError(std::invalid_argument("parameter 'valence' must be a whole number"), names);
        p.electrolyte.temperature = read.optionalScalar("liquidTemperature",
            p.electrolyte.temperature, 1.0, -HUGE_VAL, HUGE_VAL, "K");
        p.electrolyte.relativePermittivity = read.optionalScalar("relativePermittivity",
            p.electrolyte.relativePermittivity, 1.0, -HUGE_VAL, HUGE_VAL, "");
        p.innerCutoff = read.optionalScalar("doubleLayerInnerCutoff", p.innerCutoff, U::length, -HUGE_VAL, HUGE_VAL, "m");
        p.outerCutoff = read.scalar("doubleLayerOuterCutoff", U::length, 0.0, 1e-3, "m");
        p.fade = read.selector("doubleLayerFade", 2,
            "0 (shifted: F(h) - F(h_out)) or 1 (faded: F(h) up to half the "
            "outer cut-off, a smooth step to zero at it)") == 1;
        std::vector<double> zeta;
        read.perType("zetaPotential", 1.0, -HUGE_VAL, HUGE_VAL, "V", zeta);
        dl_.clear();
        read.forEachTypePair(nTypes_, names, [&](int i, int j)
        {
            p.zeta1 = zeta[i];
            p.zeta2 = zeta[j];
            dl_.push_back(colloid::DoubleLayer(p));
        });
        rangeSI_ = std::max(rangeSI_, p.outerCutoff);
        if (!isWall_) reportDebyeLength(p);
    }

    // What the outer cut-off hc takes away (lambda: Debye length), printed
    // by the pair style, with a warning above 5 % (e.g. nearly salt-free
    // water, lambda ~ 1 um): shifted, the fraction exp(-(hc - h0)/lambda)
    // of the force at the inner cut-off h0 (at every gap; hc under 3
    // lambda warns); faded, the force is uncut up to hc/2 and what is lost
    // is the fraction of the energy at h0 that the fade takes (the kernel's
    // faded and uncut energies of the particles' own type pair)
    void reportDebyeLength(const colloid::DoubleLayerParameters & p)
    {
        if (comm->me != 0 || dl_.empty()) return;
        const colloid::DoubleLayer & dl = dl_.front();
        const double lambda = dl.debyeLength();
        double removed = std::exp(-(p.outerCutoff - p.innerCutoff)/lambda);
        if (p.fade)
        {
            colloid::DoubleLayerParameters q = dl.parameters();
            q.fade = false;
            q.outerCutoff = HUGE_VAL;
            const double R = 1e-6;   // m: the ratio does not depend on it
            const double full = colloid::DoubleLayer(q).energy(R, R, p.innerCutoff);
            removed = full != 0.0 ? 1 - dl.energy(R, R, p.innerCutoff)/full : 0.0;
        }
        char msg[512];
        std::snprintf(msg, sizeof(msg),
            p.fade
          ? "%s: Debye length %g m; doubleLayerOuterCutoff %g m is %.3g Debye "
            "lengths; faded from half of it, it takes %.3g of the energy at "
            "the inner cut-off"
          : "%s: Debye length %g m; doubleLayerOuterCutoff %g m is %.3g Debye "
            "lengths; the force-shift there removes %.3g of the force at the "
            "inner cut-off", name_, lambda, p.outerCutoff, p.outerCutoff/lambda, removed);
        if (screen) std::fprintf(screen, "%s\n", msg);
        if (logfile) std::fprintf(logfile, "%s\n", msg);
        if (removed <= 0.05) return;
        std::snprintf(msg, sizeof(msg),
            "%s: doubleLayerOuterCutoff (%g m) is short for the Debye length "
            "(%g m): the double layer is cut to %.3g of its %s; use a cut-off "
            "of %g um or more for the full force", name_, p.outerCutoff, lambda,
            1.0 - removed, p.fade ? "energy at contact" : "force",
            (p.fade ? 2 : 1)*(p.innerCutoff + 3*lambda)/U::length);
        error->warning(FLERR, msg);
    }

    void readLubrication(Colloid::PropertyReader & read)
    {
        static const char *const names[] = {
            "viscosity", "liquidViscosity",
            "innerCutoff", "lubricationInnerCutoff",
            "outerCutoff", "lubricationOuterCutoff",
            "farField", "lubricationFarField", NULL};
        if (!atom->rmass_flag)
            error->all(FLERR, "cohesion colloid/.../lub needs per-particle masses (atom_style granular)");
        colloid::LubricationParameters p;
        p.viscosity = read.scalar("liquidViscosity", U::viscosity, -HUGE_VAL, HUGE_VAL, "Pa s");
        p.innerCutoff = read.optionalScalar("lubricationInnerCutoff", p.innerCutoff, U::length, -HUGE_VAL, HUGE_VAL, "m");
        p.outerCutoff = read.optionalScalar("lubricationOuterCutoff", p.outerCutoff, U::length, -HUGE_VAL, HUGE_VAL, "m");
        p.fade = read.selector("lubricationFade", 2,
            "0 (shifted: c(h) - c(h_out)) or 1 (faded: c(h) up to half the outer "
            "cut-off, a smooth step to zero at it)") == 1;
        p.farField = read.selector("lubricationFarField", 2,
            "0 (near field: 6 pi mu R*^2/h) or 1 (the two-sphere and sphere-wall "
            "hydrodynamics at every gap, with the pairs' flow-driven approach)") == 1;
        filmRupture_ = read.selector("lubricationAfterContact", 2,
            "0 (the separation lubricated as the approach) or 1 (no lubrication "
            "while separating after the overlap exceeded the inner cut-off)") == 1;
        if (filmRupture_ && isWall_) attachWallFilm();
        lub_.clear();
        try
        {
            lub_.push_back(colloid::Lubrication(p));
        }
        catch (const std::invalid_argument & e)
        {
            read.kernelError(e, names);
        }
        rangeSI_ = std::max(rangeSI_, p.outerCutoff);
    }

    const char *name_;
    const bool isWall_;
    FixWallGran *const wall_;   // the wall fix of a wall model, else NULL
    FixColloidImplicit *implicit_;  // the implicit damping update (lub on)
    const int filmOffset_;          // pairs: history value of the film state
    bool filmRupture_;              // lubricationAfterContact 1
    FixPropertyAtom *wallFilm_;     // walls: per-particle film state
    bool groundedWall_;
    bool timeStepCheck_;
    double vdwInnerCutoff_;                    // [m]
    int nTypes_;
    double rangeSI_;                           // largest gap with a force [m]
    std::vector<colloid::VanDerWaals> vdw_;    // per type pair
    std::vector<colloid::DoubleLayer> dl_;     // per type pair
    std::vector<colloid::Lubrication> lub_;    // one, or none before init
};

// One specialisation per registered name; the name is the input's.
#define COLLOID_COHESION_VARIANT(ID, TERMS, NAME) \
    template<> \
    class CohesionModel<ID> : public ColloidCohesion<TERMS> \
    { \
    public: \
        CohesionModel(LAMMPS *lmp, IContactHistorySetup *hsetup, ContactModelBase *cmb) \
        : ColloidCohesion<TERMS>(lmp, hsetup, cmb, "cohesion " NAME) {} \
    };
COLLOID_COHESION_VARIANT(COHESION_COLLOID_VDW, 1, "colloid/vdw")
COLLOID_COHESION_VARIANT(COHESION_COLLOID_DL, 2, "colloid/dl")
COLLOID_COHESION_VARIANT(COHESION_COLLOID_VDW_DL, 3, "colloid/vdw/dl")
COLLOID_COHESION_VARIANT(COHESION_COLLOID_LUB, 4, "colloid/lub")
COLLOID_COHESION_VARIANT(COHESION_COLLOID_VDW_LUB, 5, "colloid/vdw/lub")
COLLOID_COHESION_VARIANT(COHESION_COLLOID_DL_LUB, 6, "colloid/dl/lub")
COLLOID_COHESION_VARIANT(COHESION_COLLOID_VDW_DL_LUB, 7, "colloid/vdw/dl/lub")
#undef COLLOID_COHESION_VARIANT

}
}

#endif // COHESION_MODEL_COLLOID_H_
#endif
