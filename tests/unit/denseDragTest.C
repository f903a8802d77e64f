/*---------------------------------------------------------------------------*\
    Unit tests of denseDrag.H (drag among other particles).

    References written out here, independently of the kernel's algebra:
    Ergun's equation for the pressure drop of a fixed bed; Stokes' law for
    a lone sphere at vanishing Reynolds number; Newton's Cd = 0.44; Di
    Felice's exponent chi = 3.05 at its peak Re = 10^1.5; the low-Re lattice
    Boltzmann fit of van der Hoef et al. (2005) that Beetstra's law reduces
    to as Re -> 0.
\*---------------------------------------------------------------------------*/
#include "constants.H"
#include "denseDrag.H"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace colloid;

namespace
{

const double pi = constants::pi;
const double mu = 1e-3;
const double rho = 1000;
const double d = 5.8e-6;

DenseDragState state(double eps, double slip)
{
    DenseDragState s{d, eps, slip, rho, mu};
    s.check();
    return s;
}

// Ergun (1952): pressure gradient [Pa/m] of a fixed bed at superficial
// velocity Us
double ergunGradient(double eps, double Us)
{
    const double phi = 1 - eps;
    return 150*mu*phi*phi*Us/(eps*eps*eps*d*d)
         + 1.75*rho*phi*Us*Us/(eps*eps*eps*d);
}

} // namespace


// A fixed bed in steady flow: eps grad p = beta u with u = Us/eps (the
// Model A momentum balance of the fluid), so grad p = beta Us/eps^2 must
// be Ergun's gradient, from creeping to inertial flow
TEST(GidaspowDrag, FixedBedGivesErgunPressureDrop)
{
    for (double eps : {0.36, 0.4, 0.5, 0.7, 0.79})
    {
        for (double Re : {1e-3, 0.1, 1.0, 10.0, 100.0})
        {
            const double Us = Re*mu/(rho*d);
            const DenseDragState s = state(eps, Us/eps);
            const double grad = GidaspowDrag::beta(s)*Us/(eps*eps);
            const double ref = ergunGradient(eps, Us);
            EXPECT_NEAR(grad, ref, 1e-12*ref) << "eps " << eps << " Re " << Re;
            // Per particle: beta = (1 - eps) K/V_p
            EXPECT_NEAR
            (
                (1 - eps)*GidaspowDrag::coefficient(s)/s.volume(),
                GidaspowDrag::beta(s),
                1e-12*GidaspowDrag::beta(s)
            );
        }
    }
}


TEST(GidaspowDrag, SwitchesToWenYuAtPointEight)
{
    const double slip = 1e-3;
    const double below = GidaspowDrag::coefficient(state(0.8 - 1e-12, slip));
    const double at = GidaspowDrag::coefficient(state(0.8, slip));
    const DenseDragState s = state(0.8, slip);
    const double Re = s.Re();
    const double Cd = 24/Re*(1 + 0.15*std::pow(Re, 0.687));
    const double wenYu =
        0.75*Cd*0.8*0.2*rho*slip*std::pow(0.8, -2.65)/d*s.volume()/0.2;
    EXPECT_NEAR(at, wenYu, 1e-12*wenYu);
    const double ergun =
        s.volume()*(150*0.2*mu/(0.8*d*d) + 1.75*rho*slip/d);
    EXPECT_NEAR(below, ergun, 1e-9*ergun);
}


TEST(DenseDrag, LoneSphereAtLowReynoldsIsStokes)
{
    const double stokes = 3*pi*mu*d;
    for (double slip : {0.0, 1e-9, 1e-7})
    {
        const DenseDragState s = state(1.0, slip);
        EXPECT_NEAR(GidaspowDrag::coefficient(s), stokes, 2e-4*stokes);
        EXPECT_NEAR(BeetstraDrag::coefficient(s), stokes, 2e-4*stokes);
        // Di Felice's Cd = (0.63 + 4.8/sqrt(Re))^2 -> 23.04/Re: 0.96 Stokes
        EXPECT_NEAR(DiFeliceDrag::coefficient(s), 0.96*stokes, 1e-3*stokes);
    }
    // Exactly at slip = 0: the Re -> 0 limits, no division by zero
    EXPECT_DOUBLE_EQ(GidaspowDrag::coefficient(state(1.0, 0)), stokes);
    EXPECT_DOUBLE_EQ(BeetstraDrag::coefficient(state(1.0, 0)), stokes);
}


TEST(GidaspowDrag, NewtonRegimeAtHighReynolds)
{
    // Re > 1000: Cd = 0.44; per particle F = beta V_p slip/(1 - eps)
    // = 1/2 Cd rho (pi d^2/4) slip^2 eps^-1.65
    const double eps = 0.9;
    const double slip = 2000*mu/(rho*eps*d);
    const DenseDragState s = state(eps, slip);
    const double F = GidaspowDrag::coefficient(s)*slip;
    const double ref =
        0.75*0.44*eps*(1 - eps)*rho*slip*std::pow(eps, -2.65)/d
       *slip*s.volume()/(1 - eps);
    EXPECT_NEAR(F, ref, 1e-12*ref);
    EXPECT_NEAR(F, 0.5*0.44*rho*pi*d*d/4*slip*slip*std::pow(eps, -1.65),
        1e-12*ref);
}


TEST(DiFeliceDrag, ExponentAndCoefficient)
{
    EXPECT_NEAR(DiFeliceDrag::chi(std::pow(10.0, 1.5)), 3.05, 1e-12);
    EXPECT_NEAR(DiFeliceDrag::chi(1e-6), 3.7, 1e-5);
    // Re = 1 at eps = 0.6: Cd = 5.43^2, F = 1/2 Cd rho A eps^2 slip^2 eps^-chi
    const double eps = 0.6;
    const double slip = mu/(rho*eps*d);
    const DenseDragState s = state(eps, slip);
    const double chi = 3.7 - 0.65*std::exp(-0.5*1.5*1.5);
    const double ref = 0.5*5.43*5.43*rho*pi*d*d/4*eps*eps*slip*slip
        *std::pow(eps, -chi);
    EXPECT_NEAR(DiFeliceDrag::coefficient(s)*slip, ref, 1e-12*ref);
}


TEST(BeetstraDrag, LowReynoldsLimitIsVanDerHoefFit)
{
    for (double phi : {0.1, 0.3, 0.5, 0.6})
    {
        const double eps = 1 - phi;
        const double ref =
            10*phi/(eps*eps) + eps*eps*(1 + 1.5*std::sqrt(phi));
        EXPECT_NEAR(BeetstraDrag::dimensionlessForce(eps, 1e-9), ref,
            1e-4*ref);
        EXPECT_NEAR
        (
            BeetstraDrag::coefficient(state(eps, 0)),
            3*pi*mu*d*eps*ref,
            1e-12*3*pi*mu*d*eps*ref
        );
    }
    // Rises with Re (inertial term) and stays finite
    EXPECT_GT(BeetstraDrag::dimensionlessForce(0.6, 100),
              BeetstraDrag::dimensionlessForce(0.6, 1));
}


TEST(DenseDrag, RejectsBadState)
{
    EXPECT_THROW(state(0.0, 1e-3), std::invalid_argument);
    EXPECT_THROW(state(1.2, 1e-3), std::invalid_argument);
    EXPECT_THROW(state(0.5, -1), std::invalid_argument);
}
