/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: Brownian motion of the implicit drag update
    (fix_colloid_implicit.h, property/global brownianTemperature and
    brownianSeed) on free spheres in quiescent water.

    24 389 (29^3) glass spheres of radius R = 0.5 um (m = 1.31 pg) on a cubic
    lattice 3 um apart (no contacts), Stokes drag K = 6 pi mu R (tau = m/K
    = 0.139 us), T = 293.15 K, started at rest.

    meanSquareDisplacement: dt = 0.1, 1 and 5 tau; after 20 tau
      (equilibration), the mean square displacement over a lag t of
      100 tau (1000 tau at 5 tau) against the Langevin closed form
      6 D (t - tau (1 - exp(-t/tau))), D = k_B T/K, within 2 % (sampling
      error of the mean of 24 389: 0.5 %). (The scheme's diffusion
      coefficient is exact at any step; positions sampled at steps of
      5 tau add a term of order dt^2/t: +6.6 % over 100 tau.) The
      spheres move independently: their mean displacement, each
      component, within 4 standard errors sqrt(MSD/(3 N)) of 0, and the
      correlations of the components of a sphere and of spheres with
      consecutive ids within 5 standard errors (1/sqrt(N)) of 0;
    equipartition: dt = 0.01, 0.1, 1 and 5 tau; after 10 tau, 10 samples
      2 tau apart: the half-step velocities (the ones that move the
      spheres) have <w_x^2> = k_B T/m at every step, the written ones the
      scheme's k_B T/(m (1 + dt/(2 tau))), so equipartition where inertia
      is resolved (dt = 0.01 tau): within 2 % (sampling error 0.3 %);
    reproducible: the same seed gives the same positions to the last bit,
      another seed other ones.

    lubricatedPairDiffusion: 3375 pairs of spheres of R = 0.15 um (the slot
      coater's) at a gap h0 = 5 nm, each lubricated (inner cut-off 1 nm,
      outer 0.1 um: c(h0) = 6 pi mu R*^2 (1/h0 - 1/h_out), R* = R/2, 7 K)
      and with drag K, pairs 1.5 um apart; dt = 1e-10 s (the relative
      relaxation time m/(K + 2c) is 8.2 dt). After 0.1 us, the mean square
      change of each pair's separation along its axis over lags of
      0.05 us (5 windows) against the Langevin form
      2 D (t - tau (1 - exp(-t/tau))) of the relative coordinate, with
      D = k_B T/(K/2 + c(h)) and tau = m/(K + 2c(h)) at each pair's gap at
      the start of the window, within 5 % (sampling error of the mean of
      16 875: 1.1 %; the gaps spread by 0.3 nm, which the per-window
      reference follows). Lubrication without its noise (the drag's
      alone) gives D K/(K + 2c): 15 times too small; a noise variance off
      by 2 gives twice the reference.
    lubricatedWallDiffusion: the same for 3481 spheres at h0 = 5 nm above
      a primitive wall (c_w = 6 pi mu R^2 (1/h - 1/h_out), 28.5 K): the
      mean square change of the gap over 0.05 us against
      2 D (t - tau (1 - exp(-t/tau))), D = k_B T/(K + c_w), tau =
      m/(K + c_w), within 5 % (sampling error 1.1 %); without the wall's
      noise it would be 29 times too small.
    lubricatedPairDiffusionExplicit: the pairs' diffusion with
      lubricationExplicitRatio 0.25, where each pair (c dt/m = 0.057) is
      damped explicitly with its noise (fix_colloid_implicit.h): the same
      reference and tolerance, and every pair explicit.
    lubricatedPairVelocities(Explicit): the same pairs' relative
      velocities, where the step shows: along the axis the variance of
      the scheme's AR(1) process, (2 kT/m)/(1 + c dt/m) with the pair in
      the implicit update, (2 kT/m)/(1 - c dt/m) damped explicitly (c dt/m
      = 0.057: -5.4 % and +6.0 % from equipartition), across it 2 kT/m,
      within 1.5 % (sampling error 0.4 %).
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"
#include "register_colloid_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace demTest;

