/*---------------------------------------------------------------------------*\
    colloidFoam DEM tests (label stiff): many-body stiff cases of the
    implicit update of lubrication and drag (fix_colloid_implicit.h), run
    in LIGGGHTS in process. Particles of the slot-coater tutorial (d =
    0.3 um, 2500 kg/m^3) in water, lubrication cut-offs 1 nm and 0.1 um,
    Walton-Braun contact K1 = 1 N/m, e = 0.5; "strong" van der Waals:
    A = 1e-19 J.

    Each many-body case starts with every gap at the lubrication inner
    cut-off (1 nm), where c dt/m* is largest, and random velocities, and
    runs at the largest step the plugin's start-up checks accept (read
    from their log lines) and at ten times it with "timeStepCheck off":
      - lubrication only (no energy source): the kinetic energy of the
        half-step velocities (those of the implicit update) never grows,
        step by step (backward Euler on a positive semi-definite damping
        matrix contracts them in the mass norm); no gap closes;
      - van der Waals + lubrication + contact: finite, no particle passes
        another or a wall (overlap below R/4, the plugin's own bound for the
        pull at contact), and the kinetic energy stays below the van der
        Waals energy that the bonds can release (6 N A R/(6 h0), every
        particle with twelve neighbours at the inner cut-off h0, walls
        counted at their sphere-plane value).
    Cases: 13-particle FCC cluster; 108-particle FCC block on a primitive
    wall; a jittered dense FCC packing compressed between a primitive
    floor and a descending mesh wall (lubrication with the moving wall);
    one particle pinned between two primitive walls 1 nm from each; the
    13-particle cluster across a periodic face (the global solve with
    ghost partners); separate pairs, chains and a tetrahedron (the direct
    solves of small groups).

    approachAtStokesTime: two spheres (R = 0.5 um) released at rest 50 nm
    apart close to 5 nm under van der Waals (A = 1e-20 J), lubrication and
    the coupling's Stokes drag K = 6 pi mu R (per-atom Ksl, uf = 0, as
    colloidDEMFoam hands it). Reference: the overdamped closed form,
        T = int_5nm^50nm (K + 2 c(h))/(2 F(h)) dh,
    F(h) = A Rs/6 (1/h^2 - 1/hc^2), c(h) = 6 pi mu Rs^2 (1/h - 1/h_out),
    Rs = R/2, by Simpson's rule (checked against half the intervals;
    inertia changes T by about tau_S/T = 4e-5). At dt = tau_S = m/K the DEM
    must arrive within 1 % of T; at dt = 10 tau_S the gap must fall
    monotonically to 5 nm (stability). The van der Waals spring check,
    which guards the inner cut-off (0.4 nm, not reached), is off.
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace demTest;

namespace
{

const double pi = std::acos(-1.0);

// run units: um, us, pg
const double R = 0.15;          // um
const double rho = 2.5;         // pg/um^3
const double mu = 1.0;          // mPa s
const double hIn = 0.001;       // um, lubrication inner cut-off
const double hOut = 0.1;        // um, lubrication and van der Waals outer cut-off
const double K1 = 1000;         // nN/um = 1 N/m
const double hamaker = 1e-19;   // J
const double h0 = 4e-4;         // um, van der Waals inner cut-off (default)
const double v0 = 0.01;         // um/us, largest initial velocity component

typedef std::array<double, 3> Point;

struct Scene
{
    std::vector<Point> centres;     // [um]
    bool vanDerWaals = false;       // else lubrication only
    bool floor = false;             // primitive wall z = 0 under the particles
    double ceiling = NAN;           // primitive wall z = ceiling above them
    double meshCeiling = NAN;       // mesh wall starting at this z ...
    double meshSpeed = 0;           // ... moving down at this speed [um/us]
    std::string boundary = "f f f"; // LIGGGHTS boundary flags
};

// contact (Walton-Braun K1, e = 0.5, friction 0.3) and the liquid's
// viscosity, two atom types (particles, walls)
std::string contactAndLiquid()
{
    std::ostringstream in;
    in.precision(17);
    in << "fix m1 all property/global loadingStiffness peratomtypepair 2 "
       << K1 << ' ' << K1 << ' ' << K1 << ' ' << K1 << "\n"
          "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
          "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
          "fix l1 all property/global liquidViscosity scalar " << mu << "\n";
    return in.str();
}

// 13: a particle and its twelve FCC neighbours, all gaps hIn
std::vector<Point> cluster13()
{
    const double a = (2*R + hIn)/std::sqrt(2.0);
    std::vector<Point> p{{0, 0, 0}};
    for (int s1 : {-1, 1})
        for (int s2 : {-1, 1})
        {
            p.push_back({s1*a, s2*a, 0});
            p.push_back({s1*a, 0, s2*a});
            p.push_back({0, s1*a, s2*a});
        }
    return p;
}

// 3 x 3 x 3 FCC cells (108 particles), nearest gaps hIn, each centre moved
// by up to `jitter` [um] (random direction), lowest centres R + hIn above z = 0
std::vector<Point> fccBlock(double gap, double jitter, unsigned seed)
{
    const double L = std::sqrt(2.0)*(2*R + gap);
    const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Point> p;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
                for (const auto& b : basis)
                {
                    double d[3];
                    do { d[0] = u(random); d[1] = u(random); d[2] = u(random); }
                    while (d[0]*d[0] + d[1]*d[1] + d[2]*d[2] > 1);
                    p.push_back({(i + b[0] - 1.25)*L + jitter*d[0],
                                 (j + b[1] - 1.25)*L + jitter*d[1],
                                 (k + b[2])*L + jitter*d[2]});
                }
    const double zMin = std::min_element(p.begin(), p.end(),
        [](const Point& a, const Point& b) { return a[2] < b[2]; })->at(2);
    for (Point& c : p) c[2] += R + hIn - zMin;
    return p;
}

std::string input(const Scene& s, double dt, bool check)
{
    const std::string off = check ? "" : " timeStepCheck off";
    const std::string cohesion = s.vanDerWaals ? "colloid/vdw/lub" : "colloid/lub";
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(2.5, s.boundary) << contactAndLiquid()
       << "fix l2 all property/global lubricationInnerCutoff scalar " << hIn << "\n"
          "fix l3 all property/global lubricationOuterCutoff scalar " << hOut << "\n";
    if (s.vanDerWaals)
    {
        const double A = hamaker/fJ;
        in << "fix c1 all property/global hamakerConstant peratomtypepair 2 "
           << A << ' ' << A << ' ' << A << ' ' << A << "\n"
              "fix c2 all property/global vdwOuterCutoff scalar " << hOut << "\n";
    }
    in << "neighbor 0.2 bin\n"
          "neigh_modify delay 0\n"
          "pair_style gran model walton_braun tangential history cohesion " << cohesion << off << "\n"
          "pair_coeff * *\n"
          "timestep " << dt << "\n"
          "fix integrate all nve/sphere\n";
    const std::string wall = "all wall/gran model walton_braun tangential history cohesion " + cohesion;
    if (s.floor) in << "fix floor " << wall << " primitive type 2 zplane 0" << off << "\n";
    if (!std::isnan(s.ceiling)) in << "fix ceiling " << wall << " primitive type 2 zplane " << s.ceiling << off << "\n";
    if (!std::isnan(s.meshCeiling))
    {
        writeSquareStl("stiffCeiling.stl", 2.4, s.meshCeiling);
        in << "fix ceilingMesh all mesh/surface file stiffCeiling.stl type 2\n"
              "fix ceilingMove all move/mesh mesh ceilingMesh linear 0 0 " << -s.meshSpeed << "\n"
              "fix ceiling " << wall << " mesh n_meshes 1 meshes ceilingMesh" << off << "\n";
    }
    for (const Point& c : s.centres)
        in << "create_atoms 1 single " << c[0] << ' ' << c[1] << ' ' << c[2] << " units box\n";
    in << "set atom * diameter " << 2*R << " density " << rho << "\n";
    std::mt19937 random(12345);
    std::uniform_real_distribution<double> u(-v0, v0);
    for (std::size_t i = 1; i <= s.centres.size(); i++)
        in << "set atom " << i << " vx " << u(random) << " vy " << u(random) << " vz " << u(random) << "\n";
    in << "run 0\n";
    return in.str();
}

// the largest step [us] the start-up checks accept for this scene
double largestAcceptedStep(const Scene& s)
{
    LiggghtsRun probe;
    probe.commands(input(s, 1e-7, true));
    const double dt = probe.largestAllowedTimeStep();
    if (!(dt > 0)) throw std::runtime_error("no time-step limit was printed");
    // printed to 6 digits, perhaps rounded up
    return 0.9999*dt/us;
}

struct State
{
    double kinetic = 0;         // of the half-step velocities [fJ]
    double overlap = -HUGE_VAL; // largest particle-particle or wall overlap [um]
    double gap = HUGE_VAL;      // smallest surface gap [um]
    bool finite = true;
};

State measure(const LiggghtsRun& run, const Scene& s, double t)
{
    State st;
    const int n = static_cast<int>(s.centres.size());
    std::vector<Point> x(n);
    for (int i = 0; i < n; i++)
    {
        const double *xi = run.x(i + 1), *vi = run.v(i + 1), *fi = run.f(i + 1);
        const double m = run.mass(i + 1);
        for (int k = 0; k < 3; k++)
        {
            x[i][k] = xi[k];
            // velocity of the next position update (the update's v')
            const double vh = vi[k] + 0.5*run.dt()*fi[k]/m;
            st.kinetic += 0.5*m*vh*vh;
            st.finite = st.finite && std::isfinite(xi[k]) && std::isfinite(vh);
        }
    }
    auto surface = [&](double gap)
    {
        st.gap = std::min(st.gap, gap);
        st.overlap = std::max(st.overlap, -gap);
    };
    for (int i = 0; i < n; i++)
    {
        for (int j = i + 1; j < n; j++)
        {
            double d[3];
            for (int k = 0; k < 3; k++)
            {
                d[k] = x[i][k] - x[j][k];
                // nearest periodic image in x and y (box 5 um)
                if (k < 2 && s.boundary[2*k] == 'p') d[k] -= 5.0*std::round(d[k]/5.0);
            }
            surface(std::sqrt(d[0]*d[0] + d[1]*d[1] + d[2]*d[2]) - 2*R);
        }
        if (s.floor) surface(x[i][2] - R);
        if (!std::isnan(s.ceiling)) surface(s.ceiling - x[i][2] - R);
        if (!std::isnan(s.meshCeiling)) surface(s.meshCeiling - s.meshSpeed*t - x[i][2] - R);
    }
    return st;
}

// runs the scene at the largest accepted step and at 10 times it
void stiffCase(const Scene& s, int nSteps)
{
    const double accepted = largestAcceptedStep(s);
    const double m = rho*4.0/3.0*pi*R*R*R;
    const double c = 6*pi*mu*(R/2)*(R/2)*(1/hIn - 1/hOut);
    const int n = static_cast<int>(s.centres.size());
    // energy the van der Waals bonds can release [fJ]
    const double wellEnergy = 6*n*hamaker*(R*um)/(6*h0*um)/fJ;

    for (double factor : {1.0, 10.0})
    {
        const double dt = factor*accepted;
        LiggghtsRun run;
        run.commands(input(s, dt, factor == 1.0));
        State start = measure(run, s, 0), last = start;
        double maxKinetic = start.kinetic, maxOverlap = start.overlap;
        bool kineticGrew = false;
        double grewBy = 0;
        int step = 0;
        for (; step < nSteps; step++)
        {
            run.commands("run 1 pre no post no\n");
            const State now = measure(run, s, (step + 1)*dt);
            ASSERT_TRUE(now.finite) << "dt " << dt << " us: not finite at step " << step + 1;
            if (now.kinetic > last.kinetic*(1 + 1e-9) + 1e-12*start.kinetic)
            {
                kineticGrew = true;
                grewBy = std::max(grewBy, now.kinetic/last.kinetic);
            }
            maxKinetic = std::max(maxKinetic, now.kinetic);
            maxOverlap = std::max(maxOverlap, now.overlap);
            last = now;
            if (!s.vanDerWaals)
            {
                ASSERT_GT(now.gap, 0) << "dt " << dt << " us: a gap closed at step " << step + 1
                    << " (the lubrication-only cases must stay out of contact)";
            }
        }
        std::cout << (s.vanDerWaals ? "van der Waals + lubrication" : "lubrication only")
                  << ", " << n << " particles, dt = " << dt << " us (" << factor
                  << " x the largest accepted), c dt/m* at the inner cut-off " << c*dt/(m/2)
                  << ": kinetic energy " << start.kinetic << " -> " << last.kinetic
                  << " fJ (largest " << maxKinetic << "), largest overlap " << maxOverlap
                  << " um, conjugate-gradient iterations per step "
                  << run.evaluate("f_colloid_implicit[2]") << " (largest "
                  << run.evaluate("f_colloid_implicit[3]") << ")" << std::endl;
        EXPECT_EQ(run.evaluate("f_colloid_implicit[4]"), 0) << "updates that did not converge";
        EXPECT_LT(maxOverlap, 0.25*R) << "dt " << dt << " us: a particle passes another or a wall";
        if (s.vanDerWaals)
        {
            EXPECT_LT(maxKinetic, start.kinetic + wellEnergy)
                << "dt " << dt << " us: more kinetic energy than the van der Waals bonds can release";
        }
        else
        {
            EXPECT_FALSE(kineticGrew) << "dt " << dt << " us: the kinetic energy grew, by a factor "
                                      << grewBy << " in one step, without an energy source";
            EXPECT_LT(last.kinetic, start.kinetic) << "dt " << dt << " us: nothing was damped";
        }
    }
}

} // namespace


TEST(stiff, lubricatedCluster13)
{
    Scene s;
    s.centres = cluster13();
    stiffCase(s, 200);
}

TEST(stiff, lubricatedClusterAcrossPeriodicFace)
{
    // the cluster straddles the periodic face x = +-2.5 um: its pairs
    // with periodic images go to the global solve (ghost partners)
    Scene s;
    s.centres = cluster13();
    for (Point& c : s.centres)
    {
        c[0] += 2.5;
        if (c[0] >= 2.5) c[0] -= 5.0;
    }
    s.boundary = "p p f";
    stiffCase(s, 200);
}

TEST(stiff, lubricatedSmallGroups)
{
    // separate pairs, chains of 3 and 4 and a tetrahedron at the inner
    // cut-off (the direct solves), 0.5 um apart from each other
    const double a = 2*R + hIn;
    Scene s;
    for (int g = 0; g < 4; g++)
    {
        const double x0 = -1.8 + 1.2*g;
        const int length = 2 + g;
        if (g < 3)
            for (int k = 0; k < length; k++) s.centres.push_back({x0, -1.5 + k*a, 0});
        else
        {
            s.centres.push_back({x0, 0, 0});
            s.centres.push_back({x0 + a, 0, 0});
            s.centres.push_back({x0 + a/2, a*std::sqrt(3.0)/2, 0});
            s.centres.push_back({x0 + a/2, a*std::sqrt(3.0)/6, a*std::sqrt(2.0/3.0)});
        }
    }
    stiffCase(s, 200);
}

TEST(stiff, lubricatedBlock108OnWall)
{
    Scene s;
    s.centres = fccBlock(hIn, 0, 1);
    s.floor = true;
    stiffCase(s, 200);
}

TEST(stiff, vdwCluster13)
{
    Scene s;
    s.centres = cluster13();
    s.vanDerWaals = true;
    stiffCase(s, 300);
}

TEST(stiff, vdwBlock108OnWall)
{
    Scene s;
    s.centres = fccBlock(hIn, 0, 1);
    s.vanDerWaals = true;
    s.floor = true;
    stiffCase(s, 300);
}

TEST(stiff, compressedRandomPacking)
{
    Scene s;
    // nearest gaps 6 nm less up to 2 x 2.5 nm of jitter: 1 to 11 nm
    s.centres = fccBlock(0.006, 0.0025, 7);
    s.vanDerWaals = true;
    s.floor = true;
    double zMax = 0;
    for (const Point& c : s.centres) zMax = std::max(zMax, c[2]);
    s.meshCeiling = zMax + R + hIn;
    s.meshSpeed = 0.05;     // um/us = m/s
    stiffCase(s, 300);
}

TEST(stiff, pinnedBetweenWalls)
{
    for (bool vdw : {false, true})
    {
        Scene s;
        s.centres = {{0, 0, R + hIn}};
        s.floor = true;
        s.ceiling = 2*R + 2*hIn;
        s.vanDerWaals = vdw;
        stiffCase(s, 200);
    }
}


namespace
{

// overdamped approach time [s] of two spheres from gap a to gap b [m]
double overdampedApproach(double A, double Rs, double hc, double muSI, double hOutSI,
                          double K, double a, double b, int intervals)
{
    auto integrand = [&](double h)
    {
        const double F = A*Rs/6*(1/(h*h) - 1/(hc*hc));
        const double c = 6*pi*muSI*Rs*Rs*(1/h - 1/hOutSI);
        return (K + 2*c)/(2*F);
    };
    const double dh = (b - a)/intervals;
    double sum = integrand(a) + integrand(b);
    for (int i = 1; i < intervals; i++) sum += (i % 2 ? 4 : 2)*integrand(a + i*dh);
    return sum*dh/3;
}

} // namespace


TEST(stiff, approachAtStokesTime)
{
    const double Rp = 0.5;              // um
    const double A = 1e-20;             // J
    const double hStart = 0.05, hEnd = 0.005;   // um
    const double K = 6*pi*mu*Rp;        // pg/us = 1e-9 kg/s
    const double m = rho*4.0/3.0*pi*Rp*Rp*Rp;
    const double tau = m/K;             // us

    const double T = overdampedApproach(A, Rp/2*um, hOut*um, mu*1e-3, hOut*um,
                                        K*1e-9, hEnd*um, hStart*um, 200000)/us;
    ASSERT_NEAR(overdampedApproach(A, Rp/2*um, hOut*um, mu*1e-3, hOut*um,
                                   K*1e-9, hEnd*um, hStart*um, 100000)/us, T, 1e-8*T);

    for (double factor : {1.0, 10.0})
    {
        const double dt = factor*tau;
        LiggghtsRun run;
        std::ostringstream in;
        in.precision(17);
        in << LiggghtsRun::header(2)
           << "fix m1 all property/global loadingStiffness peratomtypepair 2 100 100 100 100\n"
              "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
              "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
              "fix c1 all property/global hamakerConstant peratomtypepair 2 "
           << A/fJ << ' ' << A/fJ << ' ' << A/fJ << ' ' << A/fJ << "\n"
              "fix c2 all property/global vdwOuterCutoff scalar " << hOut << "\n"
              "fix l1 all property/global liquidViscosity scalar " << mu << "\n"
              "fix l2 all property/global lubricationInnerCutoff scalar " << hIn << "\n"
              "fix l3 all property/global lubricationOuterCutoff scalar " << hOut << "\n"
              "neighbor 0.1 bin\n"
              "neigh_modify delay 0\n"
              "pair_style gran model walton_braun tangential history cohesion colloid/vdw/lub timeStepCheck off\n"
              "pair_coeff * *\n"
              "timestep " << dt << "\n"
              "fix integrate all nve/sphere\n"
              "fix Ksl all property/atom Ksl scalar yes no no " << K << "\n"
              "fix uf all property/atom uf vector yes no no 0 0 0\n"
              "create_atoms 1 single 0 0 0 units box\n"
              "create_atoms 1 single " << 2*Rp + hStart << " 0 0 units box\n"
              "set atom * diameter " << 2*Rp << " density " << rho << "\n"
              "velocity all set 0 0 0 units box\n"
              "run 0\n";
        run.commands(in.str());

        auto gap = [&]() { return run.x(2)[0] - run.x(1)[0] - 2*Rp; };
        double t = 0, tHit = -1, gOld = gap();
        bool monotone = true;
        while (tHit < 0 && t < 2*T)
        {
            // chunks while far from the end gap, single steps near it
            const int n = gOld > 2*hEnd ? std::max(1, int(0.01*T/dt)) : 1;
            run.commands("run " + std::to_string(n) + " pre no post no\n");
            t += n*dt;
            const double g = gap();
            ASSERT_TRUE(std::isfinite(g));
            monotone = monotone && g < gOld;
            if (g <= hEnd) tHit = t - n*dt*(hEnd - g)/(gOld - g);
            gOld = g;
        }
        std::cout << "dt = " << factor << " tau_S (" << dt << " us): time to a 5 nm gap "
                  << tHit << " us, overdamped closed form " << T << " us, relative error "
                  << (tHit - T)/T << std::endl;
        ASSERT_GT(tHit, 0) << "dt " << dt << " us: the gap did not reach " << hEnd << " um";
        EXPECT_TRUE(monotone) << "dt " << dt << " us: the gap did not fall monotonically";
        if (factor == 1.0) EXPECT_NEAR(tHit, T, 0.01*T) << "dt = tau_S";
    }
}


/*---------------------------------------------------------------------------*\
    dragRelaxation: one particle released at rest in a fluid moving at U,
    drag K (u_f - v) from the per-atom Ksl and uf only (the implicit update
    is attached by a colloid/lub pair style; there is no partner). The
    update takes the trapezoidal rule for the drag, so its velocities are
        v_1/2 = U (1 - g(a/2)),  v_(k+1/2) = U (1 - g(a/2) g(a)^k),
        g(b) = (1 - b/2)/(1 + b/2),  a = K dt/m
    (the first over the half step before the first step), to round-off, at
    a = 0.1, 1 and 10. Also: within 1e-3 U of the exact U (1 - exp(-t/tau))
    at a = 0.1 (second order), |v - U| shrinking every step at a = 10
    (A-stable), and the drag impulse the update hands to the coupling
    (colloidDragImpulse) equal to the particle's change of momentum.
\*---------------------------------------------------------------------------*/
TEST(stiff, dragRelaxation)
{
    const double U = 0.01;              // um/us
    const double m = rho*4.0/3.0*pi*R*R*R;
    const double K = 6*pi*mu*R;         // pg/us
    for (double a : {0.1, 1.0, 10.0})
    {
        const double dt = a*m/K;
        LiggghtsRun run;
        std::ostringstream in;
        in.precision(17);
        in << LiggghtsRun::header(2) << contactAndLiquid()
           << "pair_style gran model walton_braun tangential history cohesion colloid/lub timeStepCheck off\n"
              "pair_coeff * *\n"
              "timestep " << dt << "\n"
              "fix integrate all nve/sphere\n"
              "fix Ksl all property/atom Ksl scalar yes no no " << K << "\n"
              "fix uf all property/atom uf vector yes no no " << U << " 0 0\n"
              "fix colloidDragImpulse all property/atom colloidDragImpulse vector yes no no 0 0 0\n"
              "create_atoms 1 single 0 0 0 units box\n"
              "set atom 1 diameter " << 2*R << " density " << rho << "\n"
              "velocity all set 0 0 0 units box\n"
              "run 0\n";
        run.commands(in.str());
        auto halfStep = [&]() { return run.v(1)[0] + 0.5*dt*run.f(1)[0]/run.mass(1); };
        auto g = [](double b) { return (1 - b/2)/(1 + b/2); };
        const double v0 = halfStep();
        EXPECT_NEAR(v0, U*(1 - g(a/2)), 1e-12*U) << "a = " << a << ": the half step before the first";
        double expectedFactor = g(a/2), worstExact = 0, last = std::fabs(v0 - U);
        bool shrinking = true;
        for (int k = 1; k <= 30; k++)
        {
            run.commands("run 1 pre no post no\n");
            expectedFactor *= g(a);
            const double v = halfStep();
            ASSERT_NEAR(v, U*(1 - expectedFactor), 1e-12*U) << "a = " << a << ", step " << k;
            const double t = (k + 0.5)*dt;
            worstExact = std::max(worstExact, std::fabs(v - U*(1 - std::exp(-K*t/m))));
            shrinking = shrinking && std::fabs(v - U) < last;
            last = std::fabs(v - U);
        }
        // the impulse of the 30 steps, against m (v_30 - v_1/2)
        const double impulse = run.evaluate("f_colloidDragImpulse[1][1]");
        EXPECT_NEAR(impulse, m*(halfStep() - v0), 1e-12*m*U) << "a = " << a << ": drag impulse";
        std::cout << "K dt/m = " << a << ": largest difference from U (1 - exp(-t/tau)) "
                  << worstExact/U << " U" << std::endl;
        if (a == 0.1) EXPECT_LT(worstExact, 1e-3*U) << "second order at K dt/m = 0.1";
        if (a == 10.0) EXPECT_TRUE(shrinking) << "|v - U| grew at K dt/m = 10";
    }
}


