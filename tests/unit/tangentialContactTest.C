/*---------------------------------------------------------------------------*\
    Unit tests of the tangential contact models: Walton-Braun incremental
    slip (waltonBraun.H) and Di Renzo-Di Maio (diRenzoDiMaio.H).

    References: the closed-form solutions of Walton's stiffness law under
    monotonic loading, dT/ds = K_T0 (1 - (T - T*)/(mu N - T*))^(1/3), which
    integrates to
        T(s) = T* + (mu N - T*)[1 - (1 - 2 K_T0 s/(3 (mu N - T*)))^(3/2)]
    (full slip at s = 3 (mu N - T*)/(2 K_T0)), and its mirror image after a
    reversal; Coulomb's limit; Di Renzo & Di Maio's (2/3) 8 G* sqrt(R* delta)
    stiffness.
\*---------------------------------------------------------------------------*/
#include "diRenzoDiMaio.H"
#include "waltonBraun.H"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace colloid;

namespace
{

WaltonBraunTangential makeWB(double kt0, double mu)
{
    WaltonBraunTangentialParameters p;
    p.initialStiffness = kt0;
    p.friction = mu;
    return WaltonBraunTangential(p);
}

// Walton's monotonic loading curve from T* with limit L = mu N
double waltonLoading(double s, double Tstar, double L, double kt0)
{
    const double room = L - Tstar;
    const double x = 1 - 2*kt0*s/(3*room);
    return x <= 0 ? L : Tstar + room*(1 - std::pow(x, 1.5));
}

} // namespace


TEST(WaltonBraunTangential, MonotonicLoadingFollowsWaltonCurve)
{
    const double kt0 = 50, mu = 0.4, N = 1e-6;
    const WaltonBraunTangential wb = makeWB(kt0, mu);
    WaltonBraunTangentialState s;
    const double L = mu*N;
    const double sSlip = 3*L/(2*kt0);
    const int n = 20000;
    const double ds = 1.2*sSlip/n;
    double x = 0;
    for (int i = 1; i <= n; ++i)
    {
        const Vec3 F = wb.force(Vec3{{ds, 0, 0}}, N, s);
        x += ds;
        const double T = -F[0];     // force on particle 1 opposes the slip
        // explicit increments: first-order error ~ ds relative to sSlip
        EXPECT_NEAR(T, waltonLoading(x, 0, L, kt0), 2e-3*L) << "s = " << x;
        EXPECT_LE(T, L*(1 + 1e-12));
        EXPECT_EQ(F[1], 0.0);
    }
    EXPECT_NEAR(-wb.force(Vec3{{ds, 0, 0}}, N, s)[0], L, 1e-12*L);   // sliding
}

TEST(WaltonBraunTangential, UnloadingAfterReversalFollowsMirroredCurve)
{
    const double kt0 = 50, mu = 0.4, N = 1e-6;
    const WaltonBraunTangential wb = makeWB(kt0, mu);
    WaltonBraunTangentialState s;
    const double L = mu*N;
    const int n = 20000;
    // load to about half the limit
    const double sHalf = 0.4*3*L/(2*kt0);
    double T = 0;
    for (int i = 0; i < n; ++i)
    {
        T = -wb.force(Vec3{{sHalf/n, 0, 0}}, N, s)[0];
    }
    const double Tstar = T;
    // reverse: in the reversed direction the load is -T, the turning load
    // -T*, and the same law applies with room mu N + T*
    double x = 0;
    const double ds = 2*sHalf/n;
    for (int i = 0; i < n; ++i)
    {
        T = -wb.force(Vec3{{-ds, 0, 0}}, N, s)[0];
        x += ds;
        EXPECT_NEAR(-T, waltonLoading(x, -Tstar, L, kt0), 2e-3*L) << "s' = " << x;
    }
    // a further reversal starts again with the full stiffness K_T0
    const double Tbefore = s.load[0];
    const double tiny = 1e-6*sHalf;
    const double Tafter = -wb.force(Vec3{{tiny, 0, 0}}, N, s)[0];
    EXPECT_NEAR((Tafter - Tbefore)/tiny, kt0, 1e-6*kt0);
}