namespace
{

const double pi = std::acos(-1.0);
const double R = 0.5;           // um
const double rho = 2.5;         // pg/um^3
const double mu = 1.0;          // pg/(um us) = 1 mPa s
const double T = 293.15;        // K
const double kT = 1.380649e-23*T/1e-15;     // fJ
const double m = rho*4.0/3.0*pi*R*R*R;
const double K = 6*pi*mu*R;
const double tau = m/K;
const double D = kT/K;          // um^2/us

// Stokes drag K into fluid at rest, and Brownian motion with this seed
std::string dragAndNoise(double Kd, long seed)
{
    std::ostringstream in;
    in.precision(17);
    in << "fix Ksl all property/atom Ksl scalar yes no no " << Kd << "\n"
          "fix uf all property/atom uf vector yes no no 0 0 0\n"
          "fix bT all property/global brownianTemperature scalar " << T << "\n"
          "fix bS all property/global brownianSeed scalar " << seed << "\n";
    return in.str();
}

// Lubrication (inner cut-off 1 nm, outer hOut [um]) between the spheres,
// with the neighbour skin [um]
std::string lubrication(double hOut, double skin)
{
    std::ostringstream in;
    in.precision(17);
    in << "fix m1 all property/global loadingStiffness peratomtypepair 2 1000 1000 1000 1000\n"
          "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
          "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
          "fix l1 all property/global liquidViscosity scalar " << mu << "\n"
          "fix l2 all property/global lubricationInnerCutoff scalar 0.001\n"
          "fix l3 all property/global lubricationOuterCutoff scalar " << hOut << "\n"
          "neighbor " << skin << " bin\n"
          "neigh_modify delay 0\n"
          "pair_style gran model walton_braun tangential history cohesion colloid/lub\n"
          "pair_coeff * *\n";
    return in.str();
}

// 29^3 spheres 3 um apart, at rest, with drag into fluid at rest
void freeSpheres(LiggghtsRun& run, double dt, long seed)
{
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(45.0)
       << "atom_modify sort 0 0.0\n"
          "lattice sc 3.0\n"
          "region spheres block -44 44 -44 44 -44 44 units box\n"
          "create_atoms 1 region spheres\n"
          "set group all diameter " << 2*R << " density " << rho << "\n"
          "velocity all set 0 0 0 units box\n"
          "timestep " << dt << "\n"
          "fix integrate all nve/sphere\n"
       << dragAndNoise(K, seed);
    run.commands(in.str());
    colloidImplicitUpdate(run.instance());
    run.commands("run 0");
}

std::vector<double> positions(LiggghtsRun& run)
{
    std::vector<double> x;
    for (long id = 1; id <= run.nAtoms(); id++)
        for (int k = 0; k < 3; k++) x.push_back(run.x(id)[k]);
    return x;
}

void advance(LiggghtsRun& run, long steps)
{
    run.commands("run " + std::to_string(steps) + " pre no post no");
}

// <v_x^2> (all components) of the written and of the half-step velocities
void velocityVariance(LiggghtsRun& run, double dt, double& written, double& half)
{
    const long n = run.nAtoms();
    written = half = 0;
    for (long id = 1; id <= n; id++)
        for (int k = 0; k < 3; k++)
        {
            const double v = run.v(id)[k];
            const double w = v + 0.5*dt*run.f(id)[k]/run.mass(id);
            written += v*v;
            half += w*w;
        }
    written /= 3*n;
    half /= 3*n;
}

// pairs of lubricated spheres along x (lattice custom: a pair per point,
// 1.5 um apart), with drag, at rest; weak pairs damped explicitly below
// c dt/m = explicitRatio (0: every pair in the implicit solve)
void lubricatedPairs(LiggghtsRun& run, double Rp, double h0, double dt, long seed,
                     double explicitRatio)
{
    const double spacing = 1.5;
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(12.0)
       << "atom_modify sort 0 0.0\n"
          "lattice custom " << spacing << " a1 1 0 0 a2 0 1 0 a3 0 0 1 basis 0 0 0 basis "
       << (2*Rp + h0)/spacing << " 0 0\n"
          // whole pairs: points -10.5 ... 10.5, partners to 10.805
          "region pairs block -11 10.9 -11 10.9 -11 10.9 units box\n"
          "create_atoms 1 region pairs\n"
          "set group all diameter " << 2*Rp << " density " << rho << "\n"
          "velocity all set 0 0 0 units box\n"
       << lubrication(0.1, 0.05)
       << "fix l4 all property/global lubricationExplicitRatio scalar " << explicitRatio << "\n"
          "timestep " << dt << "\n"
          "fix integrate all nve/sphere\n"
       << dragAndNoise(6*pi*mu*Rp, seed);
    run.commands(in.str());
    run.commands("run 0");
}

} // namespace

