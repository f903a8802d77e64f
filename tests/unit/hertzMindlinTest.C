/*---------------------------------------------------------------------------*\
    Unit tests of hertzMindlin.H and elasticMaterial.H.

    References: Hertz's force 4/3 E* sqrt(R*) delta^(3/2) (seed 002 eq 3
    with effective quantities) and its derivative; the Hertz impact
    duration 2.9432 delta_max/v computed here from the quadrature
    2 int_0^1 dx/sqrt(1 - x^(5/2)), against which the undamped collision ODE
    is integrated with RK4; Mindlin's no-slip stiffness 8 G* sqrt(R* delta);
    Coulomb's limit; the effective moduli of identical materials.
\*---------------------------------------------------------------------------*/
#include "constants.H"
#include "hertzMindlin.H"
#include "numerics.H"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace colloid;

namespace
{

const double pi = constants::pi;

HertzMindlin make(double E, double G, double e, double mu)
{
    HertzMindlinParameters p;
    p.effectiveYoungsModulus = E;
    p.effectiveShearModulus = G;
    p.restitution = e;
    p.friction = mu;
    return HertzMindlin(p);
}

// Head-on collision, RK4, returns {restitution, duration}; the damped force
// is a function of (delta, d delta/dt) only, so no history is involved.
std::pair<double, double> collide(const HertzMindlin& hm, double Rs, double mStar, double v0, double dt)
{
    double x = 0, v = v0, t = 0;
    // vn = dh/dt = -d(delta)/dt
    auto acc = [&](double xs, double vs) { return -hm.normalForce(Rs, mStar, xs, -vs)/mStar; };
    while (true)
    {
        const double k1x = v, k1v = acc(x, v);
        const double k2x = v + 0.5*dt*k1v, k2v = acc(x + 0.5*dt*k1x, v + 0.5*dt*k1v);
        const double k3x = v + 0.5*dt*k2v, k3v = acc(x + 0.5*dt*k2x, v + 0.5*dt*k2v);
        const double k4x = v + dt*k3v, k4v = acc(x + dt*k3x, v + dt*k3v);
        const double xn = x + dt/6*(k1x + 2*k2x + 2*k3x + k4x);
        const double vn = v + dt/6*(k1v + 2*k2v + 2*k3v + k4v);
        if (xn <= 0 && t > 0)
        {
            // linear interpolation of the crossing (error O(dt^2 a/v))
            const double s = x/(x - xn);
            return {-(v + s*(vn - v))/v0, t + s*dt};
        }
        x = xn;
        v = vn;
        t += dt;
    }
}

} // namespace


TEST(ElasticMaterial, EffectiveModuliOfIdenticalMaterials)
{
    ElasticMaterial glass;
    glass.youngsModulus = 63e9;
    glass.poissonsRatio = 0.24;
    const double E = 63e9, nu = 0.24, G = E/(2*(1 + nu));
    EXPECT_NEAR(effectiveYoungsModulus(glass, glass), E/(2*(1 - nu*nu)), 1e-12*E);
    EXPECT_NEAR(effectiveShearModulus(glass, glass), G/(2*(2 - nu)), 1e-12*G);
    ElasticMaterial bad;
    bad.poissonsRatio = 0.7;
    EXPECT_THROW(bad.check(), std::invalid_argument);
}

TEST(HertzMindlin, NormalForceAndStiffness)
{
    const HertzMindlin hm = make(3e10, 1e10, 0.8, 0.3);
    const double Rs = 0.1e-6, mStar = 1e-17;
    for (double d : {1e-11, 1e-10, 1e-9})
    {
        const double F = 4.0/3.0*3e10*std::sqrt(Rs)*std::pow(d, 1.5);
        EXPECT_NEAR(hm.normalForce(Rs, mStar, d, 0.0), F, 1e-12*F);
        const double k = colloidTest::derivative
        (
            [&](double x) { return hm.normalForce(Rs, mStar, x, 0.0); }, d, 1e-3*d
        );
        EXPECT_NEAR(hm.normalStiffness(Rs, d), k, 1e-8*k);
        // damping opposes the approach (vn < 0 -> more repulsion)
        EXPECT_GT(hm.normalForce(Rs, mStar, d, -1e-3), F);
    }
    EXPECT_EQ(hm.normalForce(Rs, mStar, -1e-9, -1.0), 0.0);
}

TEST(HertzMindlin, UndampedImpactDurationAndRebound)
{
    // the Hertz constant from its defining integral (x = 1 - u^2 removes
    // the endpoint singularity)
    const double I = colloidTest::integrate
    (
        [](double u)
        {
            if (u == 0) return 2/std::sqrt(2.5);
            return 2*u/std::sqrt(1 - std::pow(1 - u*u, 2.5));
        },
        0, 1, 1e-12
    );
    const double Es = 3e10, Rs = 0.075e-6;
    const double m = 2500*pi/6*std::pow(0.3e-6, 3);
    const double mStar = m/2;
    const HertzMindlin hm = make(Es, 1e10, 1.0, 0.3);
    for (double v0 : {1e-2, 1.0})
    {
        const double dmax = std::pow(15*mStar*v0*v0/(16*Es*std::sqrt(Rs)), 0.4);
        const double tc = 2*I*dmax/v0;
        const auto r = collide(hm, Rs, mStar, v0, 1e-5*tc);
        EXPECT_NEAR(r.first, 1.0, 1e-6);
        EXPECT_NEAR(r.second, tc, 1e-5*tc);
    }
}

TEST(HertzMindlin, DampedRestitutionIsIndependentOfImpactSpeed)
{
    // damping ~ delta^(1/4) makes the restitution speed-independent
    const double Es = 3e10, Rs = 0.075e-6;
    const double mStar = 2500*pi/6*std::pow(0.3e-6, 3)/2;
    const HertzMindlin hm = make(Es, 1e10, 0.7, 0.3);
    const auto slow = collide(hm, Rs, mStar, 1e-3, 1e-13);
    const auto fast = collide(hm, Rs, mStar, 1.0, 1e-14);
    EXPECT_LT(slow.first, 1.0);
    EXPECT_NEAR(slow.first, fast.first, 1e-4);
}

TEST(HertzMindlin, TangentialStickAndSlip)
{
    const double G = 1e10, mu = 0.3;
    const HertzMindlin hm = make(3e10, G, 1.0, mu);   // e = 1: no damping
    const double Rs = 0.1e-6, mStar = 1e-17, d = 1e-9, N = 1e-5;
    const double kt = 8*G*std::sqrt(Rs*d);
    HertzMindlinState s;
    const Vec3 zero{{0, 0, 0}};
    Vec3 F = zero;
    const double step = 1e-14;
    for (int i = 1; i <= 5; ++i)
    {
        F = hm.tangentialForce(Rs, mStar, d, Vec3{{0, step, 0}}, zero, N, s);
        EXPECT_NEAR(F[1], -kt*i*step, 1e-12*kt*i*step);
    }
    for (int i = 0; i < 1000; ++i)
    {
        F = hm.tangentialForce(Rs, mStar, d, Vec3{{0, 1e-10, 0}}, zero, N, s);
    }
    EXPECT_NEAR(F[1], -mu*N, 1e-12*N);
    EXPECT_NEAR(mag(F), mu*N, 1e-12*N);
}
