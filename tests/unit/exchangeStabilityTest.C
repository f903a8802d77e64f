/*---------------------------------------------------------------------------*\
    Unit tests of exchangeStability.H, the fluid-step limit of the explicit
    two-way exchange.

    References:
    - the exchange stepped here term by term as the solver takes it, for
      a layer of particles (mass 1, drag coefficient 1, so tau = 1) and
      its fluid in one dimension: the DEM interval with the DEM's
      trapezoidal implicit drag in 1000 steps, its drag impulse and
      displacement summed; the fluid step from the mixture's continuity
      with that displacement, the momentum balance of averagedFluid (the
      impulse handed over, Kexchange U^n, the implicit term given back a
      step later, Euler's fluid inertia) solved for the pressure gradient,
      which the next interval's particles feel (Model A).  Its growth per
      fluid step over thousands of steps;
    - Model B's two-by-two map in closed form (the roots of
      lambda^2 - T lambda + D = 0) and its large-step limit
      -(1 - eps)/eps.
\*---------------------------------------------------------------------------*/
#include "exchangeStability.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>

using namespace colloid::exchangeStability;

namespace
{

//- Growth per fluid step of the exchange stepped directly: the ratio of
//  the state's norm over the second half of nSteps fluid steps, per step.
//  h = fluid step/tau, tau the particle's relaxation time (m/K; Model B,
//  whose drag is K/eps: eps m/K), r = rho_f/rho_p.  Model A per particle
//  and per unit of K: n K = beta, n V = 1 - eps.
double simulatedGrowth(double eps, double h, bool modelB, double r, int nSteps)
{
    const int nSub = 1000;              // DEM steps per fluid step
    const double x = h/nSub;            // DEM step/tau
    const double phi = 1 - eps;

    // An arbitrary disturbance (the steady flow subtracted: q = 0)
    double v = 0.4;                     // particle velocity
    double U = -0.3;                    // fluid velocity of the last step
    double given = 0.1;                 // implicit term to give back / (n K)
    double gradpForce = modelB ? 0 : 0.2;   // -V grad p/K of the last step
    double logNorm = 0, logNormHalf = 0;
    for (int k = 0; k < nSteps; ++k)
    {
        // DEM interval with the last fluid step's U and pressure force
        double impulse = 0, displacement = 0;
        for (int i = 0; i < nSub; ++i)
        {
            const double vNew =
                (v*(1 - 0.5*x) + x*(U + gradpForce))/(1 + 0.5*x);
            impulse += x*(U - 0.5*(v + vNew));
            displacement += 0.5*x*(v + vNew);
            v = vNew;
        }
        const double vbar = displacement/h;

        // Fluid step: continuity of the mixture, eps U + phi vbar = 0
        const double UOld = U;
        U = -phi*vbar/eps;
        if (!modelB)
        {
            // Momentum per unit volume, divided by n K:
            // (rho_f eps/(n K)) (U - UOld)/dt + U
            //   = -impulse/h + UOld + given - eps grad p/(n K)
            // with rho_f eps/(n K dt) = r eps/(phi h)
            const double epsGradp =
                -impulse/h + UOld + given - U - r*eps/(phi*h)*(U - UOld);
            // -V grad p/K = -(n V/eps) (eps grad p/(n K))
            gradpForce = -phi/eps*epsGradp;
        }
        given = U - UOld;

        // Renormalise so that nothing overflows
        const double n = std::sqrt
        (
            v*v + U*U + given*given + gradpForce*gradpForce
        );
        v /= n; U /= n; given /= n; gradpForce /= n;
        logNorm += std::log(n);
        if (k + 1 == nSteps/2)
        {
            logNormHalf = logNorm;
        }
    }
    return std::exp((logNorm - logNormHalf)/(nSteps - nSteps/2));
}


//- Model B's spectral radius in closed form: the map of (vbar, vEnd) is
//  [[-a (1 - c), c], [-a (1 - E), E]], a = (1 - eps)/eps, c = (1 - E)/h
double modelBRadius(double eps, double h)
{
    const double a = (1 - eps)/eps;
    const double E = std::exp(-h);
    const double c = (1 - E)/h;
    const double T = E - a*(1 - c);
    const double D = a*(c - E);
    const std::complex<double> root = std::sqrt(std::complex<double>(T*T - 4*D));
    return std::max(std::abs(0.5*(T + root)), std::abs(0.5*(T - root)));
}

const double rGlassWater = 0.4;     // 1000/2500

} // namespace


TEST(ExchangeStability, ModelBAgreesWithItsClosedForm)
{
    for (double eps : {0.3, 0.45, 0.6, 0.9})
    {
        for (double h : {0.01, 0.3, 1.0, 3.0, 30.0})
        {
            // Model B's particles feel no pressure: r plays no part
            EXPECT_NEAR
            (
                amplification(eps, h, true, rGlassWater),
                modelBRadius(eps, h),
                1e-9
            ) << "eps " << eps << ", h " << h;
        }
    }
    // Large steps: the particles take the fluid's velocity, which the
    // mixture's continuity sets to -(1 - eps)/eps of their last one
    EXPECT_NEAR(amplification(0.4, 1e7, true, 0), 1.5, 1e-5);
    EXPECT_NEAR(amplification(0.8, 1e7, true, 0), 0.25, 1e-5);
}