TEST(brownian, meanSquareDisplacement)
{
    for (double a : {0.1, 1.0, 5.0})
    {
        const double dt = a*tau;
        LiggghtsRun run;
        freeSpheres(run, dt, 4711);
        advance(run, std::lround(20/a));
        const std::vector<double> x0 = positions(run);
        const long steps = std::lround((a < 5 ? 100 : 1000)/a);
        advance(run, steps);
        const std::vector<double> x1 = positions(run);
        double msd = 0, mean[3] = {0, 0, 0};
        for (std::size_t k = 0; k < x0.size(); k++)
        {
            msd += (x1[k] - x0[k])*(x1[k] - x0[k]);
            mean[k % 3] += (x1[k] - x0[k])/run.nAtoms();
        }
        msd /= run.nAtoms();
        const double standardError = std::sqrt(msd/(3*run.nAtoms()));
        for (int k = 0; k < 3; k++)
            EXPECT_LT(std::fabs(mean[k]), 4*standardError) << "mean displacement " << k << ", dt = " << a << " tau";
        // no correlation between the components of one sphere's
        // displacement, nor between those of spheres with consecutive ids
        // (whose random numbers are close in the step's stream: counters
        // 4 id + k)
        const long n = run.nAtoms();
        for (int p = 0; p < 3; p++)
            for (int q = 0; q < 3; q++)
            {
                // (p, q) and (q, p) of one sphere are the same statistic
                double same = 0, next = 0;
                for (long i = 0; i < n; i++)
                {
                    const double d = x1[3*i + p] - x0[3*i + p];
                    same += d*(x1[3*i + q] - x0[3*i + q]);
                    if (i + 1 < n) next += d*(x1[3*(i + 1) + q] - x0[3*(i + 1) + q]);
                }
                const double variance = msd/3;
                if (p < q)
                    EXPECT_LT(std::fabs(same/n/variance), 5/std::sqrt(double(n)))
                        << "components " << p << ", " << q << " of a sphere, dt = " << a << " tau";
                EXPECT_LT(std::fabs(next/(n - 1)/variance), 5/std::sqrt(double(n - 1)))
                    << "components " << p << ", " << q << " of consecutive ids, dt = " << a << " tau";
            }
        const double t = steps*dt;
        const double reference = 6*D*(t - tau*(1 - std::exp(-t/tau)));
        std::printf("dt = %g tau: MSD %.6g um^2 after %g tau, Langevin %.6g um^2 (%+.2f %%)\n",
                    a, msd, t/tau, reference, 100*(msd/reference - 1));
        EXPECT_NEAR(msd/reference, 1.0, 0.02) << "dt = " << a << " tau";
    }
}

TEST(brownian, equipartition)
{
    for (double a : {0.01, 0.1, 1.0, 5.0})
    {
        const double dt = a*tau;
        LiggghtsRun run;
        freeSpheres(run, dt, 271828);
        advance(run, std::max(1L, std::lround(10/a)));
        double written = 0, half = 0;
        const int samples = 10;
        for (int s = 0; s < samples; s++)
        {
            double w, h;
            velocityVariance(run, dt, w, h);
            written += w/samples;
            half += h/samples;
            advance(run, std::max(1L, std::lround(2/a)));
        }
        std::printf("dt = %g tau: <w^2> m/kT = %.4f (half-step), <v^2> m/kT = %.4f (written; "
                    "scheme 1/(1 + dt/(2 tau)) = %.4f)\n",
                    a, half*m/kT, written*m/kT, 1/(1 + a/2));
        EXPECT_NEAR(half*m/kT, 1.0, 0.02) << "half-step velocities, dt = " << a << " tau";
        EXPECT_NEAR(written*m/kT, 1/(1 + a/2), 0.02) << "written velocities, dt = " << a << " tau";
        if (a == 0.01) EXPECT_NEAR(written*m/kT, 1.0, 0.02) << "equipartition, inertia resolved";
    }
}

TEST(brownian, reproducible)
{
    std::vector<double> first[3];
    const long seeds[3] = {99, 99, 100};
    for (int r = 0; r < 3; r++)
    {
        LiggghtsRun run;
        freeSpheres(run, 0.1*tau, seeds[r]);
        advance(run, 50);
        first[r] = positions(run);
    }
    EXPECT_TRUE(first[0] == first[1]) << "the same seed, other positions";
    EXPECT_FALSE(first[0] == first[2]) << "another seed, the same positions";
}


