/*---------------------------------------------------------------------------*\
    Unit tests of vanDerWaals.H.

    References: the Derjaguin and Gregory closed forms written out here; the
    full Hamaker energy obtained independently by integrating the pairwise
    1/r^6 attraction over the sphere volumes (1-D adaptive Simpson after the
    analytic inner integrals); numerical integration of the force against the
    energy difference.
\*---------------------------------------------------------------------------*/
#include "constants.H"
#include "numerics.H"
#include "vanDerWaals.H"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace colloid;

namespace
{

const double pi = constants::pi;
const double A = 1e-20;         // Hamaker constant [J]
const double h0 = 0.4e-9;       // default inner cut-off [m]

VanDerWaals make
(
    VanDerWaalsForm form,
    double lambda = 0,
    double hOut = HUGE_VAL,
    bool fade = false
)
{
    VanDerWaalsParameters p;
    p.hamakerConstant = A;
    p.form = form;
    p.retardationWavelength = lambda;
    p.outerCutoff = hOut;
    p.fade = fade;
    return VanDerWaals(p);
}

// Hamaker energy of two spheres by pairwise summation of -C/r^6 (A = pi^2 C
// rho1 rho2). The point-sphere integral of 1/s^6 is (4/3) pi R1^3/(r^2 -
// R1^2)^3; averaged over a shell of radius q about the centre of sphere 2
// (centre distance d) it integrates analytically in the polar angle, leaving
// one quadrature over q.
double pairwiseSphereSphereEnergy(double R1, double R2, double h)
{
    const double d = R1 + R2 + h;
    auto shell = [&](double q)
    {
        if (q == 0) return 0.0;
        const double a = (d - q)*(d - q) - R1*R1;
        const double b = (d + q)*(d + q) - R1*R1;
        // int_{-1}^{1} (r^2 - R1^2)^-3 dmu = (a^-2 - b^-2)/(4 d q)
        const double muIntegral = (1/(a*a) - 1/(b*b))/(4*d*q);
        return 2*pi*q*q*muIntegral;
    };
    const double I = colloidTest::integrate(shell, 0, R2, 1e-12*shell(R2)*R2);
    return -A/(pi*pi)*(4.0/3.0)*pi*R1*R1*R1*I;
}

// Same for a sphere and a half space: the point-half-space integral of 1/s^6
// is pi/(6 z^3); integrate over discs of the sphere.
double pairwiseSphereWallEnergy(double R, double h)
{
    auto slab = [&](double z)
    {
        const double rho2 = R*R - (z - h - R)*(z - h - R);
        return pi*rho2*pi/(6*z*z*z);
    };
    const double I = colloidTest::integratePiecewise(slab, h, h + 2*R, {h + 0.01*R, h + 0.1*R}, 1e-12*slab(h + R)*R);
    return -A/(pi*pi)*I;
}

} // namespace


TEST(VanDerWaals, DerjaguinMatchesClosedFormAtSeveralGaps)
{
    const VanDerWaals vdw = make(VanDerWaalsForm::derjaguin);
    const double R1 = 0.15e-6, R2 = 0.4e-6;
    const double Rs = R1*R2/(R1 + R2);
    for (double h : {0.5e-9, 1e-9, 5e-9, 20e-9, 100e-9})
    {
        const double F = -A*Rs/(6*h*h);
        EXPECT_NEAR(vdw.force(R1, R2, h), F, 1e-12*std::fabs(F)) << "h = " << h;
        const double U = -A*Rs/(6*h);
        EXPECT_NEAR(vdw.energy(R1, R2, h), U, 1e-12*std::fabs(U)) << "h = " << h;
    }
}

TEST(VanDerWaals, SeedEquation9ForEqualSpheres)
{
    // seed 002 eq 9: F = -C_H r/(12 a^2) for equal spheres of radius r
    const VanDerWaals vdw = make(VanDerWaalsForm::derjaguin);
    const double r = 0.3e-6, a = 3e-9;
    const double F = -A*r/(12*a*a);
    EXPECT_NEAR(vdw.force(r, r, a), F, 1e-12*std::fabs(F));
}

