/*---------------------------------------------------------------------------*\
    Unit tests of hydrodynamicMobility.H and of lubrication.H's two-sphere
    form.

    Reference: Brenner's (1961, Chem. Eng. Sci. 16, 242) exact series for a
    sphere of radius a moving normal to a plane at centre distance d,
    cosh(alpha) = d/a, summed here to round-off:
        lambda = (4/3) sinh(alpha) sum_n n(n+1)/((2n-1)(2n+3)) (N_n/D_n - 1),
      rigid (no-slip) plane:
        N_n = 2 sinh((2n+1) alpha) + (2n+1) sinh(2 alpha),
        D_n = 4 sinh^2((n+1/2) alpha) - (2n+1)^2 sinh^2(alpha);
      free surface (no shear stress): the plane of symmetry between two
        equal spheres closing along their line of centres, d = a + h/2:
        N_n = 4 cosh^2((n+1/2) alpha) + (2n+1)^2 sinh^2(alpha),
        D_n = 2 sinh((2n+1) alpha) - (2n+1) sinh(2 alpha).
    The force on each sphere is lambda times its Stokes drag, so the
    mobilities are f = 1/lambda (wall) and G = 1/lambda (two spheres).
    The fits of the kernel are held to their stated accuracy against the
    series from h = 1e-3 a to 100 a (Honig et al. 3.2 %, Bevan & Prieve
    0.8 %), and the resistances of lubrication.H's two-sphere form to the
    mobility they are built to give.

    Flow-driven 1 - A (Batchelor & Green 1972): exact values of A for two
    equal spheres at r = 2.025 ... 10 (Wilson's 2013 two-sphere code, via
    the stokesian-dynamics resistance tables; checked to 1e-6 against
    Jeffrey & Onishi's 1984 series), Batchelor & Green's near-contact
    limit 1 - A = 4.0774 h/a and far field A = 5/r^3 + ... .  At the
    table's points below r = 3 the kernel interpolates these same values,
    so there the test checks their transcription; between the points no
    exact values were at hand (the kernel's header estimates the
    interpolation error).
\*---------------------------------------------------------------------------*/
#include "constants.H"
#include "hydrodynamicMobility.H"
#include "lubrication.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

using namespace colloid;

namespace
{

// Brenner's resistance factor lambda at d/a (above)
double brenner(double dOverA, bool rigidPlane)
{
    const double al = std::acosh(dOverA);
    double sum = 0.0;
    for (int n = 1; (2*n + 1)*al < 700; n++)
    {
        const double k = 2*n + 1, s1 = std::sinh(al);
        const double N = rigidPlane
            ? 2*std::sinh(k*al) + k*std::sinh(2*al)
            : 4*std::pow(std::cosh((n + 0.5)*al), 2) + k*k*s1*s1;
        const double D = rigidPlane
            ? 4*std::pow(std::sinh((n + 0.5)*al), 2) - k*k*s1*s1
            : 2*std::sinh(k*al) - k*std::sinh(2*al);
        const double term = n*(n + 1.0)/((2*n - 1.0)*(2*n + 3.0))*(N/D - 1);
        sum += term;
        if (std::fabs(term) < 1e-17*std::fabs(sum)) break;
    }
    return 4.0/3.0*std::sinh(al)*sum;
}

// gaps h/a from 1e-3 to 100, 10 a decade
template<class Check>
void overGaps(const Check& check)
{
    for (int i = 0; i <= 50; i++) check(std::pow(10.0, -3 + 0.1*i));
}

} // namespace


TEST(HydrodynamicMobility, TwoSpheresWithinHonigsAccuracyOfTheExactSeries)
{
    overGaps([&](double u)
    {
        const double exact = 1/brenner(1 + u/2, false);
        EXPECT_NEAR(mobility::twoSpheres(u)/exact, 1.0, 0.032) << "h/a = " << u;
    });
}