namespace
{

void lubricatedPairDiffusion(double explicitRatio)
{
    const double Rp = 0.15, h0 = 0.005, hOut = 0.1;     // um
    const double dt = 1e-4;                             // us
    const double mp = rho*4.0/3.0*pi*Rp*Rp*Rp;
    const double Kp = 6*pi*mu*Rp;
    const double Rs = 0.5*Rp;
    auto c = [&](double h) { return 6*pi*mu*Rs*Rs*(1/std::max(h, 0.001) - 1/hOut); };
    std::printf("c(h0) = %.3g K, relative relaxation time %.3g us\n",
                c(h0)/Kp, mp/(Kp + 2*c(h0)));

    LiggghtsRun run;
    lubricatedPairs(run, Rp, h0, dt, 20231, explicitRatio);
    const long n = run.nAtoms();
    ASSERT_EQ(n % 2, 0);
    // each pair: atoms 2k+1 (basis 0) and 2k+2 (basis 1), created point by
    // point; checked through their separation
    auto separation = [&](long k) { return run.x(2*k + 2)[0] - run.x(2*k + 1)[0]; };
    for (long k = 0; k < n/2; k++)
        ASSERT_NEAR(separation(k), 2*Rp + h0, 1e-9) << "pair " << k;

    advance(run, 1000);
    const int windows = 5;
    const long lagSteps = 500;
    const double lag = lagSteps*dt;
    double msd = 0, reference = 0;
    for (int w = 0; w < windows; w++)
    {
        std::vector<double> start(n/2);
        for (long k = 0; k < n/2; k++)
        {
            start[k] = separation(k);
            const double h = start[k] - 2*Rp;
            const double D = kT/(0.5*Kp + c(h));
            const double tauRel = mp/(Kp + 2*c(h));
            reference += 2*D*(lag - tauRel*(1 - std::exp(-lag/tauRel)));
        }
        advance(run, lagSteps);
        for (long k = 0; k < n/2; k++)
        {
            const double d = separation(k) - start[k];
            msd += d*d;
        }
    }
    msd /= windows*(n/2);
    reference /= windows*(n/2);
    std::printf("%ld pairs: mean square change of the separation over %g us %.4g um^2, "
                "reference %.4g um^2 (%+.2f %%); without lubrication noise %.4g\n",
                n/2, lag, msd, reference, 100*(msd/reference - 1),
                reference*Kp/(Kp + 2*c(h0)));
    EXPECT_NEAR(msd, reference, 0.05*reference);
    const double share = run.evaluate("f_colloid_implicit[7]");
    std::printf("share of the pairs damped explicitly: %g\n", share);
    EXPECT_EQ(share, explicitRatio > 0 ? 1.0 : 0.0);
}

// The pairs' velocities (the half-step ones, which move the spheres):
// the relative velocity along a pair's axis is an AR(1) process. With the
// drag K on both sides of the update (Crank-Nicolson: the free spheres'
// equipartition test), the pair implicit and noise of variances 2 K kT dt
// per sphere and 2 c kT dt per pair, it has the stationary variance
// (2 kT/m)/(1 + c dt/m); with the pair damped explicitly (from the step's
// start velocities) (2 kT/m)/(1 - c dt/m); the transverse components,
// which lubrication does not touch, 2 kT/m. At gap h0 c dt/m = 0.057: the
// two differ by 12 %; asserted within 1.5 % of each pair's reference at
// its gap (sampling error of 40 samples 40 steps apart, 5 relaxation
// times along the axis, of 3375 pairs: 0.4 %; across it, relaxing in
// m/K = 125 steps, about 0.5 %).
void lubricatedPairVelocities(double explicitRatio)
{
    const double Rp = 0.15, h0 = 0.005, hOut = 0.1;     // um
    const double dt = 1e-4;                             // us
    const double mp = rho*4.0/3.0*pi*Rp*Rp*Rp;
    const double Rs = 0.5*Rp;
    auto c = [&](double h) { return 6*pi*mu*Rs*Rs*(1/std::max(h, 0.001) - 1/hOut); };
    const int sign = explicitRatio > 0 ? -1 : 1;

    LiggghtsRun run;
    lubricatedPairs(run, Rp, h0, dt, 8128, explicitRatio);
    const long n = run.nAtoms();
    advance(run, 1000);
    auto half = [&](long id, int k) { return run.v(id)[k] + 0.5*dt*run.f(id)[k]/run.mass(id); };
    double along = 0, across = 0, reference = 0;
    const int samples = 40;
    for (int sample = 0; sample < samples; sample++)
    {
        for (long k = 0; k < n/2; k++)
        {
            const long a = 2*k + 1, b = 2*k + 2;
            const double h = run.x(b)[0] - run.x(a)[0] - 2*Rp;
            const double w[3] = {half(b, 0) - half(a, 0), half(b, 1) - half(a, 1), half(b, 2) - half(a, 2)};
            along += w[0]*w[0];
            across += 0.5*(w[1]*w[1] + w[2]*w[2]);
            reference += 2*kT/mp/(1 + sign*c(h)*dt/mp);
        }
        advance(run, 40);
    }
    const double free = 2*kT/mp;
    along /= samples*(n/2);
    across /= samples*(n/2);
    reference /= samples*(n/2);
    std::printf("%ld pairs, c dt/m %.3f at the gap %g um: relative velocity variance along the axis "
                "%.4f (2 kT/m), the scheme's %.4f (%+.2f %%); across %.4f\n",
                n/2, c(h0)*dt/mp, h0, along/free, reference/free, 100*(along/reference - 1),
                across/free);
    EXPECT_NEAR(along/reference, 1.0, 0.015) << "along the axis";
    EXPECT_NEAR(across/free, 1.0, 0.015) << "across the axis";
    EXPECT_EQ(run.evaluate("f_colloid_implicit[7]"), explicitRatio > 0 ? 1.0 : 0.0)
        << "the share of the pairs damped explicitly";
}

} // namespace

