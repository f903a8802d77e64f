/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: Brownian motion of the implicit drag update
    (fix_colloid_implicit.h, property/global brownianTemperature and
    brownianSeed) on free spheres in quiescent water.

    27 000 glass spheres of radius R = 0.5 um (m = 1.31 pg) on a cubic
    lattice 3 um apart (no contacts), Stokes drag K = 6 pi mu R (tau = m/K
    = 0.139 us), T = 293.15 K, started at rest.

    meanSquareDisplacement: dt = 0.1, 1 and 5 tau; after 20 tau
      (equilibration), the mean square displacement over a lag t of
      100 tau (1000 tau at 5 tau) against the Langevin closed form
      6 D (t - tau (1 - exp(-t/tau))), D = k_B T/K, within 2 % (sampling
      error of the mean of 27 000: 0.5 %). (The scheme's diffusion
      coefficient is exact at any step; positions sampled at steps of
      5 tau add a term of order dt^2/t: +6.6 % over 100 tau.) The
      spheres move independently: their mean displacement, each
      component, within 4 standard errors sqrt(MSD/(3 N)) of 0;
    equipartition: dt = 0.01, 0.1, 1 and 5 tau; after 10 tau, 10 samples
      2 tau apart: the half-step velocities (the ones that move the
      spheres) have <w_x^2> = k_B T/m at every step, the written ones the
      scheme's k_B T/(m (1 + dt/(2 tau))), so equipartition where inertia
      is resolved (dt = 0.01 tau): within 2 % (sampling error 0.3 %);
    reproducible: the same seed gives the same positions to the last bit,
      another seed other ones.
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"
#include "register_colloid_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
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

// 30^3 spheres 3 um apart, at rest, with drag into fluid at rest
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
          "fix Ksl all property/atom Ksl scalar yes no no " << K << "\n"
          "fix uf all property/atom uf vector yes no no 0 0 0\n"
          "fix bT all property/global brownianTemperature scalar " << T << "\n"
          "fix bS all property/global brownianSeed scalar " << seed << "\n";
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
