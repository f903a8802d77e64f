/*---------------------------------------------------------------------------*\
    Unit tests of lubrication.H.

    References: Reynolds' squeeze-film results written out here (equal
    spheres 3 pi mu R^2 v/(2h), sphere-plane 6 pi mu R^2 v/h); the exact
    exponential decay of the relative velocity under a constant resistance.
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

Lubrication make(double hOuter = hOut)
{
    LubricationParameters p;
    p.viscosity = mu;
    p.innerCutoff = hIn;
    p.outerCutoff = hOuter;
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

TEST(Lubrication, ImplicitUpdateIsBackwardEulerAndNeverReversesVelocity)
{
    const Lubrication lub = make();
    const double R = 0.15e-6;
    const double m = 2500*pi/6*std::pow(2*R, 3);
    const double mStar = m/2;
    const double v = -1e-3;
    const double c = lub.resistance(R, R, hIn);
    for (double a : {1e-3, 1.0, 1e2, 1e4, 1e6})
    {
        const double dt = a*mStar/c;
        const double F = lub.implicitForce(R, R, hIn, v, mStar, dt);
        const double vNew = v + F*dt/mStar;     // explicit application
        EXPECT_NEAR(vNew, v/(1 + a), 1e-12*std::fabs(v)) << "c dt/m* = " << a;
        EXPECT_GE(vNew/v, 0.0) << "velocity reversed at c dt/m* = " << a;
        EXPECT_LE(std::fabs(vNew), std::fabs(v));
    }
}

TEST(Lubrication, ImplicitUpdateConvergesFirstOrderToExponentialDecay)
{
    // Constant gap: m* dv/dt = -c v, v(t) = v0 exp(-c t/m*)
    const Lubrication lub = make();
    const double R = 0.15e-6, h = 5e-9;
    const double mStar = 2500*pi/6*std::pow(2*R, 3)/2;
    const double c = lub.resistance(R, R, h);
    const double v0 = -1e-3;
    const double tEnd = 2*mStar/c;
    const double exact = v0*std::exp(-c*tEnd/mStar);
    double previousError = 0;
    for (int n : {20, 40, 80, 160, 320})
    {
        const double dt = tEnd/n;
        double v = v0;
        for (int i = 0; i < n; ++i)
        {
            v += lub.implicitForce(R, R, h, v, mStar, dt)*dt/mStar;
        }
        const double error = std::fabs(v - exact);
        if (n > 20)
        {
            // first order: halving dt halves the error (order 1 within 5 %)
            const double order = std::log2(previousError/error);
            EXPECT_NEAR(order, 1.0, 0.05) << "n = " << n;
        }
        previousError = error;
    }
    // and the error itself is small at the finest step: ~ (c dt/m*)/2 relative
    EXPECT_LT(previousError, 0.01*std::fabs(exact));
}

namespace
{

// A sphere (radius R, mass m) pulled at a wall by a constant force F0 (as
// van der Waals would), the lubrication film resisting, stepped with the
// pairwise implicit update and symplectic Euler. Returns the time to go
// from gap hStart to hEnd; fails the test on a reversal or an overshoot of
// the overdamped drift -F0/c(h).
double approachTime(const Lubrication& lub, double R, double m, double F0, double dt, double hStart, double hEnd)
{
    double h = hStart, v = 0, t = 0;
    while (h > hEnd)
    {
        const double F = lub.implicitForce(R, wallRadius, h, v, m, dt, -F0) - F0;
        const double vNew = v + F*dt/m;
        EXPECT_TRUE(std::isfinite(vNew));
        EXPECT_LE(vNew, 0.0) << "sphere moved away from the wall at h = " << h;
        // backward Euler relaxes v monotonically towards the drift -F0/c(h):
        // the new velocity lies between the old one and the drift
        const double drift = -F0/lub.resistance(R, wallRadius, h);
        const double tol = 1e-12*std::fabs(drift);
        EXPECT_LE(vNew, std::max(v, drift) + tol) << "overshoot at h = " << h;
        EXPECT_GE(vNew, std::min(v, drift) - tol) << "overshoot at h = " << h;
        if (vNew > 0 || !std::isfinite(vNew)) return -1;
        v = vNew;
        const double hNew = h + v*dt;
        if (hNew <= hEnd)
        {
            return t + (h - hEnd)/(-v);     // last partial step
        }
        h = hNew;
        t += dt;
    }
    return t;
}

} // namespace


TEST(Lubrication, DrivenAtWallApproachTimeMatchesOverdampedSolution)
{
    // Overdamped (m/c ~ 1e-10 s << approach time ~ 1e-4 s):
    // c(h) dh/dt = -F0 -> t = 6 pi mu R^2 [ln(h1/h2) - (h1 - h2)/h_out]/F0
    const Lubrication lub = make();
    const double R = 0.15e-6;
    const double m = 2500*pi/6*std::pow(2*R, 3);
    const double F0 = 1e-11;
    const double h1 = 50e-9, h2 = 2e-9;
    const double exact = 6*pi*mu*R*R*(std::log(h1/h2) - (h1 - h2)/hOut)/F0;
    // c dt/m* reaches ~1e3 near h2: a fully explicit update would blow up
    const double dt = exact/4000;
    ASSERT_GT(lub.resistance(R, wallRadius, h2)*dt/m, 100.0);
    const double t = approachTime(lub, R, m, F0, dt, h1, h2);
    EXPECT_NEAR(t, exact, 0.01*exact);
}

TEST(Lubrication, DrivenAtWallStaysStableAtHugeStiffness)
{
    // dt with c(h_in) dt/m* = 1e6 and a weak pull, so that hundreds of
    // steps are taken between 3 h_in and h_in at c dt/m* ~ 3e5..1e6: no
    // reversal, no overshoot of the drift, and the approach time still
    // matches the overdamped solution (first-order error ~ the relative
    // gap change per step, < 1 %)
    const Lubrication lub = make();
    const double R = 0.15e-6;
    const double m = 2500*pi/6*std::pow(2*R, 3);
    const double F0 = 5e-14;
    const double dt = 1e6*m/lub.resistance(R, wallRadius, hIn);
    const double h1 = 3*hIn, h2 = hIn;
    const double exact = 6*pi*mu*R*R*(std::log(h1/h2) - (h1 - h2)/hOut)/F0;
    ASSERT_GT(exact/dt, 100.0);
    const double t = approachTime(lub, R, m, F0, dt, h1, h2);
    EXPECT_NEAR(t, exact, 0.02*exact);
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
