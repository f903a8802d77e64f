/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: the double layer at the extremes of salt, forces
    read back after "run 0" against the closed form (surfaceForceReference.H,
    seed 002 eq 10, force-shifted at the outer cut-off), relative 1e-9,
    and the Debye length the plugin prints against
        1/kappa = sqrt(eps_r eps0 kT/(2 N_A e^2 z^2 c)),   relative 1e-4.

    extremeLowSaltForce: nearly salt-free water, c = 9.2e-5 mol/m^3
    (Debye length 1 um; c = 0 is refused, see badInputTest.cpp). Sphere
    R = 0.5 um above a charged mesh wall (zeta -30 and -50 mV). With the
    cut-off at 0.1 um (0.1 Debye lengths) the force-shift leaves only
    1 - exp(-(hc - h0)/lambda) = 9.5 % of the force: the plugin warns and
    says which cut-off would do; with the cut-off at 3.5 um it does not
    warn, and the force reaches microns (at 3 um 2 % of that at contact).

    extremeHighSaltForce: 1 M salt (Debye length 0.30 nm, shorter than the
    0.4 nm inner cut-off), two spheres R = 0.5 um, zeta -30 mV, cut-off
    5 nm: beyond 2 nm the double layer is below 1 % of its contact value.
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"
#include "surfaceForceReference.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace demTest;