TEST(VanDerWaals, BelowInnerCutoffHoldsValueAtH0)
{
    for (VanDerWaalsForm form : {VanDerWaalsForm::derjaguin, VanDerWaalsForm::hamaker})
    {
        const VanDerWaals vdw = make(form);
        const double R1 = 0.2e-6, R2 = 0.3e-6;
        const double F0 = vdw.force(R1, R2, h0);
        for (double h : {0.3e-9, 0.1e-9, 0.0, -1e-9, -20e-9})
        {
            EXPECT_EQ(vdw.force(R1, R2, h), F0) << "h = " << h;
        }
        // Continuity at h0 from above: F(h0 + eps) -> F(h0) (slope 2F/h0)
        const double eps = 1e-6*h0;
        EXPECT_NEAR(vdw.force(R1, R2, h0 + eps), F0, 3e-6*std::fabs(F0));
        const double Rs = R1*R2/(R1 + R2);
        const double tol = form == VanDerWaalsForm::derjaguin ? 1e-12 : 1e-2;
        EXPECT_NEAR(F0, -A*Rs/(6*h0*h0), tol*A*Rs/(6*h0*h0));
    }
}

TEST(VanDerWaals, OuterCutoffIsForceShiftedAndContinuous)
{
    const double hOut = 50e-9;
    const VanDerWaals cut = make(VanDerWaalsForm::derjaguin, 0, hOut);
    const VanDerWaals full = make(VanDerWaalsForm::derjaguin);
    const double R1 = 0.3e-6, R2 = 0.3e-6;
    const double Fc = full.force(R1, R2, hOut);
    for (double h : {1e-9, 10e-9, 40e-9})
    {
        const double ref = full.force(R1, R2, h) - Fc;
        EXPECT_NEAR(cut.force(R1, R2, h), ref, 1e-12*std::fabs(ref));
    }
    // Continuous at hOut: |F(hOut - eps)| ~ |dF/dh| eps
    const double eps = 1e-6*hOut;
    const double slope = 2*std::fabs(Fc)/hOut;
    EXPECT_LE(std::fabs(cut.force(R1, R2, hOut - eps)), 1.01*slope*eps);
    EXPECT_EQ(cut.force(R1, R2, hOut), 0.0);
    EXPECT_EQ(cut.force(R1, R2, 2*hOut), 0.0);
    EXPECT_EQ(cut.energy(R1, R2, 2*hOut), 0.0);
    EXPECT_LE(std::fabs(cut.energy(R1, R2, hOut - eps)), 1e-9*std::fabs(full.energy(R1, R2, hOut)));
    EXPECT_EQ(cut.range(), hOut);
}

// The faded form: the uncut force up to hOut/2, then times the smooth step
// w = 3y^2 - 2y^3 of y = (hOut - h)/(hOut/2), written out here; its energy
// against the force integrated by adaptive Simpson to the cut-off
TEST(VanDerWaals, OuterCutoffFadedKeepsTheNearField)
{
    const double hOut = 50e-9;
    const double R1 = 0.15e-6, R2 = 0.45e-6;
    for (VanDerWaalsForm form : {VanDerWaalsForm::derjaguin, VanDerWaalsForm::hamaker})
    {
        for (double R : {R2, wallRadius})
        {
            const VanDerWaals cut = make(form, 0, hOut, true);
            const VanDerWaals full = make(form);
            for (double h : {0.2e-9, 1e-9, 10e-9, 24.99e-9, 25e-9})
            {
                const double ref = full.force(R1, R, h);
                EXPECT_NEAR(cut.force(R1, R, h), ref, 1e-13*std::fabs(ref)) << "h = " << h;
            }
            for (double h : {26e-9, 31.25e-9, 37.5e-9, 45e-9, 49.9e-9})
            {
                const double y = (hOut - h)/(0.5*hOut);
                const double ref = full.force(R1, R, h)*(3*y*y - 2*y*y*y);
                EXPECT_NEAR(cut.force(R1, R, h), ref, 1e-13*std::fabs(ref)) << "h = " << h;
            }
            EXPECT_EQ(cut.force(R1, R, hOut), 0.0);
            EXPECT_EQ(cut.energy(R1, R, hOut), 0.0);
            EXPECT_EQ(cut.energy(R1, R, 2*hOut), 0.0);
            // slope continuous at hOut/2 and zero at hOut
            const double dh = 1e-6*hOut, h1 = 0.5*hOut;
            auto F = [&](double h) { return cut.force(R1, R, h); };
            const double scale = std::fabs(F(h1))/h1;
            EXPECT_NEAR((F(h1 + dh) - F(h1))/dh, (F(h1) - F(h1 - dh))/dh, 1e-4*scale);
            EXPECT_NEAR((F(hOut - dh) - F(hOut - 2*dh))/dh, 0.0, 1e-4*scale);
            // energy = work of the force from h to the cut-off, also below h0
            for (double h : {-0.3e-9, 0.2e-9, 2e-9, 20e-9, 30e-9, 45e-9})
            {
                const double work = colloidTest::integratePiecewise(F, h, hOut, {h0, h1}, 1e-32);
                EXPECT_NEAR(cut.energy(R1, R, h), work, 1e-9*std::fabs(work)) << "h = " << h;
            }
        }
    }
    // the near field must reach beyond the inner cut-off
    VanDerWaalsParameters p;
    p.hamakerConstant = A;
    p.outerCutoff = 1.5*h0;
    EXPECT_NO_THROW(VanDerWaals v(p));
    p.fade = true;
    EXPECT_THROW(VanDerWaals v(p), std::invalid_argument);
}

