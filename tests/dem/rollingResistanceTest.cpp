/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: LIGGGHTS' rolling resistance "rolling_friction
    epsd2" together with the plugin's van der Waals cohesion (the
    combination the filtration case selects with rollingFriction > 0).

    A sphere (R = 0.5 um) rests on a primitive wall, pulled down by gravity
    m g and by van der Waals attraction Fv equal to it; a horizontal force
    Fx acts at its centre. The contact carries both, Fc = m g + Fv (the
    plugin adds its surface forces beside the contact force, so the
    contact's friction and rolling limits see the load that adhesion puts
    on it). epsd2 resists rolling with a torque of at most mu_r R Fc.

    Reference (rigid-body mechanics of a solid sphere, I = 2/5 m R^2,
    friction large enough that the contact point does not slip):
      - Fx < mu_r Fc: the sphere stays where it is. Fx = 0.75 mu_r Fc is
        chosen above mu_r m g: without the adhesion's share of the contact
        load it would roll.
      - Fx > mu_r Fc: it rolls with a = (Fx - mu_r Fc)/(7/5 m). Fx = 2 mu_r
        Fc; the acceleration is measured between two velocities, 1 %.
    Fv from the closed form of surfaceForceReference.H at the inner
    cut-off (the kernel holds that value in contact).
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"
#include "surfaceForceReference.H"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <sstream>

using namespace demTest;

namespace
{

const double R = 0.5;           // um
const double rho = 2.5;         // pg/um^3
const double muR = 0.1;         // rolling resistance coefficient
const double muS = 0.5;         // Coulomb (sliding) friction
const double dt = 5e-4;         // us; Hertz contact time about 0.03 us

struct RollingRun
{
    LiggghtsRun run;
    double m = 0;               // pg
    double Fc = 0;              // contact load m g + Fv [nN]

    RollingRun()
    {
        SurfaceForceReference ref;
        ref.A = 1e-20;          // J
        ref.hcv = 0.1e-6;       // m (vdwOuterCutoff)
        ref.Rs = R*um;
        const double Fv = ref.vdwAttraction(-1e-9)/nN;   // in contact
        const double pi = std::acos(-1.0);
        m = rho*4.0/3.0*pi*R*R*R;
        const double g = Fv/m;  // um/us^2: m g = Fv
        Fc = m*g + Fv;

        std::ostringstream in;
        in.precision(17);
        in << LiggghtsRun::header(5, "p p f")
           << "fix m1 all property/global youngsModulus peratomtype 6.3e5 6.3e5\n"
              "fix m2 all property/global poissonsRatio peratomtype 0.2 0.2\n"
              "fix m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
              "fix m4 all property/global coefficientFriction peratomtypepair 2 "
           << muS << ' ' << muS << ' ' << muS << ' ' << muS << "\n"
              "fix m5 all property/global coefficientRollingFriction peratomtypepair 2 "
           << muR << ' ' << muR << ' ' << muR << ' ' << muR << "\n"
              "fix c1 all property/global hamakerConstant peratomtypepair 2 "
           << ref.A/fJ << ' ' << ref.A/fJ << ' ' << ref.A/fJ << ' ' << ref.A/fJ << "\n"
              "fix c2 all property/global vdwOuterCutoff scalar " << ref.hcv/um << "\n"
              "neighbor 0.2 bin\n"
              "neigh_modify delay 0\n"
              "pair_style gran model hertz tangential history cohesion colloid/vdw "
              "rolling_friction epsd2\n"
              "pair_coeff * *\n"
              "timestep " << dt << "\n"
              "fix wall all wall/gran model hertz tangential history cohesion colloid/vdw "
              "rolling_friction epsd2 primitive type 2 zplane 0.0\n"
              "fix integrate all nve/sphere\n"
              "fix gravi all gravity " << g << " vector 0 0 -1\n"
              "create_atoms 1 single 0 0 " << R << " units box\n"
              "set atom 1 diameter " << 2*R << " density " << rho << "\n"
              // settle onto the wall (normal damping, about 30 contact times)
              "run 2000\n";
        run.commands(in.str());
        EXPECT_NEAR(run.mass(1), m, 1e-9*m);
    }

    void push(double Fx)
    {
        std::ostringstream s;
        s.precision(17);
        s << "fix push all addforce " << Fx << " 0 0\n";
        run.commands(s.str());
    }
};

} // namespace


TEST(rollingResistance, rollingResistanceHoldsAdheredSphere)
{
    RollingRun r;
    const double Fx = 0.75*muR*r.Fc;
    const double x0 = r.run.x(1)[0];
    r.push(Fx);
    const int n = 6000;
    r.run.commands("run " + std::to_string(n) + "\n");
    const double T = n*dt;
    // what it would roll without rolling resistance, and what the
    // adhesion-free limit mu_r m g would let it roll
    const double free = 0.5*Fx/(1.4*r.m)*T*T;
    const double noAdhesion = 0.5*(Fx - muR*0.5*r.Fc)/(1.4*r.m)*T*T;
    const double moved = std::abs(r.run.x(1)[0] - x0);
    std::cout << "moved " << moved << " um in " << T << " us (free rolling " << free
              << ", rolling limit without adhesion " << noAdhesion << ")" << std::endl;
    EXPECT_LT(moved, 1e-2*noAdhesion);
    EXPECT_LT(std::abs(r.run.v(1)[0]), 1e-3*Fx/(1.4*r.m)*T);
}


TEST(rollingResistance, rollingResistanceSlowsRollingSphere)
{
    RollingRun r;
    const double Fx = 2*muR*r.Fc;
    r.push(Fx);
    const int n1 = 1000, n2 = 4000;
    r.run.commands("run " + std::to_string(n1) + "\n");
    const double v1 = r.run.v(1)[0];
    r.run.commands("run " + std::to_string(n2) + "\n");
    const double v2 = r.run.v(1)[0];
    const double a = (v2 - v1)/(n2*dt);
    const double aRef = (Fx - muR*r.Fc)/(1.4*r.m);
    std::cout << "acceleration " << a << " um/us^2, (Fx - mu_r Fc)/(7/5 m) " << aRef
              << std::endl;
    EXPECT_NEAR(a, aRef, 0.01*aRef);
    // rolling: contact point at rest
    EXPECT_NEAR(v2, R*r.run.omega(1)[1], 0.01*v2);
}
