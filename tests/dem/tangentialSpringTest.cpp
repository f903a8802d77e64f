/*---------------------------------------------------------------------------*\
    colloidFoam DEM test (labels dem, stiff): the tangential contact
    spring itself, for Walton-Braun incremental slip and for Di Renzo-Di
    Maio, at a wall.

    A sphere (R = 0.5 um, 2500 kg/m^3) rests on a primitive wall, pressed
    by a constant force F (fix addforce) to the overlap d0 = F/K1 of its
    Walton-Braun normal spring, and is given a small tangential velocity
    v0 without spin. With a linear tangential spring k at the contact
    point, a lever arm r (LIGGGHTS puts the contact point of a wall at
    r = R - d0/2, halfway into the overlap) and I = 2/5 m R^2,
    xi = x - r theta obeys
        xi'' = -(1/m + r^2/I) k xi = -(1 + 5/2 (r/R)^2) k/m xi = -w^2 xi,
    (m_t = m/(1 + 5/2 (r/R)^2), about 2/7 m: the contact point moves with
    the rotation too), so xi = v0/w sin(w t) and the centre moves at
        v_x(t) = v0 - a v0 (1 - cos(w t)),  a = k/(m w^2).
    The force amplitude k v0/w is below 1e-3 of the Coulomb limit mu F,
    where the Walton-Braun stiffness (falling to 0 at the limit as the
    cube root of the remaining load) is within 3e-4 of its initial value
    K_T0; Di Renzo-Di Maio's is
        k = (2/3) 8 G* sqrt(R d0),  G* = 1/((2 - nu1)/G1 + (2 - nu2)/G2),
    G = E/(2 (1 + nu)). The period of v_x (mean crossings over 5 periods,
    1000 steps each) must be 2 pi/w within 0.1 %, and its amplitude a v0
    within 0.1 %; a shear modulus 4 times too large or a slip increment
    counted twice changes the period by a factor 1/2 or 1/sqrt(2).
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <vector>

using namespace demTest;

namespace
{

const double pi = std::acos(-1.0);
const double R = 0.5;           // um
const double rho = 2.5;         // pg/um^3
const double K1 = 1000;         // nN/um = 1 N/m
const double F = 5;             // nN, overlap F/K1 = 5 nm
const double mu = 0.3;
const double v0 = 1e-4;         // um/us = m/s

// period and amplitude of v_x [us, um/us] for the tangential spring k
// [nN/um] that the wall's line sets up
void oscillate(const std::string& wallOptions, const std::string& properties, double k)
{
    const double m = rho*4.0/3.0*pi*R*R*R;
    const double r = R - 0.5*F/K1;
    const double w = std::sqrt((1 + 2.5*(r/R)*(r/R))*k/m);
    const double a = k/(m*w*w);
    const double period = 2*pi/w;
    const double dt = period/1000;
    std::cout << "k " << k << " nN/um, force amplitude " << k*v0/w/(mu*F)
              << " of the Coulomb limit, expected period " << period << " us" << std::endl;

    LiggghtsRun run;
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(3)
       << "fix m1 all property/global loadingStiffness peratomtypepair 2 "
       << K1 << ' ' << K1 << ' ' << K1 << ' ' << K1 << "\n"
          "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
          "fix m3 all property/global coefficientFriction peratomtypepair 2 "
       << mu << ' ' << mu << ' ' << mu << ' ' << mu << "\n"
       << properties
       << "neighbor 0.1 bin\n"
          "neigh_modify delay 0\n"
          "pair_style gran model walton_braun tangential walton_braun\n"
          "pair_coeff * *\n"
          "timestep " << dt << "\n"
          "fix wall all wall/gran model walton_braun tangential walton_braun "
          "primitive type 2 zplane 0 " << wallOptions << "\n"
          "fix push all addforce 0 0 " << -F << "\n"
          "fix integrate all nve/sphere\n"
          "create_atoms 1 single 0 0 " << R - F/K1 << " units box\n"
          "set atom 1 diameter " << 2*R << " density " << rho << "\n"
          "velocity all set " << v0 << " 0 0 units box\n"
          "run 0\n";
    run.commands(in.str());

    // v_x sampled every step over 5 periods
    std::vector<double> v;
    for (int n = 0; n < 5000; n++)
    {
        run.commands("run 1 pre no post no\n");
        v.push_back(run.v(1)[0]);
    }
    const double mean = (1 - a)*v0;
    std::vector<double> up;     // upward crossings of the mean [us]
    for (std::size_t n = 1; n < v.size(); n++)
        if (v[n - 1] < mean && v[n] >= mean)
            up.push_back(dt*(n - 1 + (mean - v[n - 1])/(v[n] - v[n - 1])));
    ASSERT_GE(up.size(), 3u) << "v_x did not oscillate about (1 - a) v0";
    const double measured = (up.back() - up.front())/(up.size() - 1);
    const double amplitude = 0.5*(*std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end()));
    std::cout << "period " << measured << " us (" << measured/period - 1 << " relative), amplitude "
              << amplitude/v0 << " v0 (a = " << a << ")" << std::endl;
    EXPECT_NEAR(measured, period, 0.001*period);
    EXPECT_NEAR(amplitude, a*v0, 0.001*a*v0);
}

} // namespace


TEST(tangentialSpring, tangentialSpringWaltonBraun)
{
    const double KT0 = 200;     // nN/um
    std::ostringstream p;
    p << "fix m4 all property/global tangentialStiffness peratomtypepair 2 "
      << KT0 << ' ' << KT0 << ' ' << KT0 << ' ' << KT0 << "\n";
    oscillate("", p.str(), KT0);
}


TEST(tangentialSpring, tangentialSpringDiRenzoDiMaio)
{
    const double E = 1e4, nu = 0.3;     // nN/um^2 = 1e3 Pa (1e7 Pa)
    const double G = E/(2*(1 + nu));
    const double Gstar = 1/(2*(2 - nu)/G);
    const double k = 2.0/3.0*8*Gstar*std::sqrt(R*F/K1);
    std::ostringstream p;
    p << "fix m4 all property/global tangentialStiffness peratomtypepair 2 200 200 200 200\n"
         "fix m5 all property/global youngsModulus peratomtype " << E << ' ' << E << "\n"
         "fix m6 all property/global poissonsRatio peratomtype " << nu << ' ' << nu << "\n";
    oscillate("diRenzoDiMaio on", p.str(), k);
}
