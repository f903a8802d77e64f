/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: extreme cases that the plugin stops at the start
    of the run because the time step is too long for them (stock
    "liggghts" program, plugin preloaded): the exit status is non-zero and
    the message names the limit, its time scale and the largest allowed
    time step.

    References, closed forms (seed 002 eq 12; Walton-Braun contact):
      van der Waals spring  t = sqrt(m* /k),  k = A R* /(3 h0^3),
                            m* = m/2, R* = R/2 (two equal spheres),
                            limit dt <= t/10;
      Walton-Braun contact  t = pi/2 sqrt(m* /K1) (1 + e), m* = m against a
                            wall, limit dt <= t/20;
    m = 4/3 pi R^3 rho, h0 = 0.4 nm (the inner cut-off).
    - 50 nm particles (R = 25 nm) at dt = 0.05 ns, a step that suits
      micron particles: the van der Waals spring (0.35 ns) stops the run;
      with "timeStepCheck off" it runs, with a warning.
    - Hamaker constant 1e-18 J (100 times water-glass), R = 0.5 um,
      dt = 0.1 ns: the van der Waals spring (0.71 ns) stops the run.
    - A wall 100 times stiffer than the particles: the particle-wall
      contact duration stops the run where the pairs' would not.
    - A tangential stiffness K_T0 100 times K1 (tangential walton_braun):
      the tangential half-period t = pi sqrt(m_t/K_T0), m_t = 2/7 m*
      (rotation included), stops the run (limit dt <= t/20).
    Not a time step but a limit all the same: with A = 1e-18 J and a soft
    contact (K1 = 0.1 N/m) the van der Waals pull at contact,
        F0 = A Rs/6 (1/h0^2 - 1/hc^2)   (Rs = R/2 pairs, R wall),
    would press the contact by F0/K1 = 5 radii (the particles pass through
    each other): the run stops where F0/K1 > R/4, naming F0/(K1 R) and the
    smallest loadingStiffness 4 F0/R, between particles and against a wall.
\*---------------------------------------------------------------------------*/
#include "liggghtsProcess.H"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

using namespace demTest;

namespace
{

const double pi = std::acos(-1.0);
const double rho = 2500;        // kg/m^3
const double h0 = 0.4e-9;       // m, default inner cut-off

double mass(double R) { return 4.0/3.0*pi*R*R*R*rho; }


// two particles of radius R [m] 20 nm apart (van der Waals only, run
// units micro), K1 [nN/um] for particles (types 1-1) and walls (1-2), a
// primitive wall 1.5 um below them (its cohesion model: wallCohesion)
std::string pairScript
(
    double R,
    double A,
    double K1,
    double K1wall,
    double dt,
    const std::string& pairOptions,
    const std::string& wallCohesion = ""
)
{
    std::ostringstream s;
    s.precision(17);
    s << boxHeader()
      << "fix m1 all property/global loadingStiffness peratomtypepair 2 "
      << K1 << ' ' << K1wall << ' ' << K1wall << ' ' << K1wall << "\n"
         "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
         "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
         "fix c1 all property/global hamakerConstant peratomtypepair 2 "
      << A/1e-15 << ' ' << A/1e-15 << ' ' << A/1e-15 << ' ' << A/1e-15 << "\n"
         "fix c2 all property/global vdwOuterCutoff scalar 0.05\n"
         "pair_style gran model walton_braun tangential history cohesion colloid/vdw "
      << pairOptions << "\n"
         "pair_coeff * *\n"
         "timestep " << dt/1e-6 << "\n"
         "fix floor all wall/gran model walton_braun tangential history " << wallCohesion
      << " primitive type 2 zplane -2\n"
         "fix integrate all nve/sphere\n"
         "create_atoms 1 single 0 0 0 units box\n"
         "create_atoms 1 single " << (2*R + 20e-9)/1e-6 << " 0 0 units box\n"
         "set atom * diameter " << 2*R/1e-6 << " density " << rho/1000 << "\n"
         "run 10\n";
    return s.str();
}

double vdwSpringTime(double R, double A)
{
    const double k = A*(R/2)/(3*h0*h0*h0);
    return std::sqrt(mass(R)/2/k);
}

// the run stopped naming the limit 'what' with time scale t [s] and
// fraction f; the suggested step is f t in us
void expectStop(const ProcessResult& r, const std::string& what, double t, double f)
{
    EXPECT_GT(r.status, 0) << r.output;
    const std::string marker = "ERROR: ";
    const std::size_t at = r.output.find(marker);
    ASSERT_NE(at, std::string::npos) << r.output;
    const std::string error = r.output.substr(at);
    EXPECT_NE(error.find(what), std::string::npos) << error;
    EXPECT_NEAR(numberAfter(error, what + " ("), t, 1e-5*t) << error;
    EXPECT_NEAR(numberAfter(error, "use 'timestep "), f*t/1e-6, 1e-5*f*t/1e-6) << error;
}

} // namespace


