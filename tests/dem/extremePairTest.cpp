/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: stiff and extreme particle pairs that the models
    run stably (the time step within the limits the plugin prints), two
    equal spheres head-on, Walton-Braun contact (K1, e = 0.5), no drag.

    References:
    - energy: the kinetic energy plus the surface-force energy U(h)
      (surfaceForceReference.H) never exceeds its initial value E0 (the
      contact stores energy, its hysteresis and lubrication only take it):
      within 1 % of the well depth |U(0)|;
    - first impact: on the loading line K1 the surface forces are held at
      their inner cut-off value Fs = F(h0), so the largest overlap solves
      K1 d^2/2 + Fs d = E0 - U(0):
          d = (sqrt(Fs^2 + 2 K1 (E0 - U(0))) - Fs)/K1,
      matched within 1 % (without lubrication), never exceeded (with it);
    - no NaN; the largest overlap is below a quarter of the radius.
    Cases:
    - extremeSmallParticles: R = 25 nm (50 nm particles), A = 1e-20 J;
    - extremeLargeHamaker: A = 1e-18 J (100 times water-glass), R = 0.5 um,
      K1 = 10 N/m (the contact must hold the van der Waals pull, 0.26 uN;
      with K1 = 0.1 N/m the plugin stops the run: startupLimitTest.cpp);
    - extremeHighSalt: 1 M salt (Debye length 0.3 nm): the double layer
      is too short to stop the van der Waals pull, the pair sticks;
    - extremeTinyGap: start at rest 0.1 nm apart, inside the inner
      cut-offs, van der Waals and double layer (1 mM); the lubricated
      variant adds the lubrication term;
    - extremeOverlapping: start at rest overlapping by 20 % and 60 % of the
      radius, contact only: the pair separates with relative speed
          v = e d0 sqrt(K1/m*)    (unloading line K2 = K1/e^2 from d0),
      within 1 %.
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"
#include "surfaceForceReference.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

using namespace demTest;

