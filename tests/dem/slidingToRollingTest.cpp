/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: a sphere launched without spin along a flat
    primitive wall under gravity, with the plugin's tangential models:
    "tangential walton_braun" (incremental slip) and, at the wall,
    "diRenzoDiMaio on" (Di Renzo & Di Maio).

    Reference (rigid-body mechanics of a solid sphere, I = 2/5 m R^2): while
    it slides, Coulomb friction mu m g decelerates it, v = v0 - mu g t, and
    spins it up, until the contact point stops slipping at
    ts = 2/7 v0/(mu g); then it rolls at v = 5/7 v0 (angular momentum about
    the contact point is conserved). Checked within 1 %: the speed at ts/2,
    and the mean speed over the last quarter of a run of 2 ts.
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <sstream>

using namespace demTest;

namespace
{

void slideThenRoll(const std::string& wallSettings)
{
    const double R = 0.5;           // um
    const double rho = 2.5;         // pg/um^3
    const double g = 9.81e-3;       // um/us^2 (1000 g, to keep the run short)
    const double mu = 0.3;
    const double K1 = 100;          // nN/um
    const double v0 = 0.2;          // um/us = m/s
    const double dt = 0.005;        // us; contact time sqrt(m/K1) = 0.11 us

    LiggghtsRun run;
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(5, "p p f")
       << "fix m1 all property/global loadingStiffness peratomtypepair 2 "
       << K1 << ' ' << K1 << ' ' << K1 << ' ' << K1 << "\n"
          "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
          "fix m3 all property/global coefficientFriction peratomtypepair 2 "
       << mu << ' ' << mu << ' ' << mu << ' ' << mu << "\n"
          "fix m4 all property/global tangentialStiffness peratomtypepair 2 80 80 80 80\n"
          "fix m5 all property/global youngsModulus peratomtype 2e4 2e4\n"
          "fix m6 all property/global poissonsRatio peratomtype 0.3 0.3\n"
          "neighbor 0.1 bin\n"
          "neigh_modify delay 0\n"
          "pair_style gran model walton_braun tangential walton_braun\n"
          "pair_coeff * *\n"
          "timestep " << dt << "\n"
          "fix wall all wall/gran model walton_braun tangential walton_braun "
          "primitive type 2 zplane 0.0 " << wallSettings << "\n"
          "fix integrate all nve/sphere\n"
          "fix gravi all gravity " << g << " vector 0 0 -1\n"
          "create_atoms 1 single 0 0 1 units box\n"
          "set atom 1 diameter " << 2*R << " density " << rho << "\n"
          "run 0\n";
    run.commands(in.str());

    // resting overlap m g/K1, launched along x without spin
    const double m = run.mass(1);
    std::ostringstream start;
    start.precision(17);
    start << "set atom 1 z " << R - m*g/K1 << " vx " << v0 << " vy 0 vz 0 omegax 0 omegay 0 omegaz 0\n";
    run.commands(start.str());

    const double ts = 2.0/7.0*v0/(mu*g);
    const int nHalf = static_cast<int>(std::lround(ts/2/dt));
    run.commands("run " + std::to_string(nHalf) + "\n");
    const double tHalf = nHalf*dt;
    const double vHalf = run.v(1)[0];
    const double vHalfRef = v0 - mu*g*tHalf;

    // on to 2 ts, averaging the last quarter (samples every 10 steps)
    const int nSamples = static_cast<int>(std::lround(ts/2/dt))/10;
    const int nRest = static_cast<int>(std::lround(2*ts/dt)) - nHalf - 10*nSamples;
    run.commands("run " + std::to_string(nRest) + " pre no post no\n");
    double vSum = 0;
    for (int n = 0; n < nSamples; n++)
    {
        run.commands("run 10 pre no post no\n");
        vSum += run.v(1)[0];
    }
    const double vRoll = vSum/nSamples;
    std::cout << wallSettings << ": v(ts/2) " << vHalf << " m/s (v0 - mu g t: " << vHalfRef
              << "), rolling " << vRoll << " m/s (5/7 v0: " << 5.0/7.0*v0 << ")" << std::endl;
    EXPECT_NEAR(vHalf, vHalfRef, 0.01*vHalfRef);
    EXPECT_NEAR(vRoll, 5.0/7.0*v0, 0.01*5.0/7.0*v0);
    // it rolls: contact point at rest, v = omega_y R
    EXPECT_NEAR(run.v(1)[0], R*run.omega(1)[1], 0.01*v0);
}

} // namespace


TEST(slidingToRolling, waltonBraunSlidingToRolling)
{
    slideThenRoll("diRenzoDiMaio off");
}


TEST(slidingToRolling, diRenzoDiMaioSlidingToRolling)
{
    slideThenRoll("diRenzoDiMaio on");
}