TEST(brownian, lubricatedPairDiffusion)
{
    lubricatedPairDiffusion(0);
}

TEST(brownian, lubricatedPairDiffusionExplicit)
{
    lubricatedPairDiffusion(0.25);
}

TEST(brownian, lubricatedPairVelocities)
{
    lubricatedPairVelocities(0);
}

TEST(brownian, lubricatedPairVelocitiesExplicit)
{
    lubricatedPairVelocities(0.25);
}


TEST(brownian, lubricatedWallDiffusion)
{
    const double Rp = 0.15, h0 = 0.005, hOut = 0.1;     // um
    const double dt = 1e-4;                             // us
    const double mp = rho*4.0/3.0*pi*Rp*Rp*Rp;
    const double Kp = 6*pi*mu*Rp;
    auto c = [&](double h) { return 6*pi*mu*Rp*Rp*(1/std::max(h, 0.001) - 1/hOut); };
    std::printf("c_w(h0) = %.3g K\n", c(h0)/Kp);

    LiggghtsRun run;
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(45.0)
       << "atom_modify sort 0 0.0\n"
          "lattice sc 1.5\n"
          // one layer: 59 x 59 spheres at z = R + h0
          "region layer block -44.9 44.9 -44.9 44.9 -0.1 0.1 units box\n"
          "create_atoms 1 region layer\n"
          "set group all diameter " << 2*Rp << " density " << rho << "\n"
          "displace_atoms all move 0 0 " << Rp + h0 << " units box\n"
          "velocity all set 0 0 0 units box\n"
       << lubrication(hOut, 2*hOut)     // a primitive wall: skin >= 2 h_out
       << "fix wall all wall/gran model walton_braun tangential history cohesion colloid/lub "
          "primitive type 2 zplane 0\n"
          "timestep " << dt << "\n"
          "fix integrate all nve/sphere\n"
       << dragAndNoise(Kp, 4711);
    run.commands(in.str());
    run.commands("run 0");
    const long n = run.nAtoms();
    for (long id = 1; id <= n; id++) ASSERT_NEAR(run.x(id)[2], Rp + h0, 1e-9);

    advance(run, 1000);
    const int windows = 5;
    const long lagSteps = 500;
    const double lag = lagSteps*dt;
    double msd = 0, reference = 0;
    for (int w = 0; w < windows; w++)
    {
        std::vector<double> start(n);
        for (long id = 1; id <= n; id++)
        {
            start[id - 1] = run.x(id)[2];
            const double h = start[id - 1] - Rp;
            const double D = kT/(Kp + c(h));
            const double tauRel = mp/(Kp + c(h));
            reference += 2*D*(lag - tauRel*(1 - std::exp(-lag/tauRel)));
        }
        advance(run, lagSteps);
        for (long id = 1; id <= n; id++)
        {
            const double d = run.x(id)[2] - start[id - 1];
            msd += d*d;
        }
    }
    msd /= windows*n;
    reference /= windows*n;
    std::printf("%ld spheres: mean square change of the gap over %g us %.4g um^2, "
                "reference %.4g um^2 (%+.2f %%); without the wall's noise %.4g\n",
                n, lag, msd, reference, 100*(msd/reference - 1),
                reference*Kp/(Kp + c(h0)));
    EXPECT_NEAR(msd, reference, 0.05*reference);
}