TEST(ExchangeStability, AmplificationIsThatOfTheExchangeSteppedDirectly)
{
    for (bool modelB : {false, true})
    {
        for (double r : {0.0, rGlassWater, 1.0})
        {
            for (double eps : {0.45, 0.55, 0.7})
            {
                for (double h : {0.2, 1.0, 3.0})
                {
                    // the trapezoidal DEM steps against the exponential:
                    // about (h/nSub)^2 in the decay
                    EXPECT_NEAR
                    (
                        simulatedGrowth(eps, h, modelB, r, 2000),
                        amplification(eps, h, modelB, r),
                        5e-3
                    ) << "eps " << eps << ", h " << h << ", r " << r
                      << ", Model " << (modelB ? 'B' : 'A');
                }
            }
        }
    }
}


TEST(ExchangeStability, CriticalStepSeparatesDecayFromGrowth)
{
    // At 0.95 and 1.05 of the critical step the directly stepped exchange
    // decays and grows, for layers where the limit binds
    for (bool modelB : {false, true})
    {
        for (double eps : {looseFluidFraction, 0.47})
        {
            const double hc = criticalStepRatio(eps, modelB, rGlassWater);
            ASSERT_TRUE(std::isfinite(hc) && hc > 0) << eps;
            EXPECT_LT(simulatedGrowth(eps, 0.95*hc, modelB, rGlassWater, 6000), 1)
                << "eps " << eps << ", Model " << (modelB ? 'B' : 'A');
            EXPECT_GT(simulatedGrowth(eps, 1.05*hc, modelB, rGlassWater, 6000), 1)
                << "eps " << eps << ", Model " << (modelB ? 'B' : 'A');
        }
    }
}


TEST(ExchangeStability, DiluteLayersAreStableAtAnyStep)
{
    // Model B at large steps: |lambda| = (1 - eps)/eps < 1 above eps = 0.5
    EXPECT_TRUE(std::isinf(criticalStepRatio(0.6, true, rGlassWater)));
    EXPECT_TRUE(std::isfinite(criticalStepRatio(0.45, true, rGlassWater)));
    // Model A, with the given-back term, is stable from 0.75 up, also for
    // particles as light as the fluid and lighter
    EXPECT_TRUE(std::isinf(criticalStepRatio(0.76, false, rGlassWater)));
    EXPECT_TRUE(std::isinf(criticalStepRatio(0.76, false, 1)));
    EXPECT_TRUE(std::isinf(criticalStepRatio(0.76, false, 3)));
    EXPECT_TRUE(std::isfinite(criticalStepRatio(0.74, false, rGlassWater)));
    // and is at large steps as stepped directly: decaying at 0.76,
    // growing at 0.74
    EXPECT_LT(simulatedGrowth(0.76, 200, false, rGlassWater, 2000), 1);
    EXPECT_GT(simulatedGrowth(0.74, 200, false, rGlassWater, 2000), 1);
}


TEST(ExchangeStability, FluidInertiaShortensTheLimit)
{
    // The fluid's acceleration, carried onto the particles by the pressure
    // gradient a step late, acts as an added mass: the lighter the
    // particles against the fluid, the shorter the stable step
    const double h0 = criticalStepRatio(looseFluidFraction, false, 0);
    const double hGlass = criticalStepRatio(looseFluidFraction, false, 0.4);
    const double hNeutral = criticalStepRatio(looseFluidFraction, false, 1);
    EXPECT_LT(hGlass, 0.9*h0);
    EXPECT_LT(hNeutral, 0.9*hGlass);
    // and a dense layer of neutrally buoyant particles is unstable at any
    // step, here at 1e-3 relaxation times as stepped directly
    EXPECT_EQ(criticalStepRatio(0.3, false, 1), 0);
    EXPECT_GT(simulatedGrowth(0.3, 1e-3, false, 1, 4000), 1);
}


TEST(ExchangeStability, LimitIsTheSmallestOverTheFreeLayers)
{
    // With the relaxation time of Ergun's viscous drag, tau proportional
    // to eps/(1 - eps), the densest free layer sets the limit
    const double tau0 = 5.6e-7;     // rho_p d^2/(150 mu), 5.8 um glass [s]
    const auto tau = [&](double eps) { return tau0*eps/(1 - eps); };
    const StepLimit limit = largestStableStep(tau, false, rGlassWater);
    EXPECT_NEAR(limit.eps, looseFluidFraction, 1e-12);
    EXPECT_NEAR
    (
        limit.step,
        criticalStepRatio(looseFluidFraction, false, rGlassWater)
       *tau(looseFluidFraction),
        1e-12
    );
    // and no free layer is unstable at 0.99 of it
    for (double eps = looseFluidFraction; eps < 1; eps += 0.01)
    {
        EXPECT_LE
        (
            amplification(eps, 0.99*limit.step/tau(eps), false, rGlassWater),
            1 + 1e-9
        ) << eps;
    }
}


TEST(ExchangeStability, FreeFluidFractionBoundsTheLayers)
{
    const double tau0 = 5.6e-7;
    const auto tau = [&](double eps) { return tau0*eps/(1 - eps); };
    // From 0.6 up the densest free layer, 0.6, sets a longer limit
    const StepLimit from06 = largestStableStep(tau, false, rGlassWater, 0.6);
    EXPECT_NEAR(from06.eps, 0.6, 1e-12);
    EXPECT_NEAR
    (
        from06.step,
        criticalStepRatio(0.6, false, rGlassWater)*tau(0.6),
        1e-12
    );
    EXPECT_GT(from06.step, 2*largestStableStep(tau, false, rGlassWater).step);
    // From 0.75 (Model A) and 0.52 (Model B) up no step is too long
    EXPECT_TRUE(std::isinf(largestStableStep(tau, false, rGlassWater, 0.75).step));
    EXPECT_TRUE(std::isinf(largestStableStep(tau, true, rGlassWater, 0.52).step));
    EXPECT_TRUE(std::isinf(largestStableStep(tau, false, rGlassWater, 1.0).step));
}