namespace
{

const double pi = std::acos(-1.0);
const double rho = 2500;            // kg/m^3
const double restitution = 0.5;

struct PairCase
{
    double R;                       // m
    double K1;                      // N/m
    SurfaceForceReference forces;   // Rs set from R
    bool lubrication = false;
    double hStart;                  // m, gap at rest at the start
    double dtFraction = 0.5;        // of the largest step allowed
};

// the plugin's limits (README): dt <= 1/20 of the contact duration and
// <= 1/10 of the van der Waals spring at h0, for two equal spheres
double timeStep(const PairCase& c)
{
    const double m = 4.0/3.0*pi*std::pow(c.R, 3)*rho;
    const double mStar = m/2;
    double dt = 0.05*pi/2*std::sqrt(mStar/c.K1)*(1 + restitution);
    if (c.forces.A != 0)
    {
        const double k = c.forces.A*c.forces.Rs/(3*std::pow(c.forces.h0v, 3));
        dt = std::min(dt, 0.1*std::sqrt(mStar/k));
    }
    return c.dtFraction*dt;
}

std::string cohesionName(const PairCase& c)
{
    std::string name;
    if (c.forces.A != 0) name += "/vdw";
    if (c.forces.salt != 0) name += "/dl";
    if (c.lubrication) name += "/lub";
    return name.empty() ? "" : " cohesion colloid" + name;
}

std::string setupScript(const PairCase& c, double dt)
{
    const SurfaceForceReference& f = c.forces;
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(5)
       << "fix m1 all property/global loadingStiffness peratomtypepair 2 "
       << c.K1/1e-3 << ' ' << c.K1/1e-3 << ' ' << c.K1/1e-3 << ' ' << c.K1/1e-3 << "\n"
          "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
          "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n";
    if (f.A != 0)
    {
        const double A = f.A/fJ;
        in << "fix v1 all property/global hamakerConstant peratomtypepair 2 "
           << A << ' ' << A << ' ' << A << ' ' << A << "\n"
              "fix v2 all property/global vdwOuterCutoff scalar " << f.hcv/um << "\n"
              "fix v3 all property/global vdwInnerCutoff scalar " << f.h0v/um << "\n";
    }
    if (f.salt != 0)
    {
        in << "fix d1 all property/global zetaPotential peratomtype " << f.zeta1 << ' ' << f.zeta2 << "\n"
              "fix d2 all property/global saltConcentration scalar " << f.salt << "\n"
              "fix d3 all property/global doubleLayerOuterCutoff scalar " << f.hcd/um << "\n"
              "fix d4 all property/global doubleLayerInnerCutoff scalar " << f.h0d/um << "\n";
    }
    if (c.lubrication)
    {
        in << "fix l1 all property/global liquidViscosity scalar 1.0\n";
    }
    in << "neighbor " << std::max(0.1, 0.2*c.R/um) << " bin\n"
          "neigh_modify delay 0\n"
          "pair_style gran model walton_braun tangential history" << cohesionName(c) << "\n"
          "pair_coeff * *\n"
          "timestep " << dt/us << "\n"
          "fix integrate all nve/sphere\n"
          "create_atoms 1 single 0 0 0 units box\n"
          "create_atoms 1 single " << (2*c.R + c.hStart)/um << " 0 0 units box\n"
          "set atom * diameter " << 2*c.R/um << " density " << rho*um*um*um/pg << "\n"
          "run 0\n";
    return in.str();
}

bool finite(const LiggghtsRun& run)
{
    for (int id : {1, 2})
        for (int k = 0; k < 3; k++)
            if (!std::isfinite(run.x(id)[k]) || !std::isfinite(run.v(id)[k])) return false;
    return true;
}

// run the pair through its first impact and ten contact durations more,
// checking energy, overlap and finiteness at every step
void runPair(PairCase c, const char* label)
{
    c.forces.Rs = c.R/2;
    const double dt = timeStep(c);
    LiggghtsRun run;
    run.commands(setupScript(c, dt));

    const double m = run.mass(1)*pg, mStar = m/2;
    const SurfaceForceReference& f = c.forces;
    const double E0 = f.energy(c.hStart);
    const double depth = std::fabs(f.energy(0));
    const double Fs = f.force(0);
    const double dImpact = (std::sqrt(Fs*Fs + 2*c.K1*(E0 - f.energy(0))) - Fs)/c.K1;
    const double tContact = pi/2*std::sqrt(mStar/c.K1)*(1 + restitution);

    auto gap = [&]() { return (run.x(2)[0] - run.x(1)[0])*um - 2*c.R; };
    double worstExcess = -HUGE_VAL, dMax = 0, dFirst = 0;
    bool touched = false, firstDone = false, allFinite = true;
    long stepsAfter = 0;
    const long afterSteps = static_cast<long>(10*tContact/dt);
    const long maxSteps = 200000;
    for (long n = 0; n < maxSteps && stepsAfter < afterSteps; n++)
    {
        run.commands("run 1 pre no post no\n");
        if (!finite(run)) { allFinite = false; break; }
        const double h = gap();
        const double vRel = (run.v(2)[0] - run.v(1)[0])*um/us;
        const double KE = 0.5*mStar*vRel*vRel;
        worstExcess = std::max(worstExcess, KE + f.energy(h) - E0);
        dMax = std::max(dMax, -h);
        touched = touched || h < 0;
        // the first impact ends when the pair moves apart (never, if
        // lubrication damps the contact: then it is the whole run)
        if (touched && vRel > 0) firstDone = true;
        if (touched && !firstDone) dFirst = std::max(dFirst, -h);
        if (touched) stepsAfter++;
    }
    std::cout << label << ": dt " << dt << " s, E0 " << E0 << " J, well depth " << depth
              << " J; largest energy excess " << worstExcess << " J; first impact overlap "
              << dFirst << " m, closed form " << dImpact << " m (" << dImpact/c.R
              << " R); largest overlap " << dMax << " m; final gap " << gap() << " m" << std::endl;

    ASSERT_TRUE(allFinite) << "NaN or infinite position or velocity";
    ASSERT_TRUE(touched) << "no impact within " << maxSteps << " steps";
    EXPECT_LT(worstExcess, 0.01*depth);
    if (c.lubrication) EXPECT_LT(dFirst, 1.01*dImpact);
    else EXPECT_NEAR(dFirst, dImpact, 0.01*dImpact);
    EXPECT_LT(dMax, 1.01*dImpact);
    EXPECT_LT(dMax, 0.25*c.R);
}

} // namespace