/*---------------------------------------------------------------------------*\
    movingWallLubrication: a particle at rest 2 nm above a mesh wall that
    moves towards it at u (fix move/mesh); lubrication only. One step of
    the implicit update must give the backward-Euler velocity with the
    wall's velocity,
        v' = (m v + dt c u)/(m + dt c),  c = 6 pi mu R^2 (1/h - 1/h_out),
    h the gap at the step's force evaluation, to round-off.
\*---------------------------------------------------------------------------*/
TEST(stiff, movingWallLubrication)
{
    const double u = 0.1;           // um/us, wall towards the particle
    const double h0 = 0.002;        // um
    const double dt = 1e-4;         // us
    writeSquareStl("movingWall.stl", 1.5, 0);
    LiggghtsRun run;
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(2) << contactAndLiquid()
       << "fix l2 all property/global lubricationInnerCutoff scalar " << hIn << "\n"
          "fix l3 all property/global lubricationOuterCutoff scalar " << hOut << "\n"
          "neighbor 0.2 bin\n"
          "neigh_modify delay 0\n"
          "pair_style gran model walton_braun tangential history cohesion colloid/lub\n"
          "pair_coeff * *\n"
          "timestep " << dt << "\n"
          "fix integrate all nve/sphere\n"
          "fix wallMesh all mesh/surface file movingWall.stl type 2\n"
          "fix wallMove all move/mesh mesh wallMesh linear 0 0 " << u << "\n"
          "fix wall all wall/gran model walton_braun tangential history cohesion colloid/lub "
          "mesh n_meshes 1 meshes wallMesh\n"
          "create_atoms 1 single 0.1 -0.2 " << R + h0 << " units box\n"
          "set atom 1 diameter " << 2*R << " density " << rho << "\n"
          "velocity all set 0 0 0 units box\n"
          "run 0\n";
    run.commands(in.str());
    const double m = run.mass(1);
    for (int k = 1; k <= 3; k++)
    {
        const double v = run.v(1)[2] + 0.5*dt*run.f(1)[2]/m;
        const double z = run.x(1)[2];
        run.commands("run 1 pre no post no\n");
        // positions at the force evaluation of this step
        const double h = z + dt*v - R - u*k*dt;
        const double c = 6*pi*mu*R*R*(1/h - 1/hOut);
        const double expected = (m*v + dt*c*u)/(m + dt*c);
        const double vNew = run.v(1)[2] + 0.5*dt*run.f(1)[2]/m;
        std::cout << "step " << k << ": gap " << h << " um, c dt/m " << c*dt/m
                  << ", v' " << vNew << " um/us, backward Euler " << expected << std::endl;
        EXPECT_NEAR(vNew, expected, 1e-9*std::fabs(expected)) << "step " << k;
    }
}


