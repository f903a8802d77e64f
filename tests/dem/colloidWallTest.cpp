/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: particle-wall terms of the colloid cohesion model
    read back after "run 0", sphere (R = 0.5 um) above a mesh wall z = 0.

    Lubrication (cohesion colloid/lub), sphere moving towards the wall at
    speed u, against the sphere-plane resistance with Rs = R (not R/4):
        F = c u,  c = 6 pi mu R^2 (1/max(h, hin) - 1/hout)
    (no integrator: the implicit update keeps the sphere's velocity and
    gives it the film's force at that velocity; the update of a moving
    sphere is tested in stiffTest.cpp).
    Double layer (cohesion colloid/dl, seed 002 eq 10 with Rs = R and two
    zeta potentials):
        F = 128 pi R n kT G1 G2/kappa (exp(-kappa h) - exp(-kappa hc)),
    and zero when the wall is declared grounded (groundedWall on).
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace demTest;

namespace
{

const double pi = std::acos(-1.0);
const double R = 0.5;           // um
const double rho = 2.5;         // pg/um^3

std::string contactMaterials()
{
    return
        "fix m1 all property/global loadingStiffness peratomtypepair 2 100 100 100 100\n"
        "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
        "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
        "neighbor 0.2 bin\n"
        "neigh_modify delay 0\n";
}

// sphere at gap h [um] above the wall, velocity vz [um/us], after run 0
void place(LiggghtsRun& run, double h, double vz)
{
    std::ostringstream s;
    s.precision(17);
    s << "set atom 1 z " << R + h << " vz " << vz << "\nrun 0\n";
    run.commands(s.str());
}

} // namespace


TEST(colloidWall, lubricationWallForce)
{
    const double mu = 1.0;          // mPa s
    const double hin = 0.001;       // um
    const double hout = 0.1;        // um
    const double dt = 1e-3;         // us
    const double u = 0.01;          // um/us = m/s, towards the wall

    writeSquareStl("lubricationWall.stl", 4, 0);
    LiggghtsRun run;
    std::ostringstream in;
    in << LiggghtsRun::header(5) << contactMaterials()
       << "fix l1 all property/global liquidViscosity scalar " << mu << "\n"
          "fix l2 all property/global lubricationInnerCutoff scalar " << hin << "\n"
          "fix l3 all property/global lubricationOuterCutoff scalar " << hout << "\n"
          "pair_style gran model walton_braun tangential history cohesion colloid/lub\n"
          "pair_coeff * *\n"
          "timestep " << dt << "\n"
          "fix wallMesh all mesh/surface file lubricationWall.stl type 2\n"
          "fix wall all wall/gran model walton_braun tangential history "
          "cohesion colloid/lub mesh n_meshes 1 meshes wallMesh\n"
          "create_atoms 1 single 0.3 -0.2 1 units box\n"
          "set atom 1 diameter " << 2*R << " density " << rho << "\n";
    run.commands(in.str());

    for (double h : {0.0005, 0.002, 0.01, 0.05, 0.09, 0.12})  // um
    {
        place(run, h, -u);
        double F = 0;
        if (h < hout)
        {
            const double c = 6*pi*mu*1e-3*(R*um)*(R*um)*(1/(std::max(h, hin)*um) - 1/(hout*um));
            F = c*u;
        }
        EXPECT_NEAR(run.f(1)[2]*nN, F, 1e-9*F + 1e-30) << "gap " << h << " um";
    }
}


namespace
{

// double-layer force on the sphere at gap h [um], wall grounded or not
void doubleLayerWall(bool grounded)
{
    const double zetaP = -0.03, zetaW = -0.05;  // V
    const double salt = 1.0;                    // mol/m^3
    const double T = 298.15, epsR = 78.4;
    const double hc = 0.05;                     // um

    writeSquareStl("doubleLayerWall.stl", 4, 0);
    LiggghtsRun run;
    std::ostringstream in;
    in << LiggghtsRun::header(5) << contactMaterials()
       << "fix c1 all property/global zetaPotential peratomtype " << zetaP << ' ' << zetaW << "\n"
          "fix c2 all property/global saltConcentration scalar " << salt << "\n"
          "fix c3 all property/global saltValence scalar 1\n"
          "fix c4 all property/global liquidTemperature scalar " << T << "\n"
          "fix c5 all property/global relativePermittivity scalar " << epsR << "\n"
          "fix c6 all property/global doubleLayerOuterCutoff scalar " << hc << "\n"
          "pair_style gran model walton_braun tangential history cohesion colloid/dl\n"
          "pair_coeff * *\n"
          "timestep 1e-4\n"
          "fix wallMesh all mesh/surface file doubleLayerWall.stl type 2\n"
          "fix wall all wall/gran model walton_braun tangential history "
          "cohesion colloid/dl mesh n_meshes 1 meshes wallMesh groundedWall "
       << (grounded ? "on" : "off") << "\n"
          "create_atoms 1 single 0.3 -0.2 1 units box\n"
          "set atom 1 diameter " << 2*R << " density " << rho << "\n";
    run.commands(in.str());

    const double kB = 1.380649e-23, e = 1.602176634e-19;
    const double NA = 6.02214076e23, eps0 = 8.8541878128e-12;
    const double kT = kB*T;
    const double kappa = 1/std::sqrt(epsR*eps0*kT/(2*NA*e*e*salt));
    const double G1 = std::tanh(e*zetaP/(4*kT)), G2 = std::tanh(e*zetaW/(4*kT));
    for (double h : {0.001, 0.005, 0.02, 0.06})  // um
    {
        place(run, h, 0);
        double F = 0;
        if (!grounded && h < hc)
        {
            F = 128*pi*R*um*NA*salt*kT*G1*G2/kappa
               *(std::exp(-kappa*h*um) - std::exp(-kappa*hc*um));
        }
        EXPECT_NEAR(run.f(1)[2]*nN, F, 1e-9*std::fabs(F) + 1e-30) << "gap " << h << " um";
    }
}

} // namespace


TEST(colloidWall, doubleLayerChargedWall)
{
    doubleLayerWall(false);
}


TEST(colloidWall, doubleLayerGroundedWall)
{
    doubleLayerWall(true);
}