TEST(VanDerWaals, FullHamakerEnergyMatchesPairwiseSummation)
{
    const VanDerWaals vdw = make(VanDerWaalsForm::hamaker);
    const double R1 = 0.2e-6, R2 = 0.5e-6;
    for (double h : {0.05*R1, 0.3*R1, R1, 4*R1})
    {
        const double ref = pairwiseSphereSphereEnergy(R1, R2, h);
        EXPECT_NEAR(vdw.energy(R1, R2, h), ref, 1e-7*std::fabs(ref)) << "h = " << h;
    }
}

TEST(VanDerWaals, FullHamakerSphereWallMatchesPairwiseSummation)
{
    const VanDerWaals vdw = make(VanDerWaalsForm::hamaker);
    const double R = 0.3e-6;
    for (double h : {0.02*R, 0.5*R, 3*R})
    {
        const double ref = pairwiseSphereWallEnergy(R, h);
        EXPECT_NEAR(vdw.energy(R, wallRadius, h), ref, 1e-7*std::fabs(ref)) << "h = " << h;
    }
}

TEST(VanDerWaals, FullHamakerLimits)
{
    const VanDerWaals vdw = make(VanDerWaalsForm::hamaker);
    const double R1 = 0.2e-6, R2 = 0.5e-6;
    const double Rs = R1*R2/(R1 + R2);
    // Near contact: Derjaguin, relative correction O(h/R)
    const double h = 1e-9;
    EXPECT_NEAR(vdw.force(R1, R2, h), -A*Rs/(6*h*h), 2*h/Rs*A*Rs/(6*h*h));
    // Far apart: London, F = -32 A R1^3 R2^3/(3 d^7) (1 + O((R/d)^2))
    const double d = 100*(R1 + R2);
    const double Flondon = -32*A*std::pow(R1*R2, 3)/(3*std::pow(d, 7));
    EXPECT_NEAR(vdw.force(R1, R2, d - R1 - R2), Flondon, 1e-3*std::fabs(Flondon));
}

TEST(VanDerWaals, RetardedGregoryForm)
{
    const double lambda = 100e-9;
    const VanDerWaals vdw = make(VanDerWaalsForm::derjaguin, lambda);
    const VanDerWaals plain = make(VanDerWaalsForm::derjaguin);
    const double R1 = 0.3e-6, R2 = 0.6e-6;
    const double Rs = R1*R2/(R1 + R2);
    for (double h : {1e-9, 10e-9, 50e-9})
    {
        // Gregory (1981): U = -A R*/(6h) (1 + 14 h/lambda)^-1
        auto U = [&](double x) { return -A*Rs/(6*x)/(1 + 14*x/lambda); };
        EXPECT_NEAR(vdw.energy(R1, R2, h), U(h), 1e-12*std::fabs(U(h)));
        const double F = -colloidTest::derivative(U, h, 1e-4*h);
        EXPECT_NEAR(vdw.force(R1, R2, h), F, 1e-8*std::fabs(F));
        // Retardation weakens the attraction
        EXPECT_LT(std::fabs(vdw.force(R1, R2, h)), std::fabs(plain.force(R1, R2, h)));
    }
}

