/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: the van der Waals force that LIGGGHTS applies
    through the plugin (cohesion colloid/vdw, Derjaguin form) against the
    closed form, force-shifted at the outer cut-off hc and held at its h0
    value below the inner cut-off:
        |F| = A Rs (1/max(h, h0)^2 - 1/hc^2)/6,  0 beyond hc,
    Rs = R1 R2/(R1 + R2) for two spheres of unequal radii, Rs = R for a
    sphere at a wall (mesh wall and primitive wall). Read back after "run 0".
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace demTest;

namespace
{

const double hamaker = 1e-20;     // J
const double h0 = 0.4e-9;         // m (plugin default inner cut-off)
const double hc = 0.1e-6;         // m (vdwOuterCutoff 0.1 um)

// closed form [N], magnitude of the attraction
double reference(double Rstar, double h)
{
    if (h >= hc) return 0.0;
    const double he = std::max(h, h0);
    return hamaker*Rstar/6*(1/(he*he) - 1/(hc*hc));
}

std::string materials(const std::string& extra = "")
{
    std::ostringstream s;
    s << "fix m1 all property/global loadingStiffness peratomtypepair 2 100 100 100 100\n"
         "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
         "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
         "fix c1 all property/global hamakerConstant peratomtypepair 2 "
      << hamaker/fJ << ' ' << hamaker/fJ << ' ' << hamaker/fJ << ' ' << hamaker/fJ << "\n"
         "fix c2 all property/global vdwOuterCutoff scalar " << hc/um << "\n"
         "neighbor 0.2 bin\n"
         "neigh_modify delay 0\n"
         "pair_style gran model walton_braun tangential history cohesion colloid/vdw\n"
         "pair_coeff * *\n"
         "timestep 1e-5\n"
      << extra;
    return s.str();
}

// gaps [m] covering: below h0, near contact, mid range, near and beyond hc
const double gaps[] = {0.2e-9, 1e-9, 5e-9, 30e-9, 0.09e-6, 0.15e-6};

} // namespace


TEST(vdwForce, vdwPairForce)
{
    LiggghtsRun run;
    const double R1 = 0.5, R2 = 0.3;   // um
    run.commands(LiggghtsRun::header(5) + materials());
    run.commands
    (
        "create_atoms 1 single 0 0 0 units box\n"
        "create_atoms 1 single 1 0 0 units box\n"
        "set atom 1 diameter 1.0 density 2.5\n"
        "set atom 2 diameter 0.6 density 2.5\n"
    );
    const double Rstar = R1*R2/(R1 + R2)*um;
    for (double h : gaps)
    {
        std::ostringstream move;
        move.precision(17);
        move << "set atom 2 x " << R1 + R2 + h/um << "\nrun 0\n";
        run.commands(move.str());
        const double F = reference(Rstar, h);
        // particle 1 pulled towards 2 (+x), 2 towards 1
        EXPECT_NEAR(run.f(1)[0]*nN, F, 1e-9*F + 1e-30) << "gap " << h;
        EXPECT_NEAR(run.f(2)[0]*nN, -F, 1e-9*F + 1e-30) << "gap " << h;
        EXPECT_EQ(run.f(1)[1], 0.0);
        EXPECT_EQ(run.f(1)[2], 0.0);
    }
}


namespace
{

void sphereWall(const std::string& wallLines)
{
    LiggghtsRun run;
    const double R = 0.5;   // um
    run.commands(LiggghtsRun::header(5) + materials(wallLines));
    run.commands
    (
        "create_atoms 1 single 0.1 0.2 1 units box\n"
        "set atom 1 diameter 1.0 density 2.5\n"
    );
    for (double h : gaps)
    {
        std::ostringstream move;
        move.precision(17);
        move << "set atom 1 z " << R + h/um << "\nrun 0\n";
        run.commands(move.str());
        const double F = reference(R*um, h);
        // pulled towards the wall at z = 0
        EXPECT_NEAR(run.f(1)[2]*nN, -F, 1e-9*F + 1e-30) << "gap " << h;
        EXPECT_EQ(run.f(1)[0], 0.0);
        EXPECT_EQ(run.f(1)[1], 0.0);
    }
}

} // namespace


TEST(vdwForce, vdwSphereMeshWallForce)
{
    writeSquareStl("vdwWall.stl", 4, 0);
    sphereWall
    (
        "fix wallMesh all mesh/surface file vdwWall.stl type 2\n"
        "fix wall all wall/gran model walton_braun tangential history "
        "cohesion colloid/vdw mesh n_meshes 1 meshes wallMesh\n"
    );
}


TEST(vdwForce, vdwSpherePrimitiveWallForce)
{
    sphereWall
    (
        "fix wall all wall/gran model walton_braun tangential history "
        "cohesion colloid/vdw primitive type 2 zplane 0.0\n"
    );
}