namespace
{

// Weak pairs damped explicitly (lubricationExplicitRatio, fix_colloid_
// implicit.h) in a 108-particle FCC block, lubrication only, two-sphere
// form (faded at hOutFar, at least twice the gap), no drag, at the step
// where c dt/m of the nearest pairs (gap `gap`) is `nearestRatio`, with
// lubricationExplicitRatio `explicitRatio` (0: every pair in the solve).
// Returns the share of the update's pairs damped explicitly, and the
// half-step velocities at the end in `velocities` [um/us]; asserts that
// the kinetic energy of the half-step velocities never grows (with every
// particle's sum of explicit c dt/m at most 1/2, v^T A v cannot grow,
// fix_colloid_implicit.h: the kinetic energy itself when no pair is
// implicit; asserted on the kinetic energy in every case), that no gap
// closes and that the relative motion is damped.
double weakPairsBlock(double gap, double hOutFar, double nearestRatio, int nSteps,
                      double explicitRatio = 0.25, std::vector<double>* velocities = nullptr)
{
    Scene s;
    s.centres = fccBlock(gap, 0, 1);
    const double m = rho*4.0/3.0*pi*R*R*R;
    // c = K (1/G - 1)/2 at u = gap/R (G: Honig et al.; uncut: the fade
    // starts at half the cut-off)
    const double u = gap/R;
    const double G = (6*u*u + 4*u)/(6*u*u + 13*u + 2);
    const double c = 0.5*6*pi*mu*R*(1/G - 1);
    const double dt = nearestRatio*m/c;
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(2.5) << contactAndLiquid()
       << LiggghtsRun::twoSphereLubrication(hIn, hOutFar, explicitRatio)
       << "timestep " << dt << "\n"
          "fix integrate all nve/sphere\n";
    for (const Point& p : s.centres)
        in << "create_atoms 1 single " << p[0] << ' ' << p[1] << ' ' << p[2] << " units box\n";
    in << "set atom * diameter " << 2*R << " density " << rho << "\n";
    std::mt19937 random(12345);
    std::uniform_real_distribution<double> v(-v0, v0);
    for (std::size_t i = 1; i <= s.centres.size(); i++)
        in << "set atom " << i << " vx " << v(random) << " vy " << v(random) << " vz " << v(random) << "\n";
    in << "run 0\n";
    LiggghtsRun run;
    run.commands(in.str());
    const State start = measure(run, s, 0);
    State last = start;
    double grewBy = 1;
    for (int step = 0; step < nSteps; step++)
    {
        run.commands("run 1 pre no post no\n");
        const State now = measure(run, s, (step + 1)*dt);
        EXPECT_TRUE(now.finite) << "not finite at step " << step + 1;
        EXPECT_GT(now.gap, 0) << "a gap closed at step " << step + 1;
        if (!now.finite || !(now.gap > 0)) break;
        if (now.kinetic > last.kinetic*(1 + 1e-9) + 1e-12*start.kinetic)
            grewBy = std::max(grewBy, now.kinetic/last.kinetic);
        last = now;
    }
    if (velocities)
    {
        velocities->clear();
        for (std::size_t i = 1; i <= s.centres.size(); i++)
            for (int k = 0; k < 3; k++)
                velocities->push_back(run.v(i)[k] + 0.5*dt*run.f(i)[k]/run.mass(i));
    }
    const double share = run.evaluate("f_colloid_implicit[7]");
    std::cout << "weak pairs explicitly (ratio " << explicitRatio << "), 108-particle FCC block, gap " << gap << " um, cut-off "
              << hOutFar << " um, nearest c dt/m " << nearestRatio << " (dt " << dt
              << " us): explicit share " << share << ", kinetic energy " << start.kinetic
              << " -> " << last.kinetic << " fJ, largest growth in a step " << grewBy << std::endl;
    EXPECT_EQ(grewBy, 1) << "the kinetic energy grew without an energy source";
    EXPECT_LT(last.kinetic, start.kinetic) << "nothing was damped";
    return share;
}

// The share of the pair updates of the block (nearest gap `gap`, no other
// pair within the cut-off hOutFar) that go explicit over the set-up's
// half step and nSteps steps when each nearest pair has c dt/m = ratio:
// both particles with at most 1/(2 ratio) neighbours in a step, at most
// 1/ratio in the half step (vector [7] counts both)
double expectedBlockShare(double gap, double hOutFar, double ratio, int nSteps)
{
    const std::vector<Point> p = fccBlock(gap, 0, 1);
    const std::size_t n = p.size();
    auto distance = [&](std::size_t i, std::size_t j)
    {
        return std::sqrt((p[i][0] - p[j][0])*(p[i][0] - p[j][0]) + (p[i][1] - p[j][1])*(p[i][1] - p[j][1])
                         + (p[i][2] - p[j][2])*(p[i][2] - p[j][2]));
    };
    std::vector<int> neighbours(n, 0);
    for (std::size_t i = 0; i < n; i++)
        for (std::size_t j = i + 1; j < n; j++)
            if (distance(i, j) - 2*R < hOutFar)
            {
                // every pair in range a nearest one: the same c for all
                EXPECT_NEAR(distance(i, j) - 2*R, gap, 1e-9) << "a pair beyond the nearest gap in range";
                neighbours[i]++;
                neighbours[j]++;
            }
    auto explicitPairs = [&](double pairRatio)
    {
        const int most = static_cast<int>(0.5/pairRatio);
        int count = 0;
        for (std::size_t i = 0; i < n; i++)
            for (std::size_t j = i + 1; j < n; j++)
                if (distance(i, j) - 2*R < hOutFar)
                    count += neighbours[i] <= most && neighbours[j] <= most;
        return count;
    };
    int pairs = 0;
    for (int k : neighbours) pairs += k;
    pairs /= 2;
    return (explicitPairs(0.5*ratio) + nSteps*double(explicitPairs(ratio)))/((nSteps + 1.0)*pairs);
}

} // namespace


