/*---------------------------------------------------------------------------*\
    Unit tests of doubleLayer.H.

    References: the Debye length of 1 mM 1:1 salt in water at 25 C (9.6 nm,
    e.g. Israelachvili, Intermolecular and Surface Forces); seed 002 eqs
    10-11 written out for equal spheres; Derjaguin's approximation applied to
    the flat-plate energies (linear superposition: 64 n kT G1 G2 exp(-kh)/k;
    Hogg-Healy-Fuerstenau in its coth/csch form); the Debye-Hueckel limit in
    which both forms agree; numerical integration of the force against the
    energy difference.
\*---------------------------------------------------------------------------*/
#include "constants.H"
#include "doubleLayer.H"
#include "numerics.H"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace colloid;

namespace
{

const double pi = constants::pi;
const double kB = 1.380649e-23;
const double e = 1.602176634e-19;
const double NA = 6.02214076e23;
const double eps0 = 8.8541878128e-12;
const double T = 298.15;
const double epsr = 78.4;

DoubleLayerParameters params
(
    DoubleLayerForm form,
    double c,
    double zeta1,
    double zeta2,
    double hOut = HUGE_VAL
)
{
    DoubleLayerParameters p;
    p.electrolyte.concentration = c;
    p.electrolyte.valence = 1;
    p.electrolyte.temperature = T;
    p.electrolyte.relativePermittivity = epsr;
    p.zeta1 = zeta1;
    p.zeta2 = zeta2;
    p.form = form;
    p.outerCutoff = hOut;
    return p;
}

double kappaOf(double c, int z)
{
    return std::sqrt(2*NA*c*z*z*e*e/(epsr*eps0*kB*T));
}

} // namespace


TEST(DoubleLayer, DebyeLengthOfMillimolarSalt)
{
    Electrolyte el;
    el.concentration = 1.0;     // 1 mM = 1 mol/m^3
    el.valence = 1;
    el.temperature = 298.15;
    el.relativePermittivity = 78.4;
    // 0.304 nm/sqrt(I [M]) -> 9.6 nm at 1 mM; within 1 %
    EXPECT_NEAR(debyeLength(el), 9.6e-9, 0.01*9.6e-9);
    // z:z salt: ionic strength z^2 c, Debye length 1/z
    el.valence = 2;
    EXPECT_NEAR(debyeLength(el), 9.6e-9/2, 0.01*9.6e-9/2);
    EXPECT_NEAR
    (
        debyeLengthFromIonicStrength(4.0, 298.15, 78.4),
        debyeLength(el),
        1e-14*debyeLength(el)
    );
    // 1 M salt: 0.30 nm; no salt (1e-6 M, pure water ~ 1e-7 M): ~300 nm
    el.valence = 1;
    el.concentration = 1000;
    EXPECT_NEAR(debyeLength(el), 0.304e-9, 0.01*0.304e-9);
    el.concentration = 1e-3;
    EXPECT_NEAR(debyeLength(el), 304e-9, 0.01*304e-9);
}

TEST(DoubleLayer, SeedEquation10ForEqualSpheres)
{
    const double c = 10.0;                      // 10 mM [mol/m^3]
    const double zeta = -0.041;                 // glass, seed 002 table 1 [V]
    const DoubleLayer dl(params(DoubleLayerForm::linearSuperposition, c, zeta, zeta));
    const double r = 2.9e-6;                    // d50 = 5.8 um
    const double kappa = kappaOf(c, 1);
    const double Gamma = std::tanh(e*zeta/(4*kB*T));
    for (double a : {0.5e-9, 1e-9, 3e-9, 10e-9, 30e-9})
    {
        // seed 002 eq 10: F = 64 pi r c N_A Gamma^2 kB T/kappa exp(-kappa a)
        const double F = 64*pi*r*c*NA*Gamma*Gamma*kB*T/kappa*std::exp(-kappa*a);
        EXPECT_NEAR(dl.force(r, r, a), F, 1e-10*F) << "a = " << a;
        EXPECT_NEAR(dl.energy(r, r, a), F/kappa, 1e-10*F/kappa);
    }
}