TEST(startupLimit, startupLimitSmallParticles)
{
    const double R = 25e-9, A = 1e-20, dt = 5e-11;
    const double t = vdwSpringTime(R, A);
    std::cout << "50 nm particles: van der Waals spring " << t << " s, dt " << dt << " s" << std::endl;
    const ProcessResult r = runLiggghts("startupLimitSmallParticles", pairScript(R, A, 100, 100, dt, ""));
    expectStop(r, "van der Waals spring at its inner cut-off", t, 0.1);
}


TEST(startupLimit, startupLimitSmallParticlesOverride)
{
    const double R = 25e-9, A = 1e-20, dt = 5e-11;
    const ProcessResult r = runLiggghts("startupLimitSmallParticlesOverride",
                                        pairScript(R, A, 100, 100, dt, "timeStepCheck off"));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.find("ERROR"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("WARNING: cohesion colloid/vdw: the time step"), std::string::npos) << r.output;
}


TEST(startupLimit, startupLimitLargeHamaker)
{
    // K1 = 10 N/m keeps the contact duration (19 ns) out of the way
    const double R = 0.5e-6, A = 1e-18, dt = 1e-10;
    const double t = vdwSpringTime(R, A);
    std::cout << "A = 1e-18 J: van der Waals spring " << t << " s, dt " << dt << " s" << std::endl;
    const ProcessResult r = runLiggghts("startupLimitLargeHamaker", pairScript(R, A, 1e4, 1e4, dt, ""));
    expectStop(r, "van der Waals spring at its inner cut-off", t, 0.1);
}


TEST(startupLimit, startupLimitStiffWall)
{
    // particles 0.1 N/m, wall 10 N/m; A = 1e-21 J keeps the van der Waals
    // spring out of the way
    const double R = 0.5e-6, A = 1e-21, dt = 2e-9, e = 0.5;
    const double K1wall = 10;   // N/m
    const double t = pi/2*std::sqrt(mass(R)/K1wall)*(1 + e);
    const double tPair = pi/2*std::sqrt(mass(R)/2/0.1)*(1 + e);
    std::cout << "stiff wall: contact duration " << t << " s (pairs " << tPair
              << " s), dt " << dt << " s" << std::endl;
    ASSERT_LT(dt, 0.05*tPair);
    const ProcessResult r = runLiggghts("startupLimitStiffWall", pairScript(R, A, 100, K1wall/1e-3, dt, ""));
    expectStop(r, "Walton-Braun contact duration of the lightest particle against a wall", t, 0.05);
}


namespace
{

// the run stopped on the van der Waals pull F0 [N] against K1 [N/m]
void expectPullStop(const ProcessResult& r, const std::string& kind, double F0, double K1, double R)
{
    EXPECT_GT(r.status, 0) << r.output;
    const std::size_t at = r.output.find("ERROR: ");
    ASSERT_NE(at, std::string::npos) << r.output;
    const std::string error = r.output.substr(at);
    EXPECT_NE(error.find("van der Waals pull at contact (" + kind), std::string::npos) << error;
    EXPECT_NEAR(numberAfter(error, "by "), F0/(K1*R), 1e-5*F0/(K1*R)) << error;
    EXPECT_NEAR(numberAfter(error, "use loadingStiffness "), 4*F0/R/1e-3, 1e-5*4*F0/R/1e-3) << error;
}

} // namespace


TEST(startupLimit, startupLimitSoftContact)
{
    const double R = 0.5e-6, A = 1e-18, hc = 50e-9, dt = 1e-11;
    const double F0 = A*(R/2)/6*(1/(h0*h0) - 1/(hc*hc));
    std::cout << "A = 1e-18 J, K1 = 0.1 N/m: pull " << F0 << " N, overlap " << F0/0.1/R
              << " radii" << std::endl;
    const ProcessResult r = runLiggghts("startupLimitSoftContact", pairScript(R, A, 100, 100, dt, ""));
    expectPullStop(r, "particle-particle", F0, 0.1, R);
}


