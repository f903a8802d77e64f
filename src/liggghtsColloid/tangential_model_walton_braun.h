/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: Walton & Braun (1986) incremental-slip
   tangential contact as a LIGGGHTS tangential model,
   "tangential walton_braun" (kernel colloid::WaltonBraunTangential,
   src/colloidModels/waltonBraun.H).

   On a fix wall/gran line, "diRenzoDiMaio on" (default off) makes the
   particle-wall contacts use Di Renzo & Di Maio (2005) instead (kernel
   colloid::DiRenzoDiMaio, seed 000), with G* from the particle's and the
   wall's youngsModulus and poissonsRatio.

   At the start of a run the pair style, and each fix wall/gran without
   diRenzoDiMaio, prints the half-period pi sqrt(m_t/K_T0) of the
   tangential spring and stops if dt exceeds 1/20 of it (colloid_time_step.h;
   "timeStepCheck off" overrides).

   Torques: the tangential force F acts at the contact point, cri (crj)
   from the centre of i (j) along -en (+en): torque_i = -cri en x F,
   torque_j = -crj en x F.

   Parameters (fix property/global, run units micro, see README.md):
     coefficientFriction  peratomtypepair  mu
     tangentialStiffness  peratomtypepair  K_T0 [nN/um = 1e-3 N/m]
     youngsModulus        peratomtype      [nN/um^2 = 1e3 Pa] (diRenzoDiMaio)
     poissonsRatio        peratomtype      (diRenzoDiMaio)
------------------------------------------------------------------------- */

#ifdef TANGENTIAL_MODEL
// the library uses ids below 16
TANGENTIAL_MODEL(TANGENTIAL_WALTON_BRAUN,walton_braun,20)
#else

#ifndef TANGENTIAL_MODEL_WALTON_BRAUN_H_
#define TANGENTIAL_MODEL_WALTON_BRAUN_H_

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>
#include <cstdio>
#include "comm.h"
#include "contact_models.h"
#include "fix_wall_gran.h"
#include "tangential_model_base.h"
#include "modify.h"
#include "update.h"
#include "colloid_properties.h"
#include "colloid_time_step.h"
#include "colloid_units.h"
#include "colloid_wall_types.h"
#include "diRenzoDiMaio.H"
#include "elasticMaterial.H"
#include "timeStepLimits.H"
#include "waltonBraun.H"

namespace LIGGGHTS {
namespace ContactModels {

template<>
class TangentialModel<TANGENTIAL_WALTON_BRAUN> : public TangentialModelBase
{
    typedef Colloid::MicroUnits U;

    // contact history layout (run units), see surfacesIntersect
    enum { LOAD = 0, TURNING = 3, LAST_INCREMENT = 6, LAST_NORMAL = 9, LAST_STEP = 10, SIZE = 11 };

public:
    TangentialModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *cmb)
    : TangentialModelBase(lmp, hsetup, cmb),
      isWall_(cmb->is_wall()),
      wall_(isWall_ ? dynamic_cast<FixWallGran*>(hsetup) : NULL),
      diRenzoWall_(false),
      timeStepCheck_(true),
      diRenzoWarned_(false),
      nTypes_(0)
    {
        // vectors change sign when seen from the other particle ("1")
        offset_ = hsetup->add_history_value("wbLoadX", "1");
        hsetup->add_history_value("wbLoadY", "1");
        hsetup->add_history_value("wbLoadZ", "1");
        hsetup->add_history_value("wbTurningX", "1");
        hsetup->add_history_value("wbTurningY", "1");
        hsetup->add_history_value("wbTurningZ", "1");
        hsetup->add_history_value("wbIncrementX", "1");
        hsetup->add_history_value("wbIncrementY", "1");
        hsetup->add_history_value("wbIncrementZ", "1");
        hsetup->add_history_value("wbNormalForce", "0");
        hsetup->add_history_value("wbTangentialStep", "0");
    }

    void registerSettings(Settings & settings)
    {
        settings.registerOnOff("diRenzoDiMaio", diRenzoWall_, false);
        settings.registerOnOff("timeStepCheck", timeStepCheck_, true);
    }

    void postSettings(IContactHistorySetup *, ContactModelBase *) {}

