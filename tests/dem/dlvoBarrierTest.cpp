/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: DLVO energy barrier between two equal spheres
    (cohesion colloid/vdw/dl, model walton_braun, no liquid drag) pushed
    head-on towards each other from beyond the interaction range.

    Reference computed in the test: the net repulsion
        F(h) = Fdl(h) - Fvdw(h),
        Fvdw = A Rs (1/max(h, h0)^2 - 1/hc^2)/6                 (h < hc),
        Fdl  = 128 pi Rs n kT G^2/kappa (exp(-kappa max(h, h0))
               - exp(-kappa hcdl))                               (h < hcdl),
        G = tanh(z e zeta/(4 kT)), n = N_A c,
        1/kappa = sqrt(eps_r eps0 kT/(2 N_A e^2 z^2 c)), Rs = R/2,
    (Derjaguin van der Waals and seed 002's linear-superposition double
    layer, each force-shifted at its outer cut-off and held below h0), and
    its energy U(h), the integral of F from h to the range, integrated
    numerically; the barrier is the maximum of U.
    - Relative kinetic energy 0.8 U_max: the pair turns back at the gap
      where U = E (within 1 %), leaves with its initial speed (within 1 %),
      and the force read back at every step matches F(h).
    - 1.2 U_max: the pair crosses the barrier and stays in the primary
      minimum (the contact's hysteresis takes the energy it would need).
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

// material and liquid, SI
const double R = 0.5e-6;            // m
const double rho = 2500;            // kg/m^3
const double hamaker = 1e-20;       // J
const double zeta = -0.03;          // V
const double salt = 1.0;            // mol/m^3 (1 mM)
const double temperature = 298.15;  // K
const double epsR = 78.4;
const double h0 = 0.4e-9;           // m, both inner cut-offs (plugin default)
const double hcVdw = 50e-9;         // m
const double hcDl = 50e-9;          // m

struct Dlvo
{
    double Rs, kappa, dlPrefactor;
    std::vector<double> h, U;       // energy table on a fine grid

    Dlvo()
    {
        const double kB = 1.380649e-23, e = 1.602176634e-19;
        const double NA = 6.02214076e23, eps0 = 8.8541878128e-12;
        const double kT = kB*temperature;
        Rs = R/2;
        kappa = 1/std::sqrt(epsR*eps0*kT/(2*NA*e*e*salt));
        const double G = std::tanh(e*zeta/(4*kT));
        dlPrefactor = 128*pi*Rs*NA*salt*kT*G*G/kappa;

        // U(h) = integral of F from h to the range, trapezoidal, 0.5 pm steps
        const double hMax = std::max(hcVdw, hcDl);
        const int n = static_cast<int>(hMax/0.5e-12);
        h.resize(n + 1);
        U.resize(n + 1);
        for (int i = 0; i <= n; i++) h[i] = hMax*i/n;
        U[n] = 0;
        for (int i = n - 1; i >= 0; i--)
            U[i] = U[i + 1] + 0.5*(force(h[i]) + force(h[i + 1]))*(h[i + 1] - h[i]);
    }

    // net repulsive force [N]
    double force(double g) const
    {
        double F = 0;
        if (g < hcVdw)
        {
            const double ge = std::max(g, h0);
            F -= hamaker*Rs/6*(1/(ge*ge) - 1/(hcVdw*hcVdw));
        }
        if (g < hcDl)
            F += dlPrefactor*(std::exp(-kappa*std::max(g, h0)) - std::exp(-kappa*hcDl));
        return F;
    }

    int barrierIndex() const
    {
        return static_cast<int>(std::max_element(U.begin(), U.end()) - U.begin());
    }

    // outer gap where U = E (E < U_max), linear interpolation on the grid
    double turningGap(double E) const
    {
        const int iBarrier = barrierIndex();
        for (int i = static_cast<int>(U.size()) - 2; i >= iBarrier; i--)
            if (U[i] >= E)
                return h[i] + (h[i + 1] - h[i])*(U[i] - E)/(U[i] - U[i + 1]);
        return -1;
    }
};

const double hStart = 60e-9;        // m, beyond both cut-offs: U = 0
const double dt = 1e-4;             // us

// the pair set up with relative kinetic energy fraction*U_max
void setup(LiggghtsRun& run, const Dlvo& dlvo, double fraction, double& vRel)
{
    std::ostringstream in;
    in.precision(17);
    const double A = hamaker/fJ;
    in << LiggghtsRun::header(5)
       << "fix m1 all property/global loadingStiffness peratomtypepair 2 100 100 100 100\n"
          "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
          "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
          "fix c1 all property/global hamakerConstant peratomtypepair 2 "
       << A << ' ' << A << ' ' << A << ' ' << A << "\n"
          "fix c2 all property/global vdwOuterCutoff scalar " << hcVdw/um << "\n"
          "fix c3 all property/global vdwInnerCutoff scalar " << h0/um << "\n"
          "fix c4 all property/global zetaPotential peratomtype " << zeta << ' ' << zeta << "\n"
          "fix c5 all property/global saltConcentration scalar " << salt << "\n"
          "fix c6 all property/global saltValence scalar 1\n"
          "fix c7 all property/global liquidTemperature scalar " << temperature << "\n"
          "fix c8 all property/global relativePermittivity scalar " << epsR << "\n"
          "fix c9 all property/global doubleLayerInnerCutoff scalar " << h0/um << "\n"
          "fix c10 all property/global doubleLayerOuterCutoff scalar " << hcDl/um << "\n"
          "neighbor 0.1 bin\n"
          "neigh_modify delay 0\n"
          "pair_style gran model walton_braun tangential history cohesion colloid/vdw/dl\n"
          "pair_coeff * *\n"
          "timestep " << dt << "\n"
          "fix integrate all nve/sphere\n"
          "create_atoms 1 single 0 0 0 units box\n"
          "create_atoms 1 single " << (2*R + hStart)/um << " 0 0 units box\n"
          "set atom * diameter " << 2*R/um << " density " << rho*um*um*um/pg << "\n"
          "run 0\n";
    run.commands(in.str());

    const double m = run.mass(1)*pg;
    const double E = fraction*dlvo.U[dlvo.barrierIndex()];
    vRel = std::sqrt(2*E/(m/2));        // m/s = um/us
    std::ostringstream v;
    v.precision(17);
    v << "velocity all set 0 0 0 units box\n"
         "set atom 1 vx " << vRel/2 << "\n"
         "set atom 2 vx " << -vRel/2 << "\n";
    run.commands(v.str());
}

double gap(const LiggghtsRun& run)
{
    return (run.x(2)[0] - run.x(1)[0])*um - 2*R;
}

} // namespace


