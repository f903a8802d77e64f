/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: two equal spheres (R = 5 um), initially at rest
    10 nm apart, pulled together by van der Waals attraction against normal
    lubrication (cohesion colloid/vdw/lub, in the plugin's implicit update)
    and Stokes drag on each sphere (LIGGGHTS' fix viscous, explicit). The
    DEM step is several times the relaxation time mr/c (mr = m/2) of the
    lubrication resistance at the end gap, so an explicit lubrication force
    would be unstable there. The drag of fix viscous stays outside the
    implicit update; its splitting error is first order in dt/tau (tau =
    m/gamma, the Stokes time), so dt = tau/200 here (the coupling's drag is
    inside it: stiffTest.cpp, approachAtStokesTime).

    Reference: the same motion solved in the test by RK4 with a step of
    2e-10 s, checked against half that step (1e-6). By symmetry v2 = -v1 = -v, gap h:
        m dv/dt = Fa(h) - gamma v - 2 c(h) v,   dh/dt = -2 v,
        Fa(h) = A Rs (1/max(h, h0)^2 - 1/hc^2)/6,
        c(h)  = 6 pi mu Rs^2 (1/max(h, hin) - 1/hout)   (h < hout),
    Rs = R/2, gamma = 6 pi mu R. The time at which the gap reaches 2 nm
    agrees within 1 %.

    lubricationFadedApproachTime: the same with the faded forms
    (lubricationFade 1, vdwFade 1) and both outer cut-offs 15 nm, so that
    the approach starts in the fade (7.5 to 15 nm) and ends in the uncut
    near field:
        c(h) = 6 pi mu Rs^2/max(h, hin) w,  Fa(h) = A Rs/(6 max(h, h0)^2) w,
        w = 1 for h <= hc/2, else w = 3y^2 - 2y^3, y = (hc - h)/(hc/2).
    The shifted form at this cut-off reaches 2 nm 43 % sooner, a fade
    starting at 0.4 hout 7 % sooner, a linear fade 6 % sooner, a near
    field 2 % stronger 1.1 % later: each fails the test.
\*---------------------------------------------------------------------------*/
#include "approachTime.H"
#include "liggghtsRun.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

using namespace demTest;

namespace
{

struct LubricatedPair
{
    double A, Rs, h0, hc, mu, hin, hout, m, gamma;
    bool fade;

    double attraction(double h) const
    {
        if (h >= hc) return 0.0;
        const double he = std::max(h, h0);
        if (!fade) return A*Rs/6*(1/(he*he) - 1/(hc*hc));
        const double y = std::min(1.0, (hc - he)/(0.5*hc));
        return A*Rs/6/(he*he)*(3*y*y - 2*y*y*y);
    }

    double resistance(double h) const
    {
        if (h >= hout) return 0.0;
        const double pi = std::acos(-1.0);
        const double he = std::max(h, hin);
        if (!fade) return 6*pi*mu*Rs*Rs*(1/he - 1/hout);
        const double y = std::min(1.0, (hout - he)/(0.5*hout));
        return 6*pi*mu*Rs*Rs/he*(3*y*y - 2*y*y*y);
    }

    // time [s] at which the gap falls to hEnd, RK4 with step dt [s]
    double timeToGap(double hStart, double hEnd, double dt) const
    {
        return approachTime(hStart, hEnd, dt, [this](double hh, double vv)
        {
            return (attraction(hh) - gamma*vv - 2*resistance(hh)*vv)/m;
        });
    }
};

} // namespace


namespace
{

// Runs the approach with the outer cut-offs hout [um] of the lubrication
// and hc [um] of the van der Waals attraction, both in the form chosen;
// returns the DEM's and the reference time to 2 nm [s]
void approach(double hout, double hc, bool fade, double & tDem, double & tRef)
{
    const double R = 5;             // um
    const double rho = 2.5;         // pg/um^3
    const double hamaker = 1e-20;   // J
    const double mu = 1.0;          // mPa s (water)
    const double hin = 0.001;       // um, lubrication inner cut-off
    const double pi = std::acos(-1.0);
    const double gamma = 6*pi*mu*R; // nN us/um = 1e-9 N s/m
    const double hStart = 0.01;     // um
    const double hEnd = 0.002;      // um
    const double dt = 0.07;         // us, Stokes time m/gamma = 13.9 us

    LiggghtsRun run;
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(20)
       << "fix m1 all property/global loadingStiffness peratomtypepair 2 100 100 100 100\n"
          "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
          "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
          "fix c1 all property/global hamakerConstant peratomtypepair 2 "
       << hamaker/fJ << ' ' << hamaker/fJ << ' ' << hamaker/fJ << ' ' << hamaker/fJ << "\n"
          "fix c2 all property/global vdwOuterCutoff scalar " << hc << "\n"
          "fix c3 all property/global vdwFade scalar " << (fade ? 1 : 0) << "\n"
          "fix l1 all property/global liquidViscosity scalar " << mu << "\n"
          "fix l2 all property/global lubricationInnerCutoff scalar " << hin << "\n"
          "fix l3 all property/global lubricationOuterCutoff scalar " << hout << "\n"
          "fix l4 all property/global lubricationFade scalar " << (fade ? 1 : 0) << "\n"
          "neighbor 0.1 bin\n"
          "neigh_modify delay 0\n"
          "pair_style gran model walton_braun tangential history cohesion colloid/vdw/lub\n"
          "pair_coeff * *\n"
          "timestep " << dt << "\n"
          "fix integrate all nve/sphere\n"
          "fix drag all viscous " << gamma << "\n"
          "create_atoms 1 single 0 0 0 units box\n"
          "create_atoms 1 single " << 2*R + hStart << " 0 0 units box\n"
          "set atom * diameter " << 2*R << " density " << rho << "\n"
          "velocity all set 0 0 0 units box\n"
          "run 0\n";
    run.commands(in.str());

    const LubricatedPair pair{hamaker, R/2*um, 0.4e-9, hc*um, mu*1e-3, hin*um, hout*um,
                              run.mass(1)*pg, gamma*nN*us/um, fade};
    tRef = pair.timeToGap(hStart*um, hEnd*um, 2e-10);
    ASSERT_NEAR(pair.timeToGap(hStart*um, hEnd*um, 2e-10/2), tRef, 1e-6*tRef) << "RK4 not converged";
    // stiffness of the lubrication at the end gap: c dt/m* (m* = m/2)
    const double stiffness = pair.resistance(hEnd*um)*dt*us/(pair.m/2);

    auto gap = [&]() { return run.x(2)[0] - run.x(1)[0] - 2*R; };
    double t = 0, tHit = -1;
    double gOld = gap();
    while (tHit < 0 && t < 3*tRef/us)
    {
        const int n = gOld > 0.003 ? 50 : 1;
        run.commands("run " + std::to_string(n) + " pre no post no\n");
        t += n*dt;
        const double g = gap();
        if (g <= hEnd) tHit = t - n*dt*(hEnd - g)/(gOld - g);
        gOld = g;
    }
    std::cout << "c dt/m* at the end gap " << stiffness << "; time to a 2 nm gap: DEM "
              << tHit*us << " s, RK4 " << tRef << " s, relative difference "
              << (tHit*us - tRef)/tRef << std::endl;
    ASSERT_GT(stiffness, 1.0) << "the test should exercise the implicit regime";
    ASSERT_GT(tHit, 0) << "the spheres did not reach a gap of " << hEnd << " um";
    tDem = tHit*us;
}

} // namespace


TEST(lubricationApproach, lubricationApproachTime)
{
    double tDem = 0, tRef = 0;
    approach(0.1, 0.1, false, tDem, tRef);
    EXPECT_NEAR(tDem, tRef, 0.01*tRef) << "time to a 2 nm gap [s]";
}


TEST(lubricationApproach, lubricationFadedApproachTime)
{
    double tDem = 0, tRef = 0;
    approach(0.015, 0.015, true, tDem, tRef);
    EXPECT_NEAR(tDem, tRef, 0.01*tRef) << "time to a 2 nm gap [s], faded form";
}