TEST(stiff, weakPairsExplicitOpenBlock)
{
    // nearest gap 0.2 um, cut-off 0.4 um (the next neighbours 0.41 um
    // apart): at most twelve neighbours each, at c dt/m 0.04, so every
    // particle's sum is at most 0.48 and every pair is damped explicitly
    const double share = weakPairsBlock(0.2, 0.4, 0.04, 200);
    EXPECT_EQ(share, 1.0) << "pairs left in the implicit solve";
}

TEST(stiff, weakPairsExplicitMixedBlock)
{
    // the same at c dt/m 0.058: the block's particles have 12, 8, 5 or 3
    // neighbours; the inner particles' twelve add up to 0.70, so their
    // pairs stay in the solve, while those between particles of the
    // surface (at most eight: 0.46) go explicit (and every pair in the
    // set-up's half step): the share must be that of the geometry (within
    // 1e-3: the particles move about 3 nm and their c by 2.4 %, while a
    // surface particle's sum would need 8 % to pass 1/2), and the
    // velocities after 200 steps must agree with those of the update with
    // every pair in the solve within 0.06, the order of their difference
    const double ratio = 0.058;
    std::vector<double> mixed, implicit;
    const double share = weakPairsBlock(0.2, 0.4, ratio, 200, 0.25, &mixed);
    const double expected = expectedBlockShare(0.2, 0.4, ratio, 200);
    std::cout << "share of the pair updates between particles with at most eight neighbours: " << expected
              << std::endl;
    ASSERT_GT(expected, 0.1);
    ASSERT_LT(expected, 0.9);
    EXPECT_NEAR(share, expected, 1e-3) << "not the pairs whose particles' sums are within 1/2";
    weakPairsBlock(0.2, 0.4, ratio, 200, 0.0, &implicit);
    double difference = 0, norm = 0;
    for (std::size_t k = 0; k < mixed.size(); k++)
    {
        difference += (mixed[k] - implicit[k])*(mixed[k] - implicit[k]);
        norm += implicit[k]*implicit[k];
    }
    // both are first order in c dt/m (0.058 here) and they differ there:
    // the explicit damping lags by a step
    std::cout << "velocities after 200 steps, mixed against all in the solve: relative difference "
              << std::sqrt(difference/norm) << std::endl;
    EXPECT_LT(std::sqrt(difference/norm), 0.06)
        << "the mixed update departs from the implicit one by more than c dt/m";
}

