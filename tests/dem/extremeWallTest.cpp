/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: a sphere (R = 0.5 um, 2500 kg/m^3) shot at a mesh
    wall z = 0 at 1 m/s, run stably at a step within the printed limits.

    extremeWallImpact: dry, oblique (normal 0.8 m/s, tangential 0.6 m/s),
    Walton-Braun normal (K1 = 1 N/m, e = 0.5) with Di Renzo-Di Maio
    tangential at the wall (seed 000; E = 1e8 Pa, nu = 0.3, mu = 0.3).
    References (m* = m against a wall):
        largest overlap  d = vn sqrt(m/K1)            (loading line K1)
        rebound          vn' = e vn                    (unloading K2 = K1/e^2)
    both within 1 %; the centre never reaches the wall plane (overlap
    below a quarter of the radius); the tangential impulse is within the
    Coulomb bound mu x the normal impulse; the kinetic energy
    (translation and rotation) after the impact is at most the initial.

    extremeWallImpactLubricated: the same sphere in water (1 mPa s),
    normal impact, lubrication only (inner cut-off 1 nm, outer 0.1 um),
    starting 0.2 um from the wall. With the sphere-plane resistance
    c(h) = 6 pi mu R^2 (1/h - 1/hout), m dv = -c dh gives the speed
        v(h) = v0 - 6 pi mu R^2/m (ln(hout/h) - 1 + h/hout),
    and the sphere stops where v = 0 (Stokes number m v0/(6 pi mu R^2) =
    0.28): never touching the wall, at that gap within 1 %.
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

using namespace demTest;

namespace
{

const double pi = std::acos(-1.0);
const double R = 0.5e-6;        // m
const double rho = 2500;        // kg/m^3

bool finite(const LiggghtsRun& run)
{
    for (int k = 0; k < 3; k++)
        if (!std::isfinite(run.x(1)[k]) || !std::isfinite(run.v(1)[k]) || !std::isfinite(run.omega(1)[k]))
            return false;
    return true;
}

std::string wallSetup(const std::string& stl, double dt)
{
    writeSquareStl(stl, 4, 0);
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(5)
       << "fix m1 all property/global loadingStiffness peratomtypepair 2 1000 1000 1000 1000\n"
          "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
          "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
          "fix m4 all property/global tangentialStiffness peratomtypepair 2 285.7 285.7 285.7 285.7\n"
          "fix m5 all property/global youngsModulus peratomtype 1e5 1e5\n"
          "fix m6 all property/global poissonsRatio peratomtype 0.3 0.3\n"
          "neighbor 0.2 bin\n"
          "neigh_modify delay 0\n"
          "timestep " << dt/us << "\n"
          "fix wallMesh all mesh/surface file " << stl << " type 2\n";
    return in.str();
}

} // namespace


TEST(extremeWall, extremeWallImpact)
{
    const double K1 = 1, e = 0.5, mu = 0.3;
    const double vn = 0.8, vt = 0.6;        // m/s
    const double dt = 1e-10;                // s, 1/850 of the contact
    LiggghtsRun run;
    std::ostringstream in;
    in.precision(17);
    in << wallSetup("wallImpact.stl", dt)
       << "pair_style gran model walton_braun tangential walton_braun\n"
          "pair_coeff * *\n"
          "fix wall all wall/gran model walton_braun tangential walton_braun "
          "mesh n_meshes 1 meshes wallMesh diRenzoDiMaio on\n"
          "fix integrate all nve/sphere\n"
          "create_atoms 1 single 0.3 -0.2 " << (R + 20e-9)/um << " units box\n"
          "set atom 1 diameter " << 2*R/um << " density " << rho*um*um*um/pg
       << " vx " << vt << " vz " << -vn << "\n"
          "run 0\n";
    run.commands(in.str());
    const double m = run.mass(1)*pg;
    const double I = 0.4*m*R*R;
    const double dRef = vn*std::sqrt(m/K1);
    const double tContact = pi/2*std::sqrt(m/K1)*(1 + e);
    const double E0 = 0.5*m*(vn*vn + vt*vt);

    double dMax = 0;
    bool allFinite = true, touched = false;
    long n = 0;
    for (; n < 100000; n++)
    {
        run.commands("run 1 pre no post no\n");
        if (!finite(run)) { allFinite = false; break; }
        const double h = run.x(1)[2]*um - R;
        dMax = std::max(dMax, -h);
        touched = touched || h < 0;
        if (touched && h > 0.01*R) break;
    }
    ASSERT_TRUE(allFinite) << "NaN or infinite position or velocity";
    ASSERT_TRUE(touched);
    const double vnOut = run.v(1)[2]*um/us;
    const double vtOut = run.v(1)[0]*um/us;
    const double w = run.omega(1)[1]/us;
    const double E1 = 0.5*m*(run.v(1)[0]*run.v(1)[0] + run.v(1)[1]*run.v(1)[1] + run.v(1)[2]*run.v(1)[2])
                    + 0.5*I*w*w;
    const double Jn = m*(vnOut + vn), Jt = m*std::fabs(vtOut - vt);
    std::cout << "1 m/s at a wall: " << n << " steps (contact " << tContact/dt << "); overlap "
              << dMax << " m (" << dMax/R << " R), closed form " << dRef << " m; rebound "
              << vnOut << " m/s, closed form " << e*vn << " m/s; tangential " << vt << " -> "
              << vtOut << " m/s, spin " << w << " 1/s; impulses t/n " << Jt/Jn
              << "; kinetic energy " << E0 << " -> " << E1 << " J" << std::endl;
    EXPECT_NEAR(dMax, dRef, 0.01*dRef);
    EXPECT_NEAR(vnOut, e*vn, 0.01*e*vn);
    EXPECT_LT(dMax, 0.25*R);
    EXPECT_LE(Jt, mu*Jn*(1 + 1e-6));
    EXPECT_LE(E1, E0);
}