TEST(WaltonBraunTangential, CoulombLimitInThreeDimensionsAndNormalScaling)
{
    const double kt0 = 50, mu = 0.3, N = 2e-6;
    const WaltonBraunTangential wb = makeWB(kt0, mu);
    WaltonBraunTangentialState s;
    // slip in a rotating direction, far beyond the limit
    for (int i = 0; i < 1000; ++i)
    {
        const double a = 0.01*i;
        const Vec3 ds{{1e-9*std::cos(a), 1e-9*std::sin(a), 0}};
        const Vec3 F = wb.force(ds, N, s);
        EXPECT_LE(mag(F), mu*N*(1 + 1e-12));
        EXPECT_EQ(F[2], 0.0);
    }
    // the stored load scales with the normal force (Walton & Braun): load
    // below the limit, then double N without slip
    WaltonBraunTangentialState partial;
    wb.force(Vec3{{0.1*mu*N/kt0, 0, 0}}, N, partial);
    const double T = mag(partial.load);
    ASSERT_LT(T, 0.5*mu*N);
    const Vec3 F = wb.force(Vec3{{0, 0, 0}}, 2*N, partial);
    EXPECT_NEAR(mag(F), 2*T, 1e-12*T);
    // no normal load: no tangential force, history cleared
    EXPECT_EQ(mag(wb.force(Vec3{{1e-9, 0, 0}}, 0.0, s)), 0.0);
    EXPECT_EQ(mag(s.load), 0.0);
}

TEST(WaltonBraunTangential, ActionEqualsReaction)
{
    // The force on particle 2 is the force for the opposite relative
    // displacement: F_ji = -F_ij
    const WaltonBraunTangential wb = makeWB(50, 0.4);
    WaltonBraunTangentialState si, sj;
    for (int i = 0; i < 100; ++i)
    {
        const Vec3 ds{{1e-10, -2e-10, 0.5e-10}};
        const Vec3 Fi = wb.force(ds, 1e-6, si);
        const Vec3 Fj = wb.force(-1.0*ds, 1e-6, sj);
        for (int k = 0; k < 3; ++k)
        {
            EXPECT_NEAR(Fi[k], -Fj[k], 1e-15*mag(Fi));
        }
    }
}

TEST(DiRenzoDiMaio, StiffnessSlipAndReversal)
{
    DiRenzoDiMaioParameters p;
    p.effectiveShearModulus = 1e9;
    p.friction = 0.3;
    const DiRenzoDiMaio ddm(p);
    const double R = 0.15e-6, delta = 1e-9, N = 1e-5;
    const double kt = 2.0/3.0*8*1e9*std::sqrt(R*delta);
    EXPECT_NEAR(ddm.stiffness(R, delta), kt, 1e-12*kt);
    DiRenzoDiMaioState s;
    // stick: F = -(2/3) k_t xi
    const double step = 1e-13;
    Vec3 F{{0, 0, 0}};
    for (int i = 1; i <= 10; ++i)
    {
        F = ddm.force(R, delta, Vec3{{step, 0, 0}}, N, s);
        EXPECT_NEAR(F[0], -kt*i*step, 1e-12*kt*i*step);
    }
    // slide: capped at mu N
    for (int i = 0; i < 1000; ++i)
    {
        F = ddm.force(R, delta, Vec3{{step*1000, 0, 0}}, N, s);
    }
    EXPECT_NEAR(F[0], -0.3*N, 1e-12*N);
    // reversal from full slip: the force falls by k_t per unit displacement
    const double back = 1e-12;
    F = ddm.force(R, delta, Vec3{{-back, 0, 0}}, N, s);
    EXPECT_NEAR(F[0], -0.3*N + kt*back, 1e-9*N);
    // separation clears the history
    ddm.force(R, -1e-10, Vec3{{0, 0, 0}}, N, s);
    EXPECT_EQ(mag(s.shear), 0.0);
}

TEST(TangentialContact, RejectsBadParameters)
{
    WaltonBraunTangentialParameters p;
    p.friction = -0.1;
    EXPECT_THROW(WaltonBraunTangential wb(p), std::invalid_argument);
    DiRenzoDiMaioParameters q;
    q.effectiveShearModulus = 0;
    EXPECT_THROW(DiRenzoDiMaio d(q), std::invalid_argument);
}
