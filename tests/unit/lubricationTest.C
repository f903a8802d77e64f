/*---------------------------------------------------------------------------*\
    Unit tests of lubrication.H.

    References: Reynolds' squeeze-film results written out here (equal
    spheres 3 pi mu R^2 v/(2h), sphere-plane 6 pi mu R^2 v/h). The implicit
    update that applies the resistance is tested in LIGGGHTS
    (tests/dem/stiffTest.cpp, lubricationApproachTest.cpp).
\*---------------------------------------------------------------------------*/
#include "constants.H"
#include "lubrication.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

using namespace colloid;

namespace
{

const double pi = constants::pi;
const double mu = 1e-3;         // water [Pa s]
const double hIn = 1e-9;
const double hOut = 100e-9;

Lubrication make(double hOuter = hOut, bool fade = false)
{
    LubricationParameters p;
    p.viscosity = mu;
    p.innerCutoff = hIn;
    p.outerCutoff = hOuter;
    p.fade = fade;
    return Lubrication(p);
}

} // namespace


TEST(Lubrication, MatchesClosedFormAtSeveralGaps)
{
    const Lubrication lub = make();
    const double R1 = 0.15e-6, R2 = 0.6e-6;
    const double Rs = R1*R2/(R1 + R2);
    const double v = -1e-3;     // approaching [m/s]
    for (double h : {1e-9, 2e-9, 10e-9, 50e-9, 99e-9})
    {
        const double F = -6*pi*mu*Rs*Rs*v*(1/h - 1/hOut);
        EXPECT_NEAR(lub.force(R1, R2, h, v), F, 1e-12*std::fabs(F)) << "h = " << h;
        EXPECT_GT(lub.force(R1, R2, h, v), 0.0);            // repulsive approaching
        EXPECT_LT(lub.force(R1, R2, h, -v), 0.0);           // attractive separating
    }
    // below the inner cut-off: the gap is h_in
    const double Fin = -6*pi*mu*Rs*Rs*v*(1/hIn - 1/hOut);
    for (double h : {0.5e-9, 0.0, -3e-9})
    {
        EXPECT_NEAR(lub.force(R1, R2, h, v), Fin, 1e-12*Fin);
    }
    // beyond the outer cut-off: nothing
    EXPECT_EQ(lub.force(R1, R2, hOut, v), 0.0);
    EXPECT_EQ(lub.force(R1, R2, 3*hOut, v), 0.0);
}

TEST(Lubrication, ClassicalEqualSphereAndSpherePlaneLimits)
{
    // With h_out -> inf the kernel is the leading-order Reynolds result
    const Lubrication lub = make(1.0);
    const double R = 0.3e-6, v = -2e-3;
    for (double h : {2e-9, 20e-9})
    {
        const double Fss = -3*pi*mu*R*R*v/(2*h);
        EXPECT_NEAR(lub.force(R, R, h, v), Fss, 1e-6*std::fabs(Fss));
        const double Fsw = -6*pi*mu*R*R*v/h;
        EXPECT_NEAR(lub.force(R, wallRadius, h, v), Fsw, 1e-6*std::fabs(Fsw));
        // a wall is R* = R, four times the equal-sphere force (not R/4)
        EXPECT_NEAR(lub.force(R, wallRadius, h, v), 4*lub.force(R, R, h, v), 1e-12*std::fabs(Fsw));
        // large second sphere tends to the wall
        EXPECT_NEAR(lub.force(R, 1e5*R, h, v), Fsw, 3e-5*std::fabs(Fsw));
    }
}

TEST(Lubrication, SymmetricAndContinuousAtCutoffs)
{
    const Lubrication lub = make();
    const double R1 = 0.1e-6, R2 = 0.9e-6, v = -1e-3;
    for (double h : {0.5e-9, 5e-9, 50e-9})
    {
        EXPECT_NEAR(lub.force(R1, R2, h, v), lub.force(R2, R1, h, v), 1e-14*std::fabs(lub.force(R1, R2, h, v)));
    }
    const double Fin = lub.force(R1, R2, hIn, v);
    EXPECT_NEAR(lub.force(R1, R2, hIn*(1 + 1e-8), v), Fin, 2e-8*Fin);
    EXPECT_EQ(lub.force(R1, R2, hIn*(1 - 1e-8), v), Fin);
    // at h_out the resistance fades linearly in (h_out - h)/h_out^2
    const double Rs = R1*R2/(R1 + R2);
    const double dh = 1e-6*hOut;
    const double c = lub.resistance(R1, R2, hOut - dh);
    EXPECT_NEAR(c, 6*pi*mu*Rs*Rs*dh/(hOut*hOut), 1e-5*c);
    EXPECT_EQ(lub.resistance(R1, R2, hOut), 0.0);
}