TEST(startupLimit, startupLimitSoftWall)
{
    // particles 10 N/m (pull: 0.05 radii), wall 0.1 N/m
    const double R = 0.5e-6, A = 1e-18, hc = 50e-9, dt = 1e-11;
    const double F0 = A*R/6*(1/(h0*h0) - 1/(hc*hc));
    const ProcessResult r = runLiggghts("startupLimitSoftWall", pairScript(R, A, 1e4, 100, dt, "", "cohesion colloid/vdw"));
    expectPullStop(r, "particle-wall", F0, 0.1, R);
}


TEST(startupLimit, startupLimitStiffTangential)
{
    // K1 = 0.1 N/m, K_T0 = 10 N/m; A = 1e-21 J keeps the van der Waals
    // spring out of the way
    const double R = 0.5e-6, A = 1e-21, dt = 1e-9, KT0 = 10;
    const double t = pi*std::sqrt(2.0/7.0*mass(R)/2/KT0);
    std::cout << "stiff tangential spring: half-period " << t << " s, dt " << dt << " s" << std::endl;
    std::string script = pairScript(R, A, 100, 100, dt, "");
    const std::string from = "pair_style gran model walton_braun tangential history";
    const std::size_t at = script.find(from);
    ASSERT_NE(at, std::string::npos);
    script.replace(at, from.size(),
        "fix m4 all property/global tangentialStiffness peratomtypepair 2 1e4 1e4 1e4 1e4\n"
        "pair_style gran model walton_braun tangential walton_braun");
    const ProcessResult r = runLiggghts("startupLimitStiffTangential", script);
    expectStop(r, "tangential half-period of two of the lightest particles", t, 0.05);
}


/*---------------------------------------------------------------------------*\
    The limits added for stiff terms (label stiff):
    - double layer (cohesion colloid/dl) of 0.1 um particles at zeta =
      -0.1 V in 100 mM salt (Debye length 0.96 nm): its spring at the
      inner cut-off h0, seed 002 eq 10 differentiated,
          k = 128 pi R* n kT G^2 exp(-kappa h0),  G = tanh(z e zeta/(4 kT)),
      stops dt = 0.5 ns (limit dt <= sqrt(m* /k)/10);
    - LIGGGHTS' explicit fix viscous with m/gamma = 10 ns stops dt = 2 ns
      (limit dt <= m/gamma/10);
    - Di Renzo-Di Maio wall contact (checked on the fly, its stiffness
      grows with the overlap): a sphere driven into a mesh wall stops the
      run during the impact, the message giving the overlap, the stiffness
      (2/3) 8 G* sqrt(R delta) and the half-period pi sqrt(2/7 m/k_t),
      each checked here, and the largest step, 1/20 of the half-period.
\*---------------------------------------------------------------------------*/
TEST(startupLimit, startupLimitDoubleLayerSpring)
{
    const double R = 0.1e-6, zeta = -0.1, salt = 100, dt = 5e-10;
    const double kB = 1.380649e-23, T = 298.15, e = 1.602176634e-19, NA = 6.02214076e23;
    const double eps = 78.4*8.8541878128e-12, n = salt*NA;
    const double kappa = std::sqrt(2*n*e*e/(eps*kB*T));
    const double G = std::tanh(e*zeta/(4*kB*T));
    const double k = 128*pi*(R/2)*n*kB*T*G*G*std::exp(-kappa*h0);
    const double t = std::sqrt(mass(R)/2/k);
    std::cout << "double layer: Debye length " << 1/kappa << " m, spring " << k << " N/m, "
              << t << " s, dt " << dt << " s" << std::endl;
    std::string script = pairScript(R, 1e-21, 100, 100, dt, "");
    const std::string from = "pair_style gran model walton_braun tangential history cohesion colloid/vdw";
    const std::size_t at = script.find(from);
    ASSERT_NE(at, std::string::npos);
    std::ostringstream dl;
    dl << "fix d1 all property/global zetaPotential peratomtype " << zeta << ' ' << zeta << "\n"
          "fix d2 all property/global saltConcentration scalar " << salt << "\n"
          "fix d3 all property/global doubleLayerOuterCutoff scalar 0.05\n"
          "pair_style gran model walton_braun tangential history cohesion colloid/dl";
    script.replace(at, from.size(), dl.str());
    const ProcessResult r = runLiggghts("startupLimitDoubleLayerSpring", script);
    expectStop(r, "double-layer spring at its inner cut-off", t, 0.1);
}