TEST(stiff, weakPairsExplicitDenseBlock)
{
    // nearest gap 50 nm at c dt/m 0.24 and the two-sphere form to 0.9 um:
    // nearly every pair is a candidate (c dt/m at most 0.25 at both ends),
    // with up to a hundred per particle, whose sums far exceed 1/2, so all
    // stay in the solve (without that bound 96 % of them went explicit and
    // the kinetic energy grew threefold in a step)
    const double share = weakPairsBlock(0.05, 0.9, 0.24, 200);
    EXPECT_LT(share, 0.01) << "pairs damped explicitly whose particles' sums exceed 1/2";
}

TEST(stiff, weakPairsExplicitUnequalMasses)
{
    // two pairs of a 0.3 um and a 0.1 um sphere (masses 27:1), 0.1 um
    // apart, one listed small first and one big first, two-sphere form to
    // 0.4 um, no drag, at the step where c dt/m is 0.4 at the small sphere
    // (within the budget of its sum, 1/2, but above the ratio 0.25) and
    // 0.015 at the big one: neither pair may go explicit in a step (judged
    // by the first or the second particle's mass alone, one of them would);
    // the set-up's half step (c dt/(2m) = 0.2 at the small sphere, within
    // the ratio) takes both explicit once: 2 of the 102 pair updates of
    // the set-up and 50 steps
    const double Rb = 0.15, Rs = 0.05, gap = 0.1;
    const double ms = rho*4.0/3.0*pi*Rs*Rs*Rs;
    const double Rstar = Rb*Rs/(Rb + Rs);
    const double u = gap/(2*Rstar);
    const double G = (6*u*u + 4*u)/(6*u*u + 13*u + 2);
    const double c = 6*pi*mu*Rstar*(1/G - 1);
    const double dt = 0.4*ms/c;
    std::ostringstream in;
    in.precision(17);
    in << LiggghtsRun::header(2.5) << contactAndLiquid()
       << LiggghtsRun::twoSphereLubrication(hIn, 0.4, 0.25)
       << "timestep " << dt << "\n"
          "fix integrate all nve/sphere\n"
          "create_atoms 1 single -1 0 0 units box\n"
          "create_atoms 1 single " << -1 + Rs + gap + Rb << " 0 0 units box\n"
          "create_atoms 1 single 1 0 0 units box\n"
          "create_atoms 1 single " << 1 + Rb + gap + Rs << " 0 0 units box\n"
          "set atom 1 diameter " << 2*Rs << " density " << rho << "\n"
          "set atom 2 diameter " << 2*Rb << " density " << rho << "\n"
          "set atom 3 diameter " << 2*Rb << " density " << rho << "\n"
          "set atom 4 diameter " << 2*Rs << " density " << rho << "\n"
          "set atom 1 vx 0.01\n"
          "set atom 4 vx -0.01\n"
          "run 0\n";
    LiggghtsRun run;
    run.commands(in.str());
    auto kinetic = [&]()
    {
        double e = 0;
        for (int id = 1; id <= 4; id++)
            for (int k = 0; k < 3; k++)
            {
                const double vh = run.v(id)[k] + 0.5*dt*run.f(id)[k]/run.mass(id);
                e += 0.5*run.mass(id)*vh*vh;
            }
        return e;
    };
    const double start = kinetic();
    double last = start, grewBy = 1;
    for (int step = 0; step < 50; step++)
    {
        run.commands("run 1 pre no post no\n");
        const double now = kinetic();
        if (now > last*(1 + 1e-9)) grewBy = std::max(grewBy, now/last);
        last = now;
    }
    const double share = run.evaluate("f_colloid_implicit[7]");
    std::cout << "unequal pairs, c dt/m 0.4 at the small sphere, 0.015 at the big: explicit share " << share
              << ", kinetic energy " << start << " -> " << last << " fJ, largest growth in a step "
              << grewBy << std::endl;
    EXPECT_NEAR(share, 2.0/102, 1e-12) << "a pair judged by one particle's mass went explicit";
    EXPECT_EQ(grewBy, 1) << "the kinetic energy grew without an energy source";
}