    void connectToProperties(PropertyRegistry & registry)
    {
        static const char *const names[] = {
            "initialStiffness", "tangentialStiffness",
            "friction", "coefficientFriction",
            "effectiveShearModulus", "youngsModulus, poissonsRatio",
            "youngsModulus", "youngsModulus",
            "poissonsRatio", "poissonsRatio", NULL};
        const char *caller = "tangential walton_braun";
        Colloid::requireMicroUnits(update, error, caller);
        Colloid::PropertyReader read(registry, modify, error, caller);
        nTypes_ = registry.max_type();
        Colloid::TypePairTable mu, kt;
        read.typePair("coefficientFriction", 1.0, -HUGE_VAL, HUGE_VAL, "", mu);
        read.typePair("tangentialStiffness", U::stiffness, -HUGE_VAL, HUGE_VAL, "N/m", kt);
        const bool diRenzo = isWall_ && diRenzoWall_;
        std::vector<double> E, nu;
        if (diRenzo)
        {
            read.perType("youngsModulus", U::force/(U::length*U::length), -HUGE_VAL, HUGE_VAL, "Pa", E);
            read.perType("poissonsRatio", 1.0, -HUGE_VAL, HUGE_VAL, "", nu);
        }
        waltonBraun_.clear();
        diRenzo_.clear();
        read.forEachTypePair(nTypes_, names, [&](int i, int j)
        {
            colloid::WaltonBraunTangentialParameters p;
            p.initialStiffness = kt(i, j);
            p.friction = mu(i, j);
            waltonBraun_.push_back(colloid::WaltonBraunTangential(p));
            if (!diRenzo) return;
            colloid::ElasticMaterial a, b;
            a.youngsModulus = E[i];
            a.poissonsRatio = nu[i];
            b.youngsModulus = E[j];
            b.poissonsRatio = nu[j];
            a.check();
            b.check();
            colloid::DiRenzoDiMaioParameters q;
            q.effectiveShearModulus = colloid::effectiveShearModulus(a, b);
            q.friction = mu(i, j);
            diRenzo_.push_back(colloid::DiRenzoDiMaio(q));
        });
        checkTimeStep();
    }

    void surfacesIntersect(const SurfacesIntersectData & sidata, ForceData & i_forces, ForceData & j_forces)
    {
        const colloid::Vec3 en = {{sidata.en[0], sidata.en[1], sidata.en[2]}};
        double * const hist = &sidata.contact_history[offset_];
        const double step = static_cast<double>(update->ntimestep);
        // a contact not updated in the previous step is a new one
        const bool newContact = step - hist[LAST_STEP] > 1.0;
        const bool updateHistory = sidata.computeflag && sidata.shearupdate;
        const double dt = update->dt;
        const colloid::Vec3 ds = {{sidata.vtr1*dt*U::length, sidata.vtr2*dt*U::length, sidata.vtr3*dt*U::length}};
        const double Fn = sidata.Fn*U::force;
        const int index = (sidata.itype - 1)*nTypes_ + (sidata.jtype - 1);

        colloid::Vec3 Ft;
        if (isWall_ && diRenzoWall_)
        {
            checkDiRenzoStep(diRenzo_[index].stiffness(sidata.radi*U::length, sidata.deltan*U::length),
                             sidata.i, sidata.deltan/sidata.radi);
            colloid::DiRenzoDiMaioState s;
            if (!newContact) s.shear = colloid::tangentialPart(stored(hist, LOAD, U::length), en);
            Ft = diRenzo_[index].force(sidata.radi*U::length, sidata.deltan*U::length, ds, Fn, s);
            if (updateHistory) store(hist, LOAD, s.shear, U::length);
        }
        else
        {
            colloid::WaltonBraunTangentialState s;
            if (!newContact)
            {
                s.load = colloid::tangentialPart(stored(hist, LOAD, U::force), en);
                s.turningLoad = colloid::tangentialPart(stored(hist, TURNING, U::force), en);
                s.lastIncrement = colloid::tangentialPart(stored(hist, LAST_INCREMENT, U::length), en);
                s.lastNormalForce = hist[LAST_NORMAL]*U::force;
            }
            Ft = waltonBraun_[index].force(ds, Fn, s);
            if (updateHistory)
            {
                store(hist, LOAD, s.load, U::force);
                store(hist, TURNING, s.turningLoad, U::force);
                store(hist, LAST_INCREMENT, s.lastIncrement, U::length);
                hist[LAST_NORMAL] = s.lastNormalForce/U::force;
            }
        }
        if (updateHistory) hist[LAST_STEP] = step;
        if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_TANGENTIAL_MODEL;

        // force on i [run units] and en x F for the torques
        const double F[3] = {Ft[0]/U::force, Ft[1]/U::force, Ft[2]/U::force};
        const double t[3] = {en[1]*F[2] - en[2]*F[1], en[2]*F[0] - en[0]*F[2], en[0]*F[1] - en[1]*F[0]};
        const double w = sidata.is_wall ? sidata.area_ratio : 1.0;
        for (int k = 0; k < 3; k++)
        {
            i_forces.delta_F[k] += w*F[k];
            i_forces.delta_torque[k] -= w*sidata.cri*t[k];
            if (!sidata.is_wall)
            {
                j_forces.delta_F[k] -= F[k];
                j_forces.delta_torque[k] -= sidata.crj*t[k];
            }
        }
    }

