/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: Walton & Braun (1986) hysteretic normal
   contact as a LIGGGHTS normal model, "model walton_braun".

   Loading with stiffness K1, unloading with K2 = K1/e^2 (kernel
   colloid::WaltonBraunNormal, src/colloidModels/waltonBraun.H); the
   largest overlap of the current contact is kept in the contact history.
   No viscous damping: the restitution comes from the hysteresis alone.
   For "tangential history" the tangential stiffness is
   kt = tangentialStiffnessRatio*K1 without tangential damping.

   At the start of a run the pair style prints the contact duration of two
   of the lightest particles, and each fix wall/gran that of the lightest
   particle against its wall, and stops if dt exceeds 1/20 of it
   (colloid_time_step.h; "timeStepCheck off" overrides).

   Parameters (fix property/global, run units micro, see README.md):
     loadingStiffness        peratomtypepair  K1 [nN/um = 1e-3 N/m]
     coefficientRestitution  peratomtypepair  e, 0 < e <= 1
     tangentialStiffnessRatio scalar, optional (default 2/7)
------------------------------------------------------------------------- */

#ifdef NORMAL_MODEL
// the library uses ids below 16 (and 9 for "off")
NORMAL_MODEL(WALTON_BRAUN,walton_braun,20)
#else

#ifndef NORMAL_MODEL_WALTON_BRAUN_H_
#define NORMAL_MODEL_WALTON_BRAUN_H_

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>
#include "contact_models.h"
#include "fix_wall_gran.h"
#include "normal_model_base.h"
#include "modify.h"
#include "update.h"
#include "colloid_properties.h"
#include "colloid_time_step.h"
#include "colloid_units.h"
#include "colloid_wall_types.h"
#include "timeStepLimits.H"
#include "waltonBraun.H"

namespace LIGGGHTS {
namespace ContactModels {

template<>
class NormalModel<WALTON_BRAUN> : public NormalModelBase
{
    typedef Colloid::MicroUnits U;

public:
    NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *cmb)
    : NormalModelBase(lmp, hsetup, cmb),
      isWall_(cmb->is_wall()),
      wall_(isWall_ ? dynamic_cast<FixWallGran*>(hsetup) : NULL),
      timeStepCheck_(true),
      nTypes_(0),
      ktRatio_(2.0/7.0)
    {
        // largest overlap [run units] and the step it was last updated in:
        // a contact whose last update is older than the previous step is a
        // new contact (LIGGGHTS keeps the history of separated pairs)
        historyOffset_ = hsetup->add_history_value("wbMaxOverlap", "0");
        hsetup->add_history_value("wbLastStep", "0");
    }

    void registerSettings(Settings & settings)
    {
        settings.registerOnOff("timeStepCheck", timeStepCheck_, true);
    }
    void postSettings(IContactHistorySetup *, ContactModelBase *) {}

    void connectToProperties(PropertyRegistry & registry)
    {
        static const char *const names[] = {
            "loadingStiffness", "loadingStiffness",
            "restitution", "coefficientRestitution", NULL};
        const char *caller = "model walton_braun";
        Colloid::requireMicroUnits(update, error, caller);
        Colloid::PropertyReader read(registry, modify, error, caller);
        nTypes_ = registry.max_type();
        Colloid::TypePairTable K1, e;
        read.typePair("loadingStiffness", U::stiffness, -HUGE_VAL, HUGE_VAL, "N/m", K1);
        read.typePair("coefficientRestitution", 1.0, -HUGE_VAL, HUGE_VAL, "", e);
        ktRatio_ = read.optionalScalar("tangentialStiffnessRatio", 2.0/7.0, 1.0, 0.0, 10.0, "");
        kernels_.clear();
        read.forEachTypePair(nTypes_, names, [&](int i, int j)
        {
            colloid::WaltonBraunNormalParameters p;
            p.loadingStiffness = K1(i, j);
            p.restitution = e(i, j);
            kernels_.push_back(colloid::WaltonBraunNormal(p));
        });

        // dt <= 1/20 of the contact duration of two of the lightest particles
        // (pair style), or of the lightest particle against the wall (wall
        // fix: m* = m, and the wall's stiffness may differ from the pairs')
        Colloid::TimeStepCheck check(lmp, caller, timeStepCheck_);
        if (isWall_)
        {
            const double tc = check.smallest([&](double m, double, int type)
            {
                return wallContactTime(m, type);
            });
            check.limit("Walton-Braun contact duration of the lightest particle against a wall", tc, 0.05);
            return;
        }
        const double tc = check.smallest([&](double m, double, int type)
        {
            const colloid::WaltonBraunNormal & wb = kernels_[(type - 1)*nTypes_ + (type - 1)];
            return colloid::timeStep::waltonBraunContactTime(m/2, wb.loadingStiffness(), wb.unloadingStiffness());
        });
        check.limit("Walton-Braun contact duration of two of the lightest particles", tc, 0.05);
    }

    // linear spring
    double stressStrainExponent() { return 1.0; }

    void surfacesIntersect(SurfacesIntersectData & sidata, ForceData & i_forces, ForceData & j_forces)
    {
        const colloid::WaltonBraunNormal & wb = kernels_[(sidata.itype - 1)*nTypes_ + (sidata.jtype - 1)];
        double * const history = &sidata.contact_history[historyOffset_];
        const double step = static_cast<double>(update->ntimestep);
        colloid::WaltonBraunNormalState state;
        state.maxOverlap = step - history[1] > 1.0 ? 0.0 : history[0]*U::length;

        const double Fn = wb.force(sidata.deltan*U::length, state)/U::force;
        if (sidata.computeflag && sidata.shearupdate)
        {
            history[0] = state.maxOverlap/U::length;
            history[1] = step;
        }

        const double K1 = wb.loadingStiffness()/U::stiffness;
        sidata.Fn = Fn;
        sidata.kn = K1;
        sidata.kt = ktRatio_*K1;
        sidata.gamman = 0.0;
        sidata.gammat = 0.0;
        if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;

        const double Fscaled = sidata.is_wall ? Fn*sidata.area_ratio : Fn;
        for (int k = 0; k < 3; k++)
        {
            i_forces.delta_F[k] += Fscaled*sidata.en[k];
            if (!sidata.is_wall) j_forces.delta_F[k] -= Fscaled*sidata.en[k];
        }
    }

    void surfacesClose(SurfacesCloseData & scdata, ForceData &, ForceData &)
    {
        if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_NORMAL_MODEL;
        if (scdata.contact_history) scdata.contact_history[historyOffset_] = 0.0;
    }

    void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
    void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

private:
    // Contact duration [s] of a particle of mass m [kg] and this type
    // against this wall fix's walls (the primitive wall's type, or each
    // mesh's), the shortest
    double wallContactTime(double m, int type) const
    {
        double tc = HUGE_VAL;
        for (int j : Colloid::wallTypes(wall_))
        {
            if (j < 1 || j > nTypes_) continue;
            const colloid::WaltonBraunNormal & wb = kernels_[(type - 1)*nTypes_ + (j - 1)];
            tc = std::min(tc, colloid::timeStep::waltonBraunContactTime(m, wb.loadingStiffness(), wb.unloadingStiffness()));
        }
        return tc;
    }

    const bool isWall_;
    FixWallGran *const wall_;   // the wall fix of a wall model, else NULL
    bool timeStepCheck_;
    int historyOffset_;
    int nTypes_;
    double ktRatio_;
    std::vector<colloid::WaltonBraunNormal> kernels_;  // per type pair
};

}
}

#endif // NORMAL_MODEL_WALTON_BRAUN_H_
#endif