TEST(DoubleLayer, LinearSuperpositionUnequalSpheresAndWallByDerjaguin)
{
    const double c = 1.0;
    const double z1 = -0.05, z2 = -0.03;
    const DoubleLayer dl(params(DoubleLayerForm::linearSuperposition, c, z1, z2));
    const double kappa = kappaOf(c, 1);
    const double G1 = std::tanh(e*z1/(4*kB*T));
    const double G2 = std::tanh(e*z2/(4*kB*T));
    auto plateEnergy = [&](double h)    // per unit area [J/m^2]
    {
        return 64*NA*c*kB*T*G1*G2/kappa*std::exp(-kappa*h);
    };
    const double R1 = 0.3e-6, R2 = 1.2e-6;
    for (double h : {1e-9, 5e-9, 20e-9})
    {
        const double Fss = 2*pi*R1*R2/(R1 + R2)*plateEnergy(h);
        EXPECT_NEAR(dl.force(R1, R2, h), Fss, 1e-10*Fss);
        const double Fsw = 2*pi*R1*plateEnergy(h);
        EXPECT_NEAR(dl.force(R1, wallRadius, h), Fsw, 1e-10*Fsw);
        // large second sphere tends to the wall
        EXPECT_NEAR(dl.force(R1, 1e4*R1, h), Fsw, 2e-4*Fsw);
        // symmetric: F_ij = -F_ji along the centre line
        EXPECT_NEAR(dl.force(R2, R1, h), dl.force(R1, R2, h), 1e-14*Fss);
    }
}

TEST(DoubleLayer, HoggHealyFuerstenauByDerjaguin)
{
    const double c = 1.0;
    const double kappa = kappaOf(c, 1);
    const double eps = epsr*eps0;
    const double R1 = 0.3e-6, R2 = 0.5e-6;
    const double Rs = R1*R2/(R1 + R2);
    for (double z2 : {-0.04, -0.01, 0.02})
    {
        const double z1 = -0.04;
        const DoubleLayer dl(params(DoubleLayerForm::hoggHealyFuerstenau, c, z1, z2));
        for (double h : {0.5e-9, 2e-9, 10e-9, 40e-9})
        {
            // constant-potential plates (HHF 1966):
            // V = (eps kappa/2)[(z1^2+z2^2)(1 - coth kh) + 2 z1 z2 csch kh]
            const double kh = kappa*h;
            const double V =
                eps*kappa/2*((z1*z1 + z2*z2)*(1 - 1/std::tanh(kh)) + 2*z1*z2/std::sinh(kh));
            const double F = 2*pi*Rs*V;
            EXPECT_NEAR(dl.force(R1, R2, h), F, 1e-9*std::fabs(F)) << "h = " << h << " z2 = " << z2;
        }
    }
    // opposite potentials attract
    const DoubleLayer opposite(params(DoubleLayerForm::hoggHealyFuerstenau, c, -0.03, 0.03));
    EXPECT_LT(opposite.force(R1, R2, 5e-9), 0.0);
}

TEST(DoubleLayer, FormsAgreeInTheDebyeHueckelFarField)
{
    // Low potentials (e zeta/kT << 1) and kappa h >> 1: both tend to
    // 4 pi eps kappa R* z1 z2 exp(-kappa h)
    const double c = 1.0;
    const double z1 = -0.005, z2 = -0.008;
    const DoubleLayer lsa(params(DoubleLayerForm::linearSuperposition, c, z1, z2));
    const DoubleLayer hhf(params(DoubleLayerForm::hoggHealyFuerstenau, c, z1, z2));
    const double kappa = kappaOf(c, 1);
    const double R = 0.5e-6;
    const double h = 5/kappa;
    const double F = 4*pi*epsr*eps0*kappa*(R/2)*z1*z2*std::exp(-kappa*h);
    // corrections: (e zeta/4kT)^2/3 ~ 0.2 % and exp(-kappa h) ~ 0.7 %
    EXPECT_NEAR(lsa.force(R, R, h), F, 0.01*F);
    EXPECT_NEAR(hhf.force(R, R, h), F, 0.01*F);
}

TEST(DoubleLayer, CutoffsAreContinuous)
{
    const double c = 1.0;
    const double hOut = 60e-9;
    const double h0 = 0.4e-9;
    const double R1 = 0.2e-6, R2 = 0.4e-6;
    for (DoubleLayerForm form : {DoubleLayerForm::linearSuperposition, DoubleLayerForm::hoggHealyFuerstenau})
    {
        const DoubleLayer dl(params(form, c, -0.04, -0.02, hOut));
        const DoubleLayer plain(params(form, c, -0.04, -0.02));
        const double F0 = dl.force(R1, R2, h0);
        EXPECT_NEAR(F0, plain.force(R1, R2, h0) - plain.force(R1, R2, hOut), 1e-12*std::fabs(F0));
        for (double h : {0.2e-9, 0.0, -2e-9})
        {
            EXPECT_EQ(dl.force(R1, R2, h), F0);
        }
        const double eps = 1e-7*h0;
        EXPECT_NEAR(dl.force(R1, R2, h0 + eps), F0, 1e-6*std::fabs(F0));
        // at hOut: the shifted force vanishes continuously
        const double slope = std::fabs(colloidTest::derivative
        (
            [&](double h) { return plain.force(R1, R2, h); }, hOut, 1e-3*hOut
        ));
        const double dh = 1e-6*hOut;
        EXPECT_LE(std::fabs(dl.force(R1, R2, hOut - dh)), 1.01*slope*dh);
        EXPECT_EQ(dl.force(R1, R2, hOut), 0.0);
        EXPECT_EQ(dl.force(R1, R2, 1.5*hOut), 0.0);
        EXPECT_LE(std::fabs(dl.energy(R1, R2, hOut - dh)), 1e-9*std::fabs(dl.energy(R1, R2, h0)));
    }
}

