/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: the two-sphere form of the lubrication
    (lubricationFarField 1) in LIGGGHTS with the plugin's implicit update,
    for two equal glass spheres of the slot coater's size (a = 0.15 um) in
    water, each with the coupling's Stokes drag K = 6 pi mu a (per-atom Ksl
    and uf, as the CFD coupling sets them). The outer cut-off is 10 a,
    faded, so the runs stay in the uncut part (h <= 5 a).

    forceDrivenApproach: pulled together by equal and opposite constant
      forces F (fix addforce) in liquid at rest, from h = a to h = a/50.
      Overdamped (the Stokes time m/K = 12.5 ns is 1.5e-6 of the run; the
      steps are 28 of it, which the implicit update takes in force balance
      exactly, fix_colloid_implicit.h):
          dh/dt = -G(h/a) F/(3 pi mu a),
          G(u) = (6u^2 + 4u)/(6u^2 + 13u + 2)      (Honig et al. 1971),
      so the time to h1 is the integral of 3 pi mu a/(G F) dh, by Simpson's
      rule here; the DEM's agrees within 1 % (it is within 1e-4). The
      near-field form (lubricationFarField 0, mobility 2u/(2u + 1)) takes
      23 % less time to the same gap and fails.

    flowDrivenApproach: no force; the liquid in uniaxial compression along
      the line of centres, u_f = E (-x, y/2, z/2), set at both particles
      every step from their positions. The pair closes at
          dh/dt = -(1 - A(r)) E r a,   r = 2 + h/a,
      with Batchelor & Green's flow mobility 1 - A (the kernel's
      mobility::twoSpheresInFlow, held to exact values in
      unit.HydrodynamicMobility; here the update's flow factor is tested);
      the time from h = a to h = a/50 agrees with its integral within 1 %
      (it is within 1e-4). With the damping acting on the pair's velocity
      alone (the flow factor dropped) the pair closes at G instead of
      1 - A and takes 90 % longer; the near-field form takes 47 % longer.
      Both fail.

    forceDrivenApproachExplicit, flowDrivenApproachExplicit: the same
      pair with lubricationExplicitRatio 0.25 (weak pairs damped
      explicitly, fix_colloid_implicit.h) at a step where c dt/m is at
      most 0.2 down to a/50, so that the pair is damped explicitly at
      every step (the update's share of explicit pairs must be 1): under
      F = 0.1 nN, and in E = 1 1/us, the approach takes 650 and 69 Stokes
      times, so inertia counts (about 1 %) and the reference is the
      pair's equation of motion, integrated in the test (RK4):
          dh/dt = w,  m dw/dt = (K/G) ((1 - A) du - w)   (flow, du = -E r a)
                      m dw/dt = -2 F - (K/G) w            (force),
      K/G = K + 2c the pair's whole resistance to relative motion, w = 0
      at the start; the DEM's time to a/50 within 1 % of it.
\*---------------------------------------------------------------------------*/
#include "hydrodynamicMobility.H"
#include "liggghtsRun.H"

#include "atom.h"
#include "fix.h"
#include "lammps.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <sstream>

using namespace demTest;

namespace
{

const double pi = std::acos(-1.0);
const double a = 0.15;          // um
const double rho = 2.5;         // pg/um^3 (glass)
const double mu = 1.0;          // pg/(um us) = 1 mPa s (water)
const double K = 6*pi*mu*a;     // pg/us, Stokes drag of each sphere
const double hIn = 0.001;       // um, lubrication inner cut-off (roughness)
const double hStart = a, hEnd = a/50;

double honigG(double u)
{
    return (6*u*u + 4*u)/(6*u*u + 13*u + 2);
}

// Simpson's rule of f over [x0, x1] with n (even) intervals
double simpson(const std::function<double(double)>& f, double x0, double x1, int n)
{
    const double dx = (x1 - x0)/n;
    double s = f(x0) + f(x1);
    for (int i = 1; i < n; i++) s += (i % 2 ? 4 : 2)*f(x0 + i*dx);
    return s*dx/3;
}

// The pair at gap hStart on the x axis, symmetric about 0, with the
// two-sphere lubrication, drag into liquid at rest and step dt [us];
// explicitRatio > 0: weak pairs damped explicitly
void setUp(LiggghtsRun& run, double dt, const std::string& extra, double explicitRatio = 0)
{
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(2)
       << "fix m1 all property/global loadingStiffness peratomtypepair 2 1 1 1 1\n"
          "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
          "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
          "fix l1 all property/global liquidViscosity scalar " << mu << "\n"
       << LiggghtsRun::twoSphereLubrication(hIn, 10*a, explicitRatio)
       << "timestep " << dt << "\n"
          "fix integrate all nve/sphere\n"
          "fix Ksl all property/atom Ksl scalar yes no no " << K << "\n"
          "fix uf all property/atom uf vector yes no no 0 0 0\n"
          "create_atoms 1 single " << -(a + hStart/2) << " 0 0 units box\n"
          "create_atoms 1 single " << a + hStart/2 << " 0 0 units box\n"
          "set atom * diameter " << 2*a << " density " << rho << "\n"
          "velocity all set 0 0 0 units box\n"
       << extra
       << "run 0\n";
    run.commands(in.str());
}

// Steps of n until the gap falls to hEnd (before each, update()); the
// time of the crossing [us], interpolated, or -1 after tMax
double timeToEndGap(LiggghtsRun& run, double dt, double tMax, const std::function<void()>& update)
{
    auto gap = [&]() { return run.x(2)[0] - run.x(1)[0] - 2*a; };
    double t = 0, gOld = gap();
    while (t < tMax)
    {
        update();
        run.commands("run 1 pre no post no\n");
        t += dt;
        const double g = gap();
        if (g <= hEnd) return t - dt*(hEnd - g)/(gOld - g);
        gOld = g;
    }
    return -1;
}

// The liquid at both particles in uniaxial compression along x at the
// strain rate E [1/us]: u_f = E (-x, y/2, z/2)
void setCompression(LiggghtsRun& run, double E)
{
    LAMMPS_NS::Modify* modify = run.instance()->modify;
    LAMMPS_NS::Fix* uf = modify->fix[modify->find_fix("uf")];
    for (int id = 1; id <= 2; id++)
    {
        const double* x = run.x(id);
        double* u = uf->array_atom[run.instance()->atom->map(id)];
        u[0] = -E*x[0];
        u[1] = 0.5*E*x[1];
        u[2] = 0.5*E*x[2];
    }
}

// The time [us] for the pair's equation of motion (header) to close from
// hStart to hEnd, by RK4 with n steps of dtau over at most tMax: accel(h, w)
// is dw/dt
double inertialApproachTime(const std::function<double(double, double)>& accel, double tMax)
{
    const int n = 400000;
    const double dtau = tMax/n;
    double h = hStart, w = 0, t = 0;
    for (int s = 0; s < n; s++)
    {
        const double k1h = w, k1w = accel(h, w);
        const double k2h = w + 0.5*dtau*k1w, k2w = accel(h + 0.5*dtau*k1h, w + 0.5*dtau*k1w);
        const double k3h = w + 0.5*dtau*k2w, k3w = accel(h + 0.5*dtau*k2h, w + 0.5*dtau*k2w);
        const double k4h = w + dtau*k3w, k4w = accel(h + dtau*k3h, w + dtau*k3w);
        const double hNew = h + dtau*(k1h + 2*k2h + 2*k3h + k4h)/6;
        w += dtau*(k1w + 2*k2w + 2*k3w + k4w)/6;
        if (hNew <= hEnd) return t + dtau*(h - hEnd)/(h - hNew);
        h = hNew;
        t += dtau;
    }
    return -1;
}

const double mass = rho*4.0/3.0*pi*a*a*a;      // pg

// the step at which c dt/m is 0.2 at hEnd (c = K (1/G - 1)/2 grows as the
// gap closes; the fade is 1 below 5 a)
double explicitStep()
{
    const double cEnd = 0.5*K*(1/honigG(hEnd/a) - 1);
    return 0.2*mass/cEnd;
}

} // namespace


TEST(pairHydrodynamics, forceDrivenApproach)
{
    const double F = 1e-4;          // nN = 0.1 pN, each sphere
    // reference: integral of 3 pi mu a/(G F) over the gap
    const double T = simpson([F](double h) { return 3*pi*mu*a/(honigG(h/a)*F); }, hEnd, hStart, 2000);
    const double dt = T/20000;
    LiggghtsRun run;
    setUp(run, dt,
        "group first id 1\n"
        "group second id 2\n"
        "fix pull1 first addforce " + std::to_string(F) + " 0 0\n"
        "fix pull2 second addforce " + std::to_string(-F) + " 0 0\n");
    const double t = timeToEndGap(run, dt, 2*T, [] {});
    std::cout << "time from h = a to a/50 under F: DEM " << t << " us, Honig's G " << T
              << " us, relative difference " << (t - T)/T << std::endl;
    ASSERT_GT(t, 0) << "the gap did not reach a/50";
    EXPECT_NEAR(t, T, 0.01*T);
}


TEST(pairHydrodynamics, flowDrivenApproach)
{
    const double E = 1e-3;          // 1/us = 1000 1/s, strain rate
    // reference: integral of 1/((1 - A) E (2a + h)) over the gap
    const double T = simpson([E](double h)
    {
        return 1/(colloid::mobility::twoSpheresInFlow(h/a)*E*(2*a + h));
    }, hEnd, hStart, 2000);
    const double dt = T/20000;
    LiggghtsRun run;
    setUp(run, dt, "");
    const double t = timeToEndGap(run, dt, 2*T, [&]() { setCompression(run, E); });
    std::cout << "time from h = a to a/50 in uniaxial compression: DEM " << t
              << " us, Batchelor & Green's 1 - A " << T << " us, relative difference "
              << (t - T)/T << std::endl;
    ASSERT_GT(t, 0) << "the gap did not reach a/50";
    EXPECT_NEAR(t, T, 0.01*T);
}


TEST(pairHydrodynamics, forceDrivenApproachExplicit)
{
    const double F = 0.1;           // nN, each sphere
    const double T = inertialApproachTime([F](double h, double w)
    {
        return (-2*F - K/honigG(h/a)*w)/mass;
    }, 100.0);
    const double dt = explicitStep();
    LiggghtsRun run;
    setUp(run, dt,
        "group first id 1\n"
        "group second id 2\n"
        "fix pull1 first addforce " + std::to_string(F) + " 0 0\n"
        "fix pull2 second addforce " + std::to_string(-F) + " 0 0\n", 0.25);
    const double t = timeToEndGap(run, dt, 2*T, [] {});
    const double share = run.evaluate("f_colloid_implicit[7]");
    std::cout << "time from h = a to a/50 under F, damped explicitly (" << T/dt << " steps, share "
              << share << "): DEM " << t << " us, the equation of motion " << T
              << " us, relative difference " << (t - T)/T << std::endl;
    ASSERT_GT(T, 0) << "the reference did not reach a/50";
    ASSERT_GT(t, 0) << "the gap did not reach a/50";
    EXPECT_NEAR(t, T, 0.01*T);
    EXPECT_EQ(share, 1.0) << "pairs left in the implicit solve";
}


TEST(pairHydrodynamics, flowDrivenApproachExplicit)
{
    const double E = 1.0;           // 1/us, strain rate
    const double T = inertialApproachTime([E](double h, double w)
    {
        const double du = -E*(2*a + h);
        return K/honigG(h/a)*(colloid::mobility::twoSpheresInFlow(h/a)*du - w)/mass;
    }, 100.0);
    const double dt = explicitStep();
    LiggghtsRun run;
    setUp(run, dt, "", 0.25);
    const double t = timeToEndGap(run, dt, 2*T, [&]() { setCompression(run, E); });
    const double share = run.evaluate("f_colloid_implicit[7]");
    std::cout << "time from h = a to a/50 in uniaxial compression, damped explicitly (" << T/dt
              << " steps, share " << share << "): DEM " << t << " us, the equation of motion " << T
              << " us, relative difference " << (t - T)/T << std::endl;
    ASSERT_GT(T, 0) << "the reference did not reach a/50";
    ASSERT_GT(t, 0) << "the gap did not reach a/50";
    EXPECT_NEAR(t, T, 0.01*T);
    EXPECT_EQ(share, 1.0) << "pairs left in the implicit solve";
}
