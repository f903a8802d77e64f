/*---------------------------------------------------------------------------*\
    Unit tests of timeStepLimits.H for the seed-000/001 particle: a 0.3 um
    glass sphere (rho = 2500 kg/m^3) in water (mu = 1e-3 Pa s).

    References: hand-computed values (arithmetic in the comments) and the
    period of the linear oscillator, integrated here.
        d = 0.3e-6 m, d^2 = 9e-14 m^2, d^3 = 2.7e-20 m^3
        m = rho pi d^3/6 = 2500*3.14159*2.7e-20/6 = 3.5343e-17 kg
        m* (two equal spheres) = 1.7671e-17 kg; R* = 0.075e-6 m
\*---------------------------------------------------------------------------*/
#include "constants.H"
#include "timeStepLimits.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace colloid;

namespace
{

const double pi = constants::pi;
const double d = 0.3e-6;
const double m = 2500*pi*d*d*d/6;
const double mStar = m/2;
const double Rs = 0.075e-6;

} // namespace


TEST(TimeStepLimits, HandComputedValuesForSubmicronGlassInWater)
{
    // mass: 3.5343e-17 kg
    EXPECT_NEAR(m, 3.5343e-17, 1e-4*3.5343e-17);
    // tau = 2500*9e-14/(18*1e-3) = 2.25e-10/0.018 = 1.25e-8 s (seed 001: ~1e-8 s)
    EXPECT_NEAR(timeStep::stokesRelaxationTime(2500, d, 1e-3), 1.25e-8, 1e-9*1.25e-8);
    // seed 002 eq 12 with k = 10 N/m: sqrt(3.5343e-17/10) = 1.8800e-9 s
    EXPECT_NEAR(timeStep::springTime(m, 10), 1.8800e-9, 1e-4*1.8800e-9);
    // linear contact, k = 10 N/m: pi sqrt(1.7671e-17/10) = pi*1.3293e-9 = 4.1762e-9 s
    EXPECT_NEAR(timeStep::linearContactTime(mStar, 10), 4.1762e-9, 1e-4*4.1762e-9);
    // Walton-Braun K1 = 10, K2 = 10/0.8^2 = 15.625:
    // pi/2 (1.3293e-9 + sqrt(1.7671e-17/15.625) = 1.0635e-9) = 3.7586e-9 s
    EXPECT_NEAR(timeStep::waltonBraunContactTime(mStar, 10, 15.625), 3.7586e-9, 2e-4*3.7586e-9);
    // vdW spring at h0 = 0.4 nm, A = 4.3e-21 J (glass, seed 002 table 1):
    // k = 4.3e-21*0.075e-6/(3*6.4e-29) = 3.225e-28/1.92e-28 = 1.6797 N/m
    const double kv = timeStep::vanDerWaalsStiffness(4.3e-21, Rs, 0.4e-9);
    EXPECT_NEAR(kv, 1.6797, 1e-4*1.6797);
    // and its spring time sqrt(1.7671e-17/1.6797) = 3.2435e-9 s
    EXPECT_NEAR(timeStep::springTime(mStar, kv), 3.2435e-9, 2e-4*3.2435e-9);
}

TEST(TimeStepLimits, ContactTimeIsHalfTheOscillatorPeriod)
{
    // integrate m x'' = -k x from x = 0, x' = 1 with RK4 until x returns to 0
    const double k = 7.0;
    const double tc = timeStep::linearContactTime(mStar, k);
    const double dt = 1e-4*tc;
    double x = 0, v = 1, t = 0;
    while (true)
    {
        auto a = [&](double xs) { return -k*xs/mStar; };
        const double k1x = v, k1v = a(x);
        const double k2x = v + 0.5*dt*k1v, k2v = a(x + 0.5*dt*k1x);
        const double k3x = v + 0.5*dt*k2v, k3v = a(x + 0.5*dt*k2x);
        const double k4x = v + dt*k3v, k4v = a(x + dt*k3x);
        const double xn = x + dt/6*(k1x + 2*k2x + 2*k3x + k4x);
        if (xn < 0)
        {
            t += dt*x/(x - xn);
            break;
        }
        v += dt/6*(k1v + 2*k2v + 2*k3v + k4v);
        x = xn;
        t += dt;
    }
    EXPECT_NEAR(t, tc, 1e-6*tc);
}

TEST(TimeStepLimits, HertzContactTimeMatchesTheUsualApproximation)
{
    // 2.87 (m*^2/(R* E*^2 v))^(1/5), a rounded form of the same result
    const double Es = 3e10, v = 0.1;
    const double tc = timeStep::hertzContactTime(mStar, Rs, Es, v);
    const double approx = 2.87*std::pow(mStar*mStar/(Rs*Es*Es*v), 0.2);
    EXPECT_NEAR(tc, approx, 1e-3*approx);
}