TEST(HydrodynamicMobility, SphereWallWithinBevanPrievesAccuracyOfTheExactSeries)
{
    overGaps([&](double u)
    {
        const double exact = 1/brenner(1 + u, true);
        EXPECT_NEAR(mobility::sphereWall(u)/exact, 1.0, 0.008) << "h/a = " << u;
    });
}

TEST(HydrodynamicMobility, LimitsOfReynoldsAndOseen)
{
    // near contact the squeeze film: G = 2h/a, f = h/a (Reynolds)
    EXPECT_NEAR(mobility::twoSpheres(1e-7)/2e-7, 1.0, 1e-5);
    EXPECT_NEAR(mobility::sphereWall(1e-7)/1e-7, 1.0, 1e-5);
    // far away the Oseen coupling of two spheres: 1 - G -> 3/(2r), r = 2 + u
    const double u = 1e4;
    EXPECT_NEAR((1 - mobility::twoSpheres(u))*(2 + u), 1.5, 1e-3);
}

TEST(HydrodynamicMobility, TwoSphereResistanceGivesThePairTheMobility)
{
    // two equal spheres (each drag 6 pi mu a, relative drag 3 pi mu a)
    // with the pair resistance c: relative mobility 3 pi mu a/(3 pi mu a + c)
    const double mu = 1e-3, a = 0.15e-6, pi = constants::pi;
    LubricationParameters p;
    p.viscosity = mu;
    p.innerCutoff = 1e-12;
    p.outerCutoff = 1.0;        // faded: no cut at these gaps
    p.fade = true;
    p.farField = true;
    const Lubrication lub(p);
    overGaps([&](double u)
    {
        const double zeta = 3*pi*mu*a;
        const double c = lub.resistance(a, a, u*a);
        EXPECT_NEAR(zeta/(zeta + c)/mobility::twoSpheres(u), 1.0, 1e-9) << "h/a = " << u;
        // and a sphere against a wall with its Stokes drag 6 pi mu a
        const double cw = lub.resistance(a, wallRadius, u*a);
        EXPECT_NEAR(2*zeta/(2*zeta + cw)/mobility::sphereWall(u), 1.0, 1e-9) << "h/a = " << u;
    });
    // the near field of the two-sphere form is the near-field form's
    LubricationParameters q = p;
    q.farField = false;
    const Lubrication near(q);
    const double h = 1e-4*a;
    EXPECT_NEAR(lub.resistance(a, a, h)/near.resistance(a, a, h), 1.0, 5e-4);
    EXPECT_NEAR(lub.resistance(a, wallRadius, h)/near.resistance(a, wallRadius, h), 1.0, 5e-4);
}


namespace
{

// exact A(r) of two equal force-free spheres (above)
struct ExactA { double r, A; };
const ExactA exactA[] =
{
    {2.025, 0.911980}, {2.05, 0.841817}, {2.1, 0.732428}, {2.2, 0.581978},
    {2.3, 0.480017}, {2.4, 0.405194}, {2.5, 0.347646}, {2.6, 0.301964},
    {2.8, 0.234186}, {3.0, 0.186662}, {3.5, 0.114775}, {4.0, 0.076287},
    {4.5, 0.053478}, {5.0, 3.901e-2}, {6.0, 2.265e-2}, {8.0, 9.616e-3},
    {10.0, 4.945e-3}
};

} // namespace


TEST(HydrodynamicMobility, FlowDrivenAgainstExactValues)
{
    // to the table's last digit (6 decimals to r = 4.5, 4 figures beyond),
    // and at r = 3, where the far-field series takes over, its 5.4e-5
    for (const ExactA& e : exactA)
    {
        const double flow = mobility::twoSpheresInFlow(e.r - 2);
        EXPECT_NEAR(flow, 1 - e.A, e.r == 3.0 ? 6e-5 : 6e-6) << "r = " << e.r;
    }
}

