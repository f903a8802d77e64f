/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: the faded outer cut-offs (vdwFade 1,
    doubleLayerFade 1) of the force LIGGGHTS applies through the plugin
    (cohesion colloid/vdw/dl) between two unequal spheres, read back after
    "run 0", against the closed forms written out here:
        F(h) = Fdl(h) - Fvdw(h)  (positive = repulsive), h0 <= h,
        Fvdw = A Rs/(6 h^2),
        Fdl  = 128 pi Rs n kT G^2/kappa exp(-kappa h),
        G = tanh(e zeta/(4 kT)), n = N_A c,
        1/kappa = sqrt(eps_r eps0 kT/(2 N_A e^2 c)),
    uncut for h <= hc/2 and times w = 3y^2 - 2y^3, y = (hc - h)/(hc/2),
    between hc/2 and hc (both terms at the same cut-off hc), zero beyond.
    The shifted forms would differ by Fvdw(hc) and Fdl(hc) at every gap
    (1.7 % of the net force at hc/2), which the tolerance (1e-8) tells
    apart.
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace demTest;

TEST(fadedForce, fadedDlvoPairForce)
{
    const double hamaker = 1e-20;   // J
    const double zeta = -0.02;      // V, both spheres
    const double salt = 1.0;        // mol/m^3
    const double T = 298.15, epsR = 78.4;
    const double hc = 60e-9;        // m, both outer cut-offs
    const double R1 = 0.5, R2 = 0.3;   // um

    const double pi = std::acos(-1.0);
    const double kB = 1.380649e-23, e = 1.602176634e-19;
    const double NA = 6.02214076e23, eps0 = 8.8541878128e-12;
    const double kT = kB*T;
    const double kappa = std::sqrt(2*NA*e*e*salt/(epsR*eps0*kT));
    const double G = std::tanh(e*zeta/(4*kT));
    const double Rs = R1*R2/(R1 + R2)*um;
    auto reference = [&](double h)
    {
        if (h >= hc) return 0.0;
        const double y = std::min(1.0, (hc - h)/(0.5*hc));
        const double w = 3*y*y - 2*y*y*y;
        const double dl = 128*pi*Rs*NA*salt*kT*G*G/kappa*std::exp(-kappa*h);
        const double vdw = hamaker*Rs/(6*h*h);
        return (dl - vdw)*w;
    };

    LiggghtsRun run;
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(5) << LiggghtsRun::waltonBraunMaterials()
       << "fix c1 all property/global hamakerConstant peratomtypepair 2 "
       << hamaker/fJ << ' ' << hamaker/fJ << ' ' << hamaker/fJ << ' ' << hamaker/fJ << "\n"
          "fix c2 all property/global vdwOuterCutoff scalar " << hc/um << "\n"
          "fix c3 all property/global vdwFade scalar 1\n"
          "fix c4 all property/global zetaPotential peratomtype " << zeta << ' ' << zeta << "\n"
          "fix c5 all property/global saltConcentration scalar " << salt << "\n"
          "fix c6 all property/global liquidTemperature scalar " << T << "\n"
          "fix c7 all property/global relativePermittivity scalar " << epsR << "\n"
          "fix c8 all property/global doubleLayerOuterCutoff scalar " << hc/um << "\n"
          "fix c9 all property/global doubleLayerFade scalar 1\n"
          "neighbor 0.2 bin\n"
          "neigh_modify delay 0\n"
          "pair_style gran model walton_braun tangential history cohesion colloid/vdw/dl\n"
          "pair_coeff * *\n"
          "timestep 1e-5\n"
          "create_atoms 1 single 0 0 0 units box\n"
          "create_atoms 1 single 1 0 0 units box\n"
          "set atom 1 diameter 1.0 density 2.5\n"
          "set atom 2 diameter 0.6 density 2.5\n";
    run.commands(in.str());

    // near field (uncut), the start of the fade, inside it, beyond
    for (double h : {2e-9, 10e-9, 29e-9, 30e-9, 38e-9, 50e-9, 59e-9, 70e-9})
    {
        std::ostringstream move;
        move.precision(17);
        move << "set atom 2 x " << R1 + R2 + h/um << "\nrun 0\n";
        run.commands(move.str());
        const double F = reference(h);
        // a repulsive F pushes particle 1 towards -x, particle 2 towards +x
        EXPECT_NEAR(run.f(1)[0]*nN, -F, 1e-8*std::fabs(F) + 1e-30) << "gap " << h;
        EXPECT_NEAR(run.f(2)[0]*nN, F, 1e-8*std::fabs(F) + 1e-30) << "gap " << h;
    }
}
