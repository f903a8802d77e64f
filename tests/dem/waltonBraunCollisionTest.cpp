/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: dry head-on collision of two equal spheres with the
    plugin's "model walton_braun" (no cohesion, no damping).

    Reference (Walton & Braun 1986): loading with K1 over a quarter period
    sqrt(mr/K1) pi/2, unloading with K2 = K1/e^2 over sqrt(mr/K2) pi/2, so
      restitution   e_out = sqrt(K1/K2) = e,
      duration      tc = pi/2 (sqrt(mr/K1) + sqrt(mr/K2))
    of the contact force (it falls to zero at the overlap
    delta0 = delta_max (1 - e^2), before the surfaces part),
    mr = m1 m2/(m1 + m2) the reduced mass. Both within 1 %.
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <sstream>

using namespace demTest;

TEST(waltonBraunCollision, waltonBraunRestitution)
{
    const double K1 = 100;          // nN/um = 0.1 N/m
    const double e = 0.5;
    const double K2 = K1/(e*e);
    const double R = 0.5;           // um
    const double rho = 2.5;         // pg/um^3
    const double v0 = 0.05;         // um/us = m/s, each particle
    const double dt = 2e-5;         // us

    LiggghtsRun run;
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(5)
       << "fix m1 all property/global loadingStiffness peratomtypepair 2 "
       << K1 << ' ' << K1 << ' ' << K1 << ' ' << K1 << "\n"
          "fix m2 all property/global coefficientRestitution peratomtypepair 2 "
       << e << ' ' << e << ' ' << e << ' ' << e << "\n"
          "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
          "neighbor 0.1 bin\n"
          "neigh_modify delay 0\n"
          "pair_style gran model walton_braun tangential history\n"
          "pair_coeff * *\n"
          "timestep " << dt << "\n"
          "fix integrate all nve/sphere\n"
          "create_atoms 1 single 0 0 0 units box\n"
          "create_atoms 1 single " << 2*R + 0.002 << " 0 0 units box\n"
          "set atom * diameter " << 2*R << " density " << rho << "\n"
          "velocity all set 0 0 0 units box\n"
          "set atom 1 vx " << v0 << "\n"
          "set atom 2 vx " << -v0 << "\n"
          "run 0\n";
    run.commands(in.str());

    const double m = run.mass(1);
    const double mStar = m/2;
    const double pi = std::acos(-1.0);
    const double tcRef = pi/2*(std::sqrt(mStar/K1) + std::sqrt(mStar/K2));

    // step through the collision: the force starts when the gap closes
    // (interpolated crossing) and ends at the first step without force,
    // found to within one step (dt/tc ~ 1e-4)
    auto gap = [&]() { return run.x(2)[0] - run.x(1)[0] - 2*R; };
    double t = 0, tIn = -1, tOut = -1;
    double gOld = gap();
    const int maxSteps = static_cast<int>(5*tcRef/dt) + 200;
    for (int n = 0; n < maxSteps && tOut < 0; n++)
    {
        run.commands("run 1 pre no post no\n");
        t += dt;
        const double g = gap();
        if (gOld > 0 && g <= 0) tIn = t - dt*g/(g - gOld);
        if (tIn > 0 && run.f(1)[0] == 0.0) tOut = t - dt/2;
        gOld = g;
    }
    ASSERT_GT(tIn, 0) << "no contact";
    ASSERT_GT(tOut, 0) << "no rebound";

    const double vRelOut = run.v(2)[0] - run.v(1)[0];
    const double eOut = vRelOut/(2*v0);
    std::cout << "restitution " << eOut << " (sqrt(K1/K2) = " << std::sqrt(K1/K2)
              << "), force duration " << tOut - tIn << " us (predicted " << tcRef
              << " us)" << std::endl;
    EXPECT_NEAR(eOut, std::sqrt(K1/K2), 0.01*e);
    EXPECT_NEAR(tOut - tIn, tcRef, 0.01*tcRef);
}