TEST(startupLimit, startupLimitViscousFix)
{
    const double R = 0.5e-6, A = 1e-21, dt = 2e-9, tau = 1e-8;
    const double gamma = mass(R)/tau;           // kg/s
    std::string script = pairScript(R, A, 100, 100, dt, "");
    const std::string before = "fix integrate all nve/sphere\n";
    const std::size_t at = script.find(before);
    ASSERT_NE(at, std::string::npos);
    std::ostringstream viscous;
    viscous.precision(17);
    viscous << "fix drag all viscous " << gamma/1e-9 << "\n";
    script.insert(at, viscous.str());
    const ProcessResult r = runLiggghts("startupLimitViscousFix", script);
    expectStop(r, "relaxation time m/gamma of the explicit drag of fix viscous "
                  "(the drag through per-atom Ksl and uf is implicit, see README)", tau, 0.1);
}


TEST(startupLimit, startupLimitDiRenzoDiMaioWall)
{
    const double R = 0.5e-6, E = 1e8, nu = 0.3, dt = 3e-9;
    std::ofstream stl("diRenzoWall.stl");
    stl << "solid wall\n"
           "facet normal 0 0 1\nouter loop\nvertex -3 -3 0\nvertex 3 -3 0\nvertex 3 3 0\nendloop\nendfacet\n"
           "facet normal 0 0 1\nouter loop\nvertex -3 -3 0\nvertex 3 3 0\nvertex -3 3 0\nendloop\nendfacet\n"
           "endsolid wall\n";
    stl.close();
    std::ostringstream s;
    s.precision(17);
    s << boxHeader()
      << "fix m1 all property/global loadingStiffness peratomtypepair 2 100 100 100 100\n"
         "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
         "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
         "fix m4 all property/global tangentialStiffness peratomtypepair 2 100 100 100 100\n"
         "fix m5 all property/global youngsModulus peratomtype " << E/1e3 << ' ' << E/1e3 << "\n"
         "fix m6 all property/global poissonsRatio peratomtype " << nu << ' ' << nu << "\n"
         "pair_style gran model walton_braun tangential walton_braun\n"
         "pair_coeff * *\n"
         "timestep " << dt/1e-6 << "\n"
         "fix wallMesh all mesh/surface file diRenzoWall.stl type 2\n"
         "fix wall all wall/gran model walton_braun tangential walton_braun "
         "mesh n_meshes 1 meshes wallMesh diRenzoDiMaio on\n"
         "fix integrate all nve/sphere\n"
         "create_atoms 1 single 0 0 " << (R + 5e-9)/1e-6 << " units box\n"
         "set atom 1 diameter " << 2*R/1e-6 << " density " << rho/1000 << " vx 0.5 vz -1\n"
         "run 200\n";
    const ProcessResult r = runLiggghts("startupLimitDiRenzoDiMaioWall", s.str());
    EXPECT_GT(r.status, 0) << r.output;
    const std::size_t at = r.output.find("ERROR");
    ASSERT_NE(at, std::string::npos) << r.output;
    const std::string error = r.output.substr(at);
    ASSERT_NE(error.find("(diRenzoDiMaio on) reached an overlap of"), std::string::npos) << error;
    const double overlap = numberAfter(error, "an overlap of ")*R;
    const double G = E/(2*(1 + nu));
    const double Gstar = 1/(2*(2 - nu)/G);
    const double k = 2.0/3.0*8*Gstar*std::sqrt(R*overlap);
    const double halfPeriod = pi*std::sqrt(2.0/7.0*mass(R)/k);
    std::cout << "Di Renzo-Di Maio wall: stopped at overlap " << overlap << " m, k_t " << k
              << " N/m, half-period " << halfPeriod << " s, dt " << dt << " s" << std::endl;
    // the overlap is printed to 6 digits: k to about 1e-6
    EXPECT_NEAR(numberAfter(error, "tangential stiffness is "), k, 1e-5*k) << error;
    EXPECT_NEAR(numberAfter(error, "half-period of that spring, "), halfPeriod, 1e-5*halfPeriod) << error;
    EXPECT_NEAR(numberAfter(error, "use a time step of "), 0.05*halfPeriod, 1e-5*halfPeriod) << error;
    EXPECT_GT(dt, 0.05*halfPeriod);
}