TEST(extremeWall, extremeWallImpactLubricated)
{
    const double mu = 1e-3;                 // Pa s
    const double hin = 1e-9, hout = 0.1e-6; // m
    const double v0 = 1;                    // m/s
    const double hStart = 0.2e-6;           // m
    const double dt = 1e-10;                // s
    LiggghtsRun run;
    std::ostringstream in;
    in.precision(17);
    in << wallSetup("wallImpactLubricated.stl", dt)
       << "fix l1 all property/global liquidViscosity scalar " << mu/1e-3 << "\n"
          "fix l2 all property/global lubricationInnerCutoff scalar " << hin/um << "\n"
          "fix l3 all property/global lubricationOuterCutoff scalar " << hout/um << "\n"
          "pair_style gran model walton_braun tangential history cohesion colloid/lub\n"
          "pair_coeff * *\n"
          "fix wall all wall/gran model walton_braun tangential history cohesion colloid/lub "
          "mesh n_meshes 1 meshes wallMesh\n"
          "fix integrate all nve/sphere\n"
          "create_atoms 1 single 0.3 -0.2 " << (R + hStart)/um << " units box\n"
          "set atom 1 diameter " << 2*R/um << " density " << rho*um*um*um/pg << " vz " << -v0 << "\n"
          "run 0\n";
    run.commands(in.str());
    const double m = run.mass(1)*pg;
    const double b = 6*pi*mu*R*R/m;
    const double stokes = v0/b;

    // stopping gap: v(h) = 0, bisection on [hin, hout]
    auto v = [&](double h) { return v0 - b*(std::log(hout/h) - 1 + h/hout); };
    ASSERT_LT(v(hin), 0) << "would reach the inner cut-off";
    double lo = hin, hi = hout;
    for (int i = 0; i < 200; i++)
    {
        const double mid = 0.5*(lo + hi);
        (v(mid) > 0 ? hi : lo) = mid;
    }
    const double hStop = 0.5*(lo + hi);

    double hMin = hStart, KEprev = 0.5*m*v0*v0;
    bool allFinite = true, energyFalls = true;
    for (long n = 0; n < 100000; n++)
    {
        run.commands("run 10 pre no post no\n");
        if (!finite(run)) { allFinite = false; break; }
        const double h = run.x(1)[2]*um - R;
        const double vz = run.v(1)[2]*um/us;
        const double KE = 0.5*m*vz*vz;
        energyFalls = energyFalls && KE <= KEprev;
        KEprev = KE;
        hMin = std::min(hMin, h);
        if (std::fabs(vz) < 1e-6*v0) break;
    }
    std::cout << "1 m/s in water: Stokes number " << stokes << "; stopped at " << hMin
              << " m, closed form " << hStop << " m" << std::endl;
    ASSERT_TRUE(allFinite) << "NaN or infinite position or velocity";
    EXPECT_TRUE(energyFalls);
    EXPECT_GT(hMin, 0);
    EXPECT_NEAR(hMin, hStop, 0.01*hStop);
}