    void surfacesClose(SurfacesCloseData & scdata, ForceData &, ForceData &)
    {
        if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_TANGENTIAL_MODEL;
        if (!scdata.contact_history) return;
        for (int k = 0; k < SIZE; k++) scdata.contact_history[offset_ + k] = 0.0;
    }

    void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
    void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

private:
    // dt <= 1/20 of pi sqrt(m_t/K_T0), the half-period of the tangential
    // spring as the normal contact's duration is that of the normal one,
    // with m_t = 2/7 m* for solid spheres (the contact point moves with the
    // rotation too): two of the lightest particles (pair style),
    // or the lightest particle against this fix's walls (m* = m). Di
    // Renzo-Di Maio walls are checked on the fly (checkDiRenzoStep): their
    // stiffness grows with the overlap, which a start-up check does not know.
    void checkTimeStep()
    {
        if (isWall_ && diRenzoWall_) return;
        Colloid::TimeStepCheck check(lmp, "tangential walton_braun", timeStepCheck_);
        const std::vector<int> walls = Colloid::wallTypes(wall_);
        const double t = check.smallest([&](double m, double, int type)
        {
            double k = 0.0;
            if (!isWall_) k = waltonBraun_[(type - 1)*nTypes_ + (type - 1)].parameters().initialStiffness;
            for (int j : walls)
                if (j >= 1 && j <= nTypes_)
                    k = std::max(k, waltonBraun_[(type - 1)*nTypes_ + (j - 1)].parameters().initialStiffness);
            if (!(k > 0.0)) return HUGE_VAL;
            return colloid::timeStep::linearContactTime(2.0/7.0*(isWall_ ? m : m/2), k);
        });
        check.limit(isWall_ ? "tangential half-period of the lightest particle against a wall"
                            : "tangential half-period of two of the lightest particles", t, 0.05);
    }

    // The same limit for a Di Renzo-Di Maio wall contact of particle i at
    // its current tangential stiffness k [N/m] (overlap: fraction of the
    // radius), each step: a stop (or, with timeStepCheck off, one warning)
    // when the overlap has made the spring too stiff for the step
    void checkDiRenzoStep(double k, int i, double overlap)
    {
        const double halfPeriod = colloid::timeStep::linearContactTime(2.0/7.0*atom->rmass[i]*U::mass, k);
        const double dt = update->dt*U::time;
        if (dt <= 0.05*halfPeriod || diRenzoWarned_) return;
        char msg[768];
        std::snprintf(msg, sizeof(msg),
            "tangential walton_braun: at step " BIGINT_FORMAT " a contact with wall '%s' "
            "(diRenzoDiMaio on) reached an overlap of %.6g radii, where the Di Renzo-Di "
            "Maio tangential stiffness is %g N/m: the time step %g s exceeds 0.05 x the "
            "half-period of that spring, %g s; use a time step of %g s or less (LIGGGHTS "
            "'timestep %g', or DEM { timeStep %g; } with colloidDEMFoam), stiffer normal "
            "contact (less overlap), or, at your own risk, 'timeStepCheck off' on the "
            "fix wall/gran line", update->ntimestep, wall_ ? wall_->id : "?", overlap, k,
            dt, halfPeriod, 0.05*halfPeriod, 0.05*halfPeriod/U::time, 0.05*halfPeriod);
        if (timeStepCheck_)
        {
            // only this rank knows: error->one, which aborts without
            // flushing a redirected screen, so the message is written and
            // flushed here first
            for (FILE *out : {screen, logfile})
                if (out)
                {
                    std::fprintf(out, "ERROR on proc %d: %s\n", comm->me, msg);
                    std::fflush(out);
                }
            error->one(FLERR, msg);
        }
        diRenzoWarned_ = true;
        error->warning(FLERR, msg);
    }

    static colloid::Vec3 stored(const double *hist, int at, double toSI)
    {
        return {{hist[at]*toSI, hist[at + 1]*toSI, hist[at + 2]*toSI}};
    }

    static void store(double *hist, int at, const colloid::Vec3 & v, double toSI)
    {
        for (int k = 0; k < 3; k++) hist[at + k] = v[k]/toSI;
    }

    const bool isWall_;
    FixWallGran *const wall_;   // the wall fix of a wall model, else NULL
    bool diRenzoWall_;
    bool timeStepCheck_;
    bool diRenzoWarned_;
    int nTypes_;
    int offset_;
    std::vector<colloid::WaltonBraunTangential> waltonBraun_;  // per type pair
    std::vector<colloid::DiRenzoDiMaio> diRenzo_;              // per type pair, walls
};

}
}

#endif // TANGENTIAL_MODEL_WALTON_BRAUN_H_
#endif
