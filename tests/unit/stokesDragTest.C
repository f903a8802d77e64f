/*---------------------------------------------------------------------------*\
    Unit tests of stokesDrag.H.

    References: Stokes' law and the relaxation time written out here; the
    exact solution of m dv/dt = 3 pi mu d (u - v) + (m - m_f) g, which relaxes
    exponentially to the settling velocity; backward Euler's first order.
\*---------------------------------------------------------------------------*/
#include "constants.H"
#include "stokesDrag.H"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace colloid;

namespace
{

const double pi = constants::pi;
const double mu = 1e-3;
const double rhoF = 1000;
const double rhoP = 2500;
const double d = 0.3e-6;

StokesDrag make()
{
    StokesDragParameters p;
    p.viscosity = mu;
    p.fluidDensity = rhoF;
    return StokesDrag(p);
}

} // namespace


TEST(StokesDrag, ForceRelaxationTimeAndSettlingVelocity)
{
    const StokesDrag drag = make();
    const Vec3 u{{1e-3, -2e-3, 0}}, v{{0, 1e-3, 5e-4}};
    const Vec3 F = drag.force(d, u, v);
    for (int k = 0; k < 3; ++k)
    {
        const double ref = 3*pi*mu*d*(u[k] - v[k]);
        EXPECT_NEAR(F[k], ref, 1e-14*std::fabs(3*pi*mu*d*1e-3));
    }
    // tau = m/(3 pi mu d) for a sphere equals rho_p d^2/(18 mu)
    const double m = rhoP*pi*d*d*d/6;
    EXPECT_NEAR(drag.relaxationTime(rhoP, d), m/(3*pi*mu*d), 1e-12*drag.relaxationTime(rhoP, d));
    // settling: drag balances the buoyant weight
    const double g = 9.81;
    const double vs = drag.settlingVelocity(rhoP, d, g);
    EXPECT_NEAR(3*pi*mu*d*vs, (rhoP - rhoF)*pi*d*d*d/6*g, 1e-12*3*pi*mu*d*vs);
}

TEST(StokesDrag, ImplicitUpdateConvergesToExactRelaxationAndSettling)
{
    const StokesDrag drag = make();
    const double g = 9.81;
    const double m = rhoP*pi*d*d*d/6;
    const double weight = (m - rhoF*pi*d*d*d/6)*g;     // downwards, along -z
    const double tau = drag.relaxationTime(rhoP, d);
    const double vs = drag.settlingVelocity(rhoP, d, g);
    const Vec3 u{{0, 0, 0}};
    const double tEnd = 3*tau;
    // exact: v(t) = -vs (1 - exp(-t/tau)) from rest
    const double exact = -vs*(1 - std::exp(-tEnd/tau));
    double previousError = 0;
    for (int n : {25, 50, 100, 200})
    {
        const double dt = tEnd/n;
        Vec3 v{{0, 0, 0}};
        for (int i = 0; i < n; ++i)
        {
            const Vec3 Fo{{0, 0, -weight}};
            const Vec3 F = drag.implicitForce(d, m, dt, u, v, Fo);
            v[2] += (F[2] + Fo[2])*dt/m;
        }
        const double error = std::fabs(v[2] - exact);
        if (n > 25)
        {
            EXPECT_NEAR(std::log2(previousError/error), 1.0, 0.1) << "n = " << n;
        }
        previousError = error;
    }
    // stable at dt = 1e4 tau, where an explicit drag would diverge: the
    // distance to the settling velocity shrinks by 1/(1 + dt/tau) per step
    Vec3 v{{0, 0, 0}};
    const double dt = 1e4*tau;
    for (int i = 0; i < 5; ++i)
    {
        const Vec3 Fo{{0, 0, -weight}};
        const Vec3 F = drag.implicitForce(d, m, dt, u, v, Fo);
        v[2] += (F[2] + Fo[2])*dt/m;
        const double ref = -vs*(1 - std::pow(1 + dt/tau, -(i + 1)));
        EXPECT_NEAR(v[2], ref, 1e-12*vs) << "step " << i;
    }
}

TEST(StokesDrag, RejectsBadParameters)
{
    StokesDragParameters p;
    p.viscosity = 0;
    EXPECT_THROW(StokesDrag s(p), std::invalid_argument);
}