// The faded form: the uncut Reynolds resistance 6 pi mu R*^2/h up to
// h_out/2, then times the smooth step w = 3y^2 - 2y^3 of y = (h_out - h)/
// (h_out/2), written out here
TEST(Lubrication, FadedFormKeepsTheNearFieldAndFadesSmoothly)
{
    const Lubrication lub = make(hOut, true);
    const double R1 = 0.15e-6, R2 = 0.6e-6;
    const double Rs = R1*R2/(R1 + R2);
    const double c0 = 6*pi*mu*Rs*Rs;
    // near field: uncut, also below the inner cut-off (gap h_in)
    for (double h : {1e-9, 3e-9, 20e-9, 49.99e-9, 50e-9})
    {
        EXPECT_NEAR(lub.resistance(R1, R2, h), c0/h, 1e-12*c0/h) << "h = " << h;
    }
    for (double h : {0.5e-9, 0.0, -2e-9})
    {
        EXPECT_NEAR(lub.resistance(R1, R2, h), c0/hIn, 1e-12*c0/hIn) << "h = " << h;
    }
    // the fade
    for (double h : {55e-9, 62.5e-9, 75e-9, 90e-9, 99e-9})
    {
        const double y = (hOut - h)/(0.5*hOut);
        const double c = c0/h*(3*y*y - 2*y*y*y);
        EXPECT_NEAR(lub.resistance(R1, R2, h), c, 1e-12*c) << "h = " << h;
    }
    EXPECT_NEAR(lub.resistance(R1, R2, 75e-9), 0.5*c0/75e-9, 1e-12*c0/75e-9);
    EXPECT_EQ(lub.resistance(R1, R2, hOut), 0.0);
    EXPECT_EQ(lub.resistance(R1, R2, 2*hOut), 0.0);
    // continuous with a continuous slope at h_out/2 and at h_out
    const double dh = 1e-6*hOut;
    const double h1 = 0.5*hOut;
    auto slope = [&](double a, double b)
    {
        return (lub.resistance(R1, R2, b) - lub.resistance(R1, R2, a))/(b - a);
    };
    EXPECT_NEAR(lub.resistance(R1, R2, h1 + dh), c0/h1, 1e-5*c0/h1);
    EXPECT_NEAR(slope(h1, h1 + dh), slope(h1 - dh, h1), 1e-4*c0/(h1*h1));
    EXPECT_NEAR(slope(hOut - 2*dh, hOut - dh), 0.0, 1e-4*c0/(h1*h1));
    // monotone: never more resistance at a larger gap
    double last = HUGE_VAL;
    for (int i = 0; i <= 1000; i++)
    {
        const double c = lub.resistance(R1, R2, hIn + (hOut - hIn)*i/1000.0);
        EXPECT_LE(c, last) << "i = " << i;
        last = c;
    }
    // a wall is R* = R, as in the shifted form
    EXPECT_NEAR(lub.resistance(R1, wallRadius, 20e-9), 6*pi*mu*R1*R1/20e-9, 1e-9*6*pi*mu*R1*R1/20e-9);
}

TEST(Lubrication, FadedFormNeedsItsNearFieldBeyondTheInnerCutoff)
{
    LubricationParameters p;
    p.viscosity = mu;
    p.innerCutoff = 2e-9;
    p.outerCutoff = 3e-9;
    EXPECT_NO_THROW(Lubrication l(p));
    p.fade = true;
    EXPECT_THROW(Lubrication l(p), std::invalid_argument);
    p.outerCutoff = 4.0001e-9;
    EXPECT_NO_THROW(Lubrication l(p));
}

TEST(Lubrication, RejectsBadParameters)
{
    LubricationParameters p;
    p.viscosity = -1;
    try
    {
        Lubrication l(p);
        FAIL() << "negative viscosity accepted";
    }
    catch (const std::invalid_argument& ex)
    {
        EXPECT_NE(std::string(ex.what()).find("viscosity"), std::string::npos);
    }
    p.viscosity = 1e-3;
    p.innerCutoff = 2e-9;
    p.outerCutoff = 1e-9;
    EXPECT_THROW(Lubrication l(p), std::invalid_argument);
}