TEST(VanDerWaals, ForceIntegralEqualsEnergyDifference)
{
    const double hOut = 30e-9;
    const double R1 = 0.15e-6, R2 = 0.45e-6;
    struct Case { VanDerWaalsForm form; double lambda; double R2; };
    for (Case c :
        {
            Case{VanDerWaalsForm::derjaguin, 0, R2},
            Case{VanDerWaalsForm::derjaguin, 100e-9, R2},
            Case{VanDerWaalsForm::hamaker, 0, R2},
            Case{VanDerWaalsForm::hamaker, 0, wallRadius},
            Case{VanDerWaalsForm::derjaguin, 0, wallRadius}
        })
    {
        const VanDerWaals vdw = make(c.form, c.lambda, hOut);
        auto F = [&](double h) { return vdw.force(R1, c.R2, h); };
        // from inside the overlap, across h0 and hOut, to beyond hOut
        const double a = -0.5e-9, b = 40e-9;
        const double work = colloidTest::integratePiecewise(F, a, b, {h0, hOut}, 1e-30);
        const double dU = vdw.energy(R1, c.R2, a) - vdw.energy(R1, c.R2, b);
        EXPECT_NEAR(work, dU, 1e-8*std::fabs(dU));
        // and inside the smooth range only
        const double w2 = colloidTest::integrate(F, 1e-9, 20e-9, 1e-32);
        const double dU2 = vdw.energy(R1, c.R2, 1e-9) - vdw.energy(R1, c.R2, 20e-9);
        EXPECT_NEAR(w2, dU2, 1e-8*std::fabs(dU2));
    }
}

TEST(VanDerWaals, SymmetricInTheTwoSpheres)
{
    for (VanDerWaalsForm form : {VanDerWaalsForm::derjaguin, VanDerWaalsForm::hamaker})
    {
        const VanDerWaals vdw = make(form);
        const double R1 = 0.1e-6, R2 = 0.7e-6;
        for (double h : {0.2e-9, 2e-9, 200e-9})
        {
            // F_ij = -F_ji: the centre-line force is the same scalar for both
            const double Fij = vdw.force(R1, R2, h);
            const double Fji = vdw.force(R2, R1, h);
            EXPECT_NEAR(Fij, Fji, 1e-13*std::fabs(Fij));
            EXPECT_LT(Fij, 0.0);
        }
    }
}

TEST(VanDerWaals, SphereWallIsLimitOfLargeSphere)
{
    const double R = 0.3e-6;
    const double Rbig = 1e4*R;
    for (VanDerWaalsForm form : {VanDerWaalsForm::derjaguin, VanDerWaalsForm::hamaker})
    {
        const VanDerWaals vdw = make(form);
        for (double h : {0.2e-9, 2e-9, 0.1*R, R})
        {
            const double Fw = vdw.force(R, wallRadius, h);
            // relative difference O(R/Rbig, h/Rbig)
            EXPECT_NEAR(vdw.force(R, Rbig, h), Fw, 3e-4*std::fabs(Fw)) << "h = " << h;
            const double Uw = vdw.energy(R, wallRadius, h);
            EXPECT_NEAR(vdw.energy(R, Rbig, h), Uw, 3e-4*std::fabs(Uw)) << "h = " << h;
        }
        // Derjaguin sphere-wall: R* = R
        if (form == VanDerWaalsForm::derjaguin)
        {
            const double h = 3e-9;
            EXPECT_NEAR(vdw.force(R, wallRadius, h), -A*R/(6*h*h), 1e-12*A*R/(6*h*h));
        }
    }
}

TEST(VanDerWaals, RejectsBadParameters)
{
    VanDerWaalsParameters p;
    p.hamakerConstant = A;
    p.innerCutoff = -1e-9;
    try
    {
        VanDerWaals v(p);
        FAIL() << "negative inner cut-off accepted";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("innerCutoff"), std::string::npos);
    }
    p.innerCutoff = 1e-9;
    p.outerCutoff = 0.5e-9;
    EXPECT_THROW(VanDerWaals v(p), std::invalid_argument);
    p.outerCutoff = HUGE_VAL;
    p.form = VanDerWaalsForm::hamaker;
    p.retardationWavelength = 100e-9;
    EXPECT_THROW(VanDerWaals v(p), std::invalid_argument);
    p.retardationWavelength = 0;
    p.hamakerConstant = 1e-10;
    EXPECT_THROW(VanDerWaals v(p), std::invalid_argument);
}