TEST(DoubleLayer, ForceIntegralEqualsEnergyDifference)
{
    const double hOut = 50e-9;
    const double h0 = 0.4e-9;
    for (DoubleLayerForm form : {DoubleLayerForm::linearSuperposition, DoubleLayerForm::hoggHealyFuerstenau})
    {
        for (double R2 : {0.6e-6, wallRadius})
        {
            for (double cut : {hOut, HUGE_VAL})
            {
                const DoubleLayer dl(params(form, 1.0, -0.05, -0.01, cut));
                const double R1 = 0.3e-6;
                auto F = [&](double h) { return dl.force(R1, R2, h); };
                const double a = -1e-9, b = 70e-9;
                const double work = colloidTest::integratePiecewise(F, a, b, {h0, hOut}, 1e-30);
                const double dU = dl.energy(R1, R2, a) - dl.energy(R1, R2, b);
                EXPECT_NEAR(work, dU, 1e-8*std::fabs(dU));
            }
        }
    }
}

// The faded form: the uncut force up to hOut/2, then times the smooth step
// w = 3y^2 - 2y^3 of y = (hOut - h)/(hOut/2), written out here; the energy
// against the force integrated by adaptive Simpson to the cut-off
TEST(DoubleLayer, OuterCutoffFadedKeepsTheNearField)
{
    const double hOut = 50e-9;
    const double h0 = 0.4e-9;
    const double R1 = 0.2e-6;
    for (DoubleLayerForm form : {DoubleLayerForm::linearSuperposition, DoubleLayerForm::hoggHealyFuerstenau})
    {
        for (double R2 : {0.4e-6, wallRadius})
        {
            DoubleLayerParameters p = params(form, 1.0, -0.04, -0.02, hOut);
            p.fade = true;
            const DoubleLayer dl(p);
            const DoubleLayer plain(params(form, 1.0, -0.04, -0.02));
            for (double h : {0.4e-9, 3e-9, 24.99e-9, 25e-9})
            {
                const double ref = plain.force(R1, R2, h);
                EXPECT_NEAR(dl.force(R1, R2, h), ref, 1e-13*std::fabs(ref)) << "h = " << h;
            }
            EXPECT_EQ(dl.force(R1, R2, -1e-9), plain.force(R1, R2, h0));
            for (double h : {26e-9, 37.5e-9, 49e-9})
            {
                const double y = (hOut - h)/(0.5*hOut);
                const double ref = plain.force(R1, R2, h)*(3*y*y - 2*y*y*y);
                EXPECT_NEAR(dl.force(R1, R2, h), ref, 1e-13*std::fabs(ref)) << "h = " << h;
            }
            EXPECT_EQ(dl.force(R1, R2, hOut), 0.0);
            EXPECT_EQ(dl.energy(R1, R2, hOut), 0.0);
            auto F = [&](double h) { return dl.force(R1, R2, h); };
            for (double h : {-1e-9, 1e-9, 10e-9, 30e-9})
            {
                const double work = colloidTest::integratePiecewise(F, h, hOut, {h0, 0.5*hOut}, 1e-32);
                EXPECT_NEAR(dl.energy(R1, R2, h), work, 1e-8*std::fabs(work)) << "h = " << h;
            }
        }
    }
}

TEST(DoubleLayer, RejectsBadParameters)
{
    DoubleLayerParameters p = params(DoubleLayerForm::linearSuperposition, 1.0, -0.04, -0.04);
    p.electrolyte.concentration = 0;
    try
    {
        DoubleLayer dl(p);
        FAIL() << "zero concentration accepted";
    }
    catch (const std::invalid_argument& ex)
    {
        EXPECT_NE(std::string(ex.what()).find("concentration"), std::string::npos);
    }
    p.electrolyte.concentration = 1;
    p.zeta1 = 1.0;
    EXPECT_THROW(DoubleLayer dl(p), std::invalid_argument);
    p.zeta1 = -0.04;
    p.electrolyte.valence = 0;
    EXPECT_THROW(DoubleLayer dl(p), std::invalid_argument);
}