TEST(HydrodynamicMobility, FlowDrivenLimitsAndShape)
{
    // Batchelor & Green's near-contact limit, and 5/r^3 far away
    EXPECT_NEAR(mobility::twoSpheresInFlow(1e-7)/1e-7, 4.0774, 1e-4);
    EXPECT_NEAR((1 - mobility::twoSpheresInFlow(1e3))*std::pow(1002.0, 3), 5.0, 1e-3);
    // continuous where the forms meet (u = 0.025 and r = 3)
    for (double u : {0.025, 1.0})
    {
        EXPECT_NEAR(mobility::twoSpheresInFlow(u*(1 - 1e-12)), mobility::twoSpheresInFlow(u*(1 + 1e-12)), 1e-6)
            << "u = " << u;
    }
    // A falls monotonically with distance, and the liquid carries a pair
    // together more easily than a force pushes it (1 - A > G): the flow
    // factor of lubrication.H lies in (0, 1)
    double last = 0.0;
    overGaps([&](double u)
    {
        const double flow = mobility::twoSpheresInFlow(u);
        EXPECT_GT(flow, last) << "h/a = " << u;
        EXPECT_GT(flow, mobility::twoSpheres(u)) << "h/a = " << u;
        EXPECT_LT(flow, 1.0) << "h/a = " << u;
        last = flow;
    });
}

TEST(HydrodynamicMobility, FlowFactorGivesThePairTheFlowDrivenMobility)
{
    // two equal spheres, each with drag zeta = 6 pi mu a towards the
    // liquid's velocity at its centre, and the pair damping
    // -c (v_n - phi u_n): the relative normal velocity in a flow with
    // relative normal velocity u_n is (zeta/2 + c phi)/(zeta/2 + c) u_n.
    // Outer cut-off 2a, faded: 1 - A up to h = a, then 1 - A w with the
    // resistance's weight w (written out: x = (h - a)/a, w = 1 - x^2 (3 -
    // 2x)), and 1 beyond 2a
    const double mu = 1e-3, a = 0.15e-6, pi = constants::pi;
    LubricationParameters p;
    p.viscosity = mu;
    p.innerCutoff = 1e-12;
    p.outerCutoff = 2*a;
    p.fade = true;
    p.farField = true;
    const Lubrication lub(p);
    overGaps([&](double u)
    {
        const double zr = 3*pi*mu*a, c = lub.resistance(a, a, u*a), phi = lub.flowFactor(a, a, u*a);
        const double x = std::min(1.0, std::max(0.0, u - 1)), w = 1 - x*x*(3 - 2*x);
        const double expected = 1 - (1 - mobility::twoSpheresInFlow(u))*w;
        EXPECT_NEAR((zr + c*phi)/(zr + c), expected, 1e-12) << "h/a = " << u;
        // and the force-driven mobility: G up to a, the faded resistance's beyond
        if (u <= 1)
        {
            EXPECT_NEAR(zr/(zr + c), mobility::twoSpheres(u), 1e-12) << "h/a = " << u;
        }
    });
    // none in the near-field form, for a wall, or beyond the cut-off
    EXPECT_EQ(lub.flowFactor(a, wallRadius, 0.1*a), 0.0);
    EXPECT_EQ(lub.flowFactor(a, a, 2*a), 0.0);
    LubricationParameters q = p;
    q.farField = false;
    EXPECT_EQ(Lubrication(q).flowFactor(a, a, 0.1*a), 0.0);
}

TEST(HydrodynamicMobility, TwoSphereFormRefusesTheShiftedCutoff)
{
    // shifted, it would lose c(h_out) ~ 1.5 zeta a/h_out at every gap
    LubricationParameters p;
    p.outerCutoff = 0.3e-6;
    p.farField = true;
    p.fade = false;
    try
    {
        Lubrication lub(p);
        FAIL() << "the shifted two-sphere form was accepted";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("'farField' = 1 needs 'fade' = 1"), std::string::npos) << e.what();
    }
    p.fade = true;
    EXPECT_NO_THROW(Lubrication lub(p));
}
