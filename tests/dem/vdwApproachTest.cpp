/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: two equal spheres, initially at rest 20 nm apart,
    pulled together by van der Waals attraction (cohesion colloid/vdw)
    against Stokes drag on each sphere (LIGGGHTS "fix viscous",
    F = -gamma v, gamma = 6 pi mu R).

    Reference: the same motion solved in the test by RK4 with a step of
    1e-11 s, checked against half that step (1e-6). By symmetry v2 = -v1 = -v, gap h:
        m dv/dt = Fa(h) - gamma v,   dh/dt = -2 v,
        Fa(h) = A Rs (1/max(h, h0)^2 - 1/hc^2)/6 (Derjaguin, force-shifted at
        the outer cut-off hc), Rs = R/2.
    The time at which the gap reaches 1 nm agrees within 1 %.
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

struct Pair
{
    double A, Rs, h0, hc, m, gamma;

    double attraction(double h) const
    {
        if (h >= hc) return 0.0;
        const double he = std::max(h, h0);
        return A*Rs/6*(1/(he*he) - 1/(hc*hc));
    }

    // time [s] at which the gap falls to hEnd, RK4 with step dt [s]
    double timeToGap(double hStart, double hEnd, double dt) const
    {
        return approachTime(hStart, hEnd, dt, [this](double hh, double vv)
        {
            return (attraction(hh) - gamma*vv)/m;
        });
    }
};

} // namespace


TEST(vdwApproach, vdwApproachTime)
{
    const double R = 0.5;           // um
    const double rho = 2.5;         // pg/um^3
    const double hamaker = 1e-20;   // J
    const double hc = 0.1;          // um
    const double mu = 1.0;          // mPa s (water)
    const double pi = std::acos(-1.0);
    const double gamma = 6*pi*mu*R; // nN us/um = 1e-9 N s/m
    const double hStart = 0.02;     // um
    const double hEnd = 0.001;      // um
    const double dt = 0.0005;       // us; Stokes time m/gamma = 0.14 us, vdW spring
                                    // at h0 sqrt(m*/k) = 0.007 us (limit: 1/10)

    LiggghtsRun run;
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(5)
       << "fix m1 all property/global loadingStiffness peratomtypepair 2 100 100 100 100\n"
          "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
          "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
          "fix c1 all property/global hamakerConstant peratomtypepair 2 "
       << hamaker/fJ << ' ' << hamaker/fJ << ' ' << hamaker/fJ << ' ' << hamaker/fJ << "\n"
          "fix c2 all property/global vdwOuterCutoff scalar " << hc << "\n"
          "neighbor 0.1 bin\n"
          "neigh_modify delay 0\n"
          "pair_style gran model walton_braun tangential history cohesion colloid/vdw\n"
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

    const Pair pair{hamaker, R/2*um, 0.4e-9, hc*um, run.mass(1)*pg, gamma*nN*us/um};
    const double tRef = pair.timeToGap(hStart*um, hEnd*um, 1e-11);
    ASSERT_NEAR(pair.timeToGap(hStart*um, hEnd*um, 1e-11/2), tRef, 1e-6*tRef) << "RK4 not converged";

    // coarse steps far away, single steps for the last few nm
    auto gap = [&]() { return run.x(2)[0] - run.x(1)[0] - 2*R; };
    double t = 0, tHit = -1;
    double gOld = gap();
    while (tHit < 0 && t < 3*tRef/us)
    {
        const int n = gOld > 0.004 ? 200 : 1;
        run.commands("run " + std::to_string(n) + " pre no post no\n");
        t += n*dt;
        const double g = gap();
        if (g <= hEnd) tHit = t - n*dt*(hEnd - g)/(gOld - g);
        gOld = g;
    }
    ASSERT_GT(tHit, 0) << "the spheres did not reach a gap of " << hEnd << " um";
    std::cout << "time to a 1 nm gap: DEM " << tHit*us << " s, RK4 " << tRef
              << " s, relative difference " << (tHit*us - tRef)/tRef << std::endl;
    EXPECT_NEAR(tHit*us, tRef, 0.01*tRef) << "time to contact [s]";
}