namespace
{

const double R = 0.5e-6;        // m
const double rho = 2500;        // kg/m^3

std::string materials()
{
    return
        "fix m1 all property/global loadingStiffness peratomtypepair 2 100 100 100 100\n"
        "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
        "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
        "neighbor 0.2 bin\n"
        "neigh_modify delay 0\n";
}

std::string doubleLayer(const SurfaceForceReference& f)
{
    std::ostringstream in;
    in.precision(17);
    in << "fix d1 all property/global zetaPotential peratomtype " << f.zeta1 << ' ' << f.zeta2 << "\n"
          "fix d2 all property/global saltConcentration scalar " << f.salt << "\n"
          "fix d3 all property/global doubleLayerOuterCutoff scalar " << f.hcd/um << "\n";
    return in.str();
}

std::string readLog(const std::string& name)
{
    std::ifstream in(name);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// the number after marker in text (first occurrence); NaN if none
double numberAfter(const std::string& text, const std::string& marker)
{
    const std::size_t at = text.find(marker);
    if (at == std::string::npos) return std::nan("");
    return std::strtod(text.c_str() + at + marker.size(), nullptr);
}

// sphere above a mesh wall z = 0: repulsive force [N] at each gap [m]
void wallForces(const SurfaceForceReference& f, const double* gaps, int n, const std::string& log)
{
    writeSquareStl("lowSaltWall.stl", 4, 0);
    LiggghtsRun run;
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(5) << materials() << doubleLayer(f)
       << "pair_style gran model walton_braun tangential history cohesion colloid/dl\n"
          "pair_coeff * *\n"
          "timestep 1e-4\n"
          "fix wallMesh all mesh/surface file lowSaltWall.stl type 2\n"
          "fix wall all wall/gran model walton_braun tangential history "
          "cohesion colloid/dl mesh n_meshes 1 meshes wallMesh\n"
          "create_atoms 1 single 0.3 -0.2 1 units box\n"
          "set atom 1 diameter " << 2*R/um << " density " << rho*um*um*um/pg << "\n"
          "run 0\n";
    run.commands(in.str());
    for (int i = 0; i < n; i++)
    {
        std::ostringstream s;
        s.precision(17);
        s << "set atom 1 z " << (R + gaps[i])/um << "\nrun 0\n";
        run.commands(s.str());
        const double F = f.force(gaps[i]);
        EXPECT_NEAR(run.f(1)[2]*nN, F, 1e-9*std::fabs(F) + 1e-30) << "gap " << gaps[i] << " m";
    }
    const std::string text = readLog(log);
    const double lambda = numberAfter(text, "Debye length ");
    EXPECT_NEAR(lambda, f.debyeLength(), 1e-4*f.debyeLength()) << text;
}

} // namespace


TEST(extremeSalt, extremeLowSaltForce)
{
    SurfaceForceReference f;
    f.zeta1 = -0.03;
    f.zeta2 = -0.05;
    f.salt = f.saltFor(1e-6);
    f.Rs = R;
    const double lambda = f.debyeLength();
    const std::string log = "extremeLowSaltForce.log";

    // cut-off 0.1 um: the shift takes most of the force, with a warning
    f.hcd = 0.1e-6;
    const double shortGaps[] = {0.1e-9, 1e-9, 10e-9, 50e-9, 99e-9, 0.12e-6};
    wallForces(f, shortGaps, 6, log);
    const double left = f.force(0)/(f.dlPrefactor()*std::exp(-f.h0d/lambda));
    std::cout << "c = " << f.salt << " mol/m^3, Debye length " << lambda
              << " m; cut-off 0.1 um keeps " << left << " of the force at contact" << std::endl;
    EXPECT_NEAR(left, 1 - std::exp(-(f.hcd - f.h0d)/lambda), 1e-9);
    std::string text = readLog(log);
    EXPECT_NE(text.find("WARNING: cohesion colloid/dl: doubleLayerOuterCutoff"), std::string::npos) << text;
    EXPECT_NEAR(numberAfter(text, "use a cut-off of "), (f.h0d + 3*lambda)/um, 1e-5) << text;

    // cut-off 3.5 um: no warning, the force reaches microns
    f.hcd = 3.5e-6;
    const double longGaps[] = {1e-9, 0.1e-6, 1e-6, 3e-6, 3.6e-6};
    wallForces(f, longGaps, 5, log);
    text = readLog(log);
    EXPECT_EQ(text.find("WARNING: cohesion colloid/dl"), std::string::npos) << text;
    std::cout << "cut-off 3.5 um: force at 3 um / at contact " << f.force(3e-6)/f.force(0) << std::endl;
}


TEST(extremeSalt, extremeHighSaltForce)
{
    SurfaceForceReference f;
    f.zeta1 = f.zeta2 = -0.03;
    f.salt = 1000;              // mol/m^3 = 1 M
    f.hcd = 5e-9;
    f.Rs = R/2;

    LiggghtsRun run;
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(5) << materials() << doubleLayer(f)
       << "pair_style gran model walton_braun tangential history cohesion colloid/dl\n"
          "pair_coeff * *\n"
          "timestep 1e-4\n"
          "create_atoms 1 single 0 0 0 units box\n"
          "create_atoms 1 single 1.01 0 0 units box\n"
          "set atom * diameter " << 2*R/um << " density " << rho*um*um*um/pg << "\n"
          "run 0\n";
    run.commands(in.str());
    const double F0 = f.force(0);
    for (double h : {0.1e-9, 0.3e-9, 0.4e-9, 0.6e-9, 1e-9, 2e-9, 4e-9, 6e-9})
    {
        std::ostringstream s;
        s.precision(17);
        s << "set atom 2 x " << (2*R + h)/um << "\nrun 0\n";
        run.commands(s.str());
        // repulsion pushes particle 1 (at the origin) towards -x
        const double F = -run.f(1)[0]*nN;
        EXPECT_NEAR(F, f.force(h), 1e-9*std::fabs(f.force(h)) + 1e-30) << "gap " << h << " m";
        if (h >= 2e-9) EXPECT_LT(std::fabs(F), 0.01*F0) << "gap " << h << " m";
        std::cout << "gap " << h << " m: force " << F << " N (" << F/F0 << " of contact)" << std::endl;
    }
    const double lambda = numberAfter(readLog("extremeHighSaltForce.log"), "Debye length ");
    EXPECT_NEAR(lambda, f.debyeLength(), 1e-4*f.debyeLength());
}
