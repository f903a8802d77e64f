/*---------------------------------------------------------------------------*\
    Unit tests of the Walton-Braun normal model (waltonBraun.H).

    References: the piecewise-linear loading/unloading law written out here;
    for a free binary collision the analytic restitution sqrt(K1/K2) and
    duration pi/2 sqrt(m* /K1) + pi/2 sqrt(m* /K2), against which the 1-D
    collision ODE is integrated with classical RK4 at a step of 1e-4 of the
    contact time.
\*---------------------------------------------------------------------------*/
#include "constants.H"
#include "waltonBraun.H"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace colloid;

namespace
{

const double pi = constants::pi;

WaltonBraunNormal make(double K1, double e)
{
    WaltonBraunNormalParameters p;
    p.loadingStiffness = K1;
    p.restitution = e;
    return WaltonBraunNormal(p);
}

struct Collision
{
    double restitution;
    double duration;
};

// Head-on collision of a pair of reduced mass mStar arriving at speed v0:
// mStar d2(delta)/dt2 = -F(delta), delta(0) = 0, d(delta)/dt(0) = v0.
// RK4; the stage evaluations use a copy of the contact history so that only
// accepted steps update the maximum overlap. The exit time and speed are
// found by cubic Hermite interpolation across the last step.
// Returns the restitution (exit/entry speed) and the duration of the force.
Collision collide(const WaltonBraunNormal& wb, double mStar, double v0, double dt)
{
    WaltonBraunNormalState state;
    double x = 0, v = v0, t = 0;
    auto acc = [&](double xs)
    {
        WaltonBraunNormalState trial = state;
        return -wb.force(xs, trial)/mStar;
    };
    for (long i = 0; i < 100000000; ++i)
    {
        const double k1x = v, k1v = acc(x);
        const double k2x = v + 0.5*dt*k1v, k2v = acc(x + 0.5*dt*k1x);
        const double k3x = v + 0.5*dt*k2v, k3v = acc(x + 0.5*dt*k2x);
        const double k4x = v + dt*k3v, k4v = acc(x + dt*k3x);
        const double xn = x + dt/6*(k1x + 2*k2x + 2*k3x + k4x);
        const double vn = v + dt/6*(k1v + 2*k2v + 2*k3v + k4v);
        // The force ends where the unloading line reaches zero, at
        // delta_0 = delta_max (1 - K1/K2) > 0 (the surfaces then fly apart
        // at constant speed while still overlapping geometrically).
        const double d0 = state.maxOverlap*(1 - wb.loadingStiffness()/wb.unloadingStiffness());
        if (xn <= d0 && t > 0)
        {
            // Hermite cubic for x on [t, t+dt]: find the root by bisection
            auto hx = [&](double s)
            {
                const double s2 = s*s, s3 = s2*s;
                return (2*s3 - 3*s2 + 1)*x + (s3 - 2*s2 + s)*dt*v
                     + (-2*s3 + 3*s2)*xn + (s3 - s2)*dt*vn - d0;
            };
            auto hv = [&](double s)
            {
                const double s2 = s*s;
                return ((6*s2 - 6*s)*x + (3*s2 - 4*s + 1)*dt*v
                      + (-6*s2 + 6*s)*xn + (3*s2 - 2*s)*dt*vn)/dt;
            };
            double lo = 0, hi = 1;
            for (int k = 0; k < 100; ++k)
            {
                const double mid = 0.5*(lo + hi);
                (hx(mid) > 0 ? lo : hi) = mid;
            }
            return {-hv(lo)/v0, t + lo*dt};
        }
        x = xn;
        v = vn;
        t += dt;
        wb.force(x, state);     // accept: update the history
    }
    return {NAN, NAN};
}

} // namespace


TEST(WaltonBraunNormal, LoadingUnloadingReloadingPath)
{
    const double K1 = 100, e = 0.6;
    const WaltonBraunNormal wb = make(K1, e);
    const double K2 = K1/(e*e);
    EXPECT_NEAR(wb.unloadingStiffness(), K2, 1e-12*K2);
    WaltonBraunNormalState s;
    // loading along K1
    for (double d : {1e-9, 5e-9, 10e-9})
    {
        EXPECT_NEAR(wb.force(d, s), K1*d, 1e-12*K1*d);
    }
    EXPECT_EQ(s.maxOverlap, 10e-9);
    // unloading along K2 from (dmax, K1 dmax)
    const double dmax = 10e-9;
    const double d0 = dmax*(1 - K1/K2);
    for (double d : {9e-9, 7e-9, d0 + 1e-10})
    {
        EXPECT_NEAR(wb.force(d, s), K2*(d - d0), 1e-9*K1*dmax);
    }
    // no tension below d0
    EXPECT_EQ(wb.force(0.5*d0, s), 0.0);
    // reloading along K2 up to dmax, then along K1 again
    EXPECT_NEAR(wb.force(9.5e-9, s), K2*(9.5e-9 - d0), 1e-9*K1*dmax);
    EXPECT_NEAR(wb.force(12e-9, s), K1*12e-9, 1e-12*K1*12e-9);
    EXPECT_EQ(s.maxOverlap, 12e-9);
    // separation resets the history
    EXPECT_EQ(wb.force(-1e-9, s), 0.0);
    EXPECT_EQ(s.maxOverlap, 0.0);
}

TEST(WaltonBraunNormal, CollisionRestitutionAndDurationMatchTheory)
{
    // a 0.3 um glass sphere against an equal one
    const double m = 2500*pi/6*std::pow(0.3e-6, 3);
    const double mStar = m/2;
    for (double e : {0.3, 0.7, 0.95, 1.0})
    {
        for (double v0 : {1e-3, 1.0})
        {
            const double K1 = 10.0;     // [N/m]
            const WaltonBraunNormal wb = make(K1, e);
            const double K2 = K1/(e*e);
            const double tc = pi/2*(std::sqrt(mStar/K1) + std::sqrt(mStar/K2));
            const Collision c = collide(wb, mStar, v0, 1e-4*tc);
            // restitution sqrt(K1/K2) = e, duration analytic; 1e-6 relative
            EXPECT_NEAR(c.restitution, std::sqrt(K1/K2), 1e-6) << "e = " << e << " v0 = " << v0;
            EXPECT_NEAR(c.duration, tc, 1e-6*tc) << "e = " << e << " v0 = " << v0;
        }
    }
}

TEST(WaltonBraunNormal, RejectsBadParameters)
{
    WaltonBraunNormalParameters p;
    p.loadingStiffness = 10;
    p.restitution = 1.5;
    try
    {
        WaltonBraunNormal wb(p);
        FAIL() << "restitution 1.5 accepted";
    }
    catch (const std::invalid_argument& ex)
    {
        EXPECT_NE(std::string(ex.what()).find("restitution"), std::string::npos);
    }
    p.restitution = 0;
    EXPECT_THROW(WaltonBraunNormal wb(p), std::invalid_argument);
    p.restitution = 0.5;
    p.loadingStiffness = -1;
    EXPECT_THROW(WaltonBraunNormal wb(p), std::invalid_argument);
}