TEST(extremePair, extremeSmallParticles)
{
    PairCase c;
    c.R = 25e-9;
    c.K1 = 0.1;
    c.forces.A = 1e-20;
    c.hStart = 20e-9;
    runPair(c, "50 nm particles");
}


TEST(extremePair, extremeLargeHamaker)
{
    PairCase c;
    c.R = 0.5e-6;
    c.K1 = 10;
    c.forces.A = 1e-18;
    c.hStart = 20e-9;
    runPair(c, "A = 1e-18 J");
}


TEST(extremePair, extremeHighSalt)
{
    PairCase c;
    c.R = 0.5e-6;
    c.K1 = 1;
    c.forces.A = 1e-20;
    c.forces.zeta1 = c.forces.zeta2 = -0.03;
    c.forces.salt = 1000;           // mol/m^3 = 1 M
    c.forces.hcd = 5e-9;            // 16 Debye lengths
    c.hStart = 20e-9;
    runPair(c, "1 M salt");
}


namespace
{

PairCase tinyGap()
{
    PairCase c;
    c.R = 0.5e-6;
    c.K1 = 1;
    c.forces.A = 1e-20;
    c.forces.zeta1 = c.forces.zeta2 = -0.03;
    c.forces.salt = 1;
    c.hStart = 0.1e-9;
    return c;
}

} // namespace


TEST(extremePair, extremeTinyGap)
{
    runPair(tinyGap(), "gap 0.1 nm");
}


TEST(extremePair, extremeTinyGapLubricated)
{
    PairCase c = tinyGap();
    c.lubrication = true;
    runPair(c, "gap 0.1 nm, lubricated");
}


TEST(extremePair, extremeOverlapping)
{
    const double R = 0.5e-6, K1 = 0.1;   // m, N/m
    for (double fraction : {0.2, 0.6})
    {
        const double d0 = fraction*R;
        const double dt = 1e-10;         // s: 1/1900 of the contact duration
        LiggghtsRun run;
        std::ostringstream in;
        in.precision(17);
        in << LiggghtsRun::header(5)
           << "fix m1 all property/global loadingStiffness peratomtypepair 2 100 100 100 100\n"
              "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
              "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
              "neighbor 0.2 bin\n"
              "neigh_modify delay 0\n"
              "pair_style gran model walton_braun tangential history\n"
              "pair_coeff * *\n"
              "timestep " << dt/us << "\n"
              "fix integrate all nve/sphere\n"
              "create_atoms 1 single 0 0 0 units box\n"
              "create_atoms 1 single " << (2*R - d0)/um << " 0 0 units box\n"
              "set atom * diameter " << 2*R/um << " density " << rho*um*um*um/pg << "\n"
              "run 0\n";
        run.commands(in.str());
        const double mStar = run.mass(1)*pg/2;
        const double vRef = restitution*d0*std::sqrt(K1/mStar);

        auto gap = [&]() { return (run.x(2)[0] - run.x(1)[0])*um - 2*R; };
        double dMax = 0;
        bool allFinite = true;
        long n = 0;
        for (; n < 100000 && gap() < 0.01*R; n++)
        {
            run.commands("run 1 pre no post no\n");
            allFinite = allFinite && finite(run);
            if (!allFinite) break;
            dMax = std::max(dMax, -gap());
        }
        const double v = (run.v(2)[0] - run.v(1)[0])*um/us;
        std::cout << "overlap " << fraction << " R: separated after " << n << " steps at "
                  << v << " m/s, closed form " << vRef << " m/s; largest overlap " << dMax
                  << " m" << std::endl;
        ASSERT_TRUE(allFinite) << "NaN or infinite position or velocity";
        EXPECT_GT(gap(), 0);
        EXPECT_NEAR(v, vRef, 0.01*vRef);
        EXPECT_LE(dMax, d0*(1 + 1e-9));
    }
}