TEST(dlvoBarrier, dlvoBarrierTurnsBack)
{
    const Dlvo dlvo;
    LiggghtsRun run;
    double vRel;
    setup(run, dlvo, 0.8, vRel);
    const double E = 0.8*dlvo.U[dlvo.barrierIndex()];
    const double hTurn = dlvo.turningGap(E);

    const double Fscale = std::fabs(dlvo.force(hTurn));
    double hMin = gap(run), worstForce = 0;
    const int maxSteps = static_cast<int>(4*hStart/vRel/(dt*us));
    for (int n = 0; n < maxSteps; n++)
    {
        // back where it started, moving apart
        if (n > 0 && gap(run) > hStart && run.v(2)[0] > run.v(1)[0]) break;
        // single steps where the turning point is, coarse ones further out
        run.commands(gap(run) < 10e-9 ? "run 1 pre no post no\n" : "run 20 pre no post no\n");
        const double g = gap(run);
        hMin = std::min(hMin, g);
        // repulsion pushes particle 1 towards -x
        worstForce = std::max(worstForce, std::fabs(-run.f(1)[0]*nN - dlvo.force(g)));
    }
    const double vOut = run.v(2)[0] - run.v(1)[0];
    std::cout << "barrier " << dlvo.U[dlvo.barrierIndex()] << " J at "
              << dlvo.h[dlvo.barrierIndex()] << " m; turning gap DEM " << hMin
              << " m, reference " << hTurn << " m; speed in " << vRel << " out "
              << vOut << " m/s; largest force error " << worstForce << " N" << std::endl;

    ASSERT_GT(gap(run), hStart) << "the pair did not come back";
    EXPECT_GT(hMin, dlvo.h[dlvo.barrierIndex()]) << "crossed the barrier";
    EXPECT_NEAR(hMin, hTurn, 0.01*hTurn);
    EXPECT_NEAR(vOut, vRel, 0.01*vRel);
    EXPECT_LT(worstForce, 1e-9*Fscale);
}


TEST(dlvoBarrier, dlvoBarrierCrossedSticks)
{
    const Dlvo dlvo;
    LiggghtsRun run;
    double vRel;
    setup(run, dlvo, 1.2, vRel);
    const double hBarrier = dlvo.h[dlvo.barrierIndex()];

    // approach, then ten times the approach time with the pair in contact
    const double tApproach = hStart/vRel;
    const int steps = static_cast<int>(10*tApproach/(dt*us));
    bool touched = false;
    double hMaxAfter = -1;
    for (int n = 0; n < steps; n += 10)
    {
        run.commands("run 10 pre no post no\n");
        const double g = gap(run);
        if (g < 0) touched = true;
        if (touched) hMaxAfter = std::max(hMaxAfter, g);
    }
    std::cout << "largest gap after first contact " << hMaxAfter
              << " m, barrier at " << hBarrier << " m, final gap " << gap(run)
              << " m" << std::endl;
    ASSERT_TRUE(touched) << "the pair did not cross the barrier";
    EXPECT_LT(hMaxAfter, hBarrier);
    EXPECT_LT(gap(run), hBarrier);
}
