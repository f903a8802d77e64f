/*---------------------------------------------------------------------------*\
    colloidBarrier: the DLVO interaction energy of two particles (or a
    particle and a charged wall) as the DEM sees it, its barrier against
    agglomeration in k_B T, and the salt concentration at which the
    barrier falls to a given height (the critical coagulation
    concentration, CCC, for a height of 0), or the zeta potential at
    which it does at the given salt (in a real dispersion salt and pH move
    the zeta potential too: the two answers bracket what a chemistry
    change does).

    Why: whether a dispersion agglomerates is decided by the double-layer
    barrier a pair must cross to reach the van der Waals minimum; a
    barrier of 15-25 k_B T or more keeps it stable for the seconds of a
    process, one of a few k_B T lets Brownian motion and shear push pairs
    over it.  The tool answers "what chemistry keeps my dispersion
    stable" before a run, with the project's own force kernels and the
    run's cut-offs (src/colloidModels: vanDerWaals.H, doubleLayer.H).

    With -stabilityRatio it also gives how fast Brownian motion alone
    brings pairs into contact: Fuchs' stability ratio with the DEM's own
    hydrodynamics (the free Stokes drag of each particle and the pair's
    lubrication, with the run's cut-offs), W = S I with
        I = integral from h_t to infinity of beta(h) exp(U(h)/k_B T)/(S + h)^2 dh,
        beta(h) = 1 + c(h)/zeta_red  (relative diffusion D_inf/D(h): the
                  lubrication resistance c in parallel with the pair's
                  reduced Stokes drag zeta_red = 6 pi mu R1 R2/(R1 + R2)),
    S = R1 + R2 and h_t the touching gap of the contact analysis; the
    collision rate constant k = 4 pi D_inf/I, D_inf = k_B T (1/zeta_1 +
    1/zeta_2) (Smoluchowski's 8 k_B T/(3 mu) for equal spheres without
    forces and hydrodynamics).  W near 1: every Brownian encounter ends in
    contact; W = e^20: one in 5e8.

    The energy is the work against the DEM's force, U(h) = integral from h
    to the largest outer cut-off of F(h') dh' (the forces are force-shifted
    to zero at their outer cut-offs, or with -cutoffForm faded all three
    faded as the plugin's vdwFade, doubleLayerFade and lubricationFade do,
    and held constant below their inner ones), by the trapezoidal rule on 40 000 geometrically spaced gaps (its
    error is far below 1e-4 k_B T here).

    Usage (SI units; defaults in brackets):
      colloidBarrier -radius R [-radius2 R2 | -wall] -hamaker A
          -zeta z1 [-zeta2 z2 (= z1)] -salt c [mol/m^3 = mM]
          [-valence 1] [-temperature 298.15] [-permittivity 78.4]
          [-vdwOuterCutoff 1e-7] [-doubleLayerOuterCutoff inf]
          [-innerCutoff 4e-10] [-form linearSuperposition|hoggHealyFuerstenau]
          [-cutoffForm shifted|faded]
          [-ccc height_kT] [-zetaAt height_kT] [-csv file]
          [-stabilityRatio [-viscosity 1e-3] [-lubricationInnerCutoff 1e-9]
           [-lubricationOuterCutoff 1e-7] [-touchingGap 0.01 R_min]
           [-solidsFraction phi]]
    Prints key = value lines: debyeLength, barrier (k_B T) and barrierGap,
    the energy at contact (the inner cut-off), the secondary minimum, the
    largest repulsive force beyond the inner cut-off and its gap (what a
    flow must push a pair with to force it over the barrier without
    Brownian motion: compare with the order 6 pi mu G R1 R2 of a shear
    rate G; 0 when the pair only attracts);
    with -ccc the salt concentration at which the barrier is height_kT
    (bisection in log c over 1e-4 ... 1e4 mol/m^3); with -zetaAt the
    zeta potential (of both surfaces, with the sign given) at which it
    is height_kT at the given salt (bisection over 0 ... 0.3 V); with
    -csv the curve (gap, force, energy); with -stabilityRatio (pairs only)
    stabilityRatio, hydrodynamicRetardation (W without the colloid
    forces), perikineticRate k [m^3/s] and, with -solidsFraction (the
    particles' volume fraction, particles of radius R), the Brownian
    contacts per particle and second, k n.  Bad input: a message naming the option, its
    value and the allowed range, and exit 1.
\*---------------------------------------------------------------------------*/
#include "constants.H"
#include "doubleLayer.H"
#include "lubrication.H"
#include "pairGeometry.H"
#include "vanDerWaals.H"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{

struct Options
{
    double R1 = -1, R2 = -1, hamaker = 0, zeta1 = 0, zeta2 = std::nan(""), salt = -1;
    int valence = 1;
    double temperature = 298.15, permittivity = 78.4;
    double vdwOuter = 1e-7, dlOuter = std::numeric_limits<double>::infinity();
    double inner = 0.4e-9;
    colloid::DoubleLayerForm form = colloid::DoubleLayerForm::linearSuperposition;
    bool wall = false;
    double cccHeight = std::nan("");
    double zetaHeight = std::nan("");
    std::string csv;
    bool stability = false;
    double viscosity = 1e-3, lubInner = 1e-9, lubOuter = 1e-7;
    bool fade = false;      // -cutoffForm faded (all three terms)
    double touchingGap = std::nan(""), solidsFraction = std::nan("");
};

[[noreturn]] void usage(const std::string& why)
{
    std::cerr << "colloidBarrier: " << why << "\n"
        "usage: colloidBarrier -radius R [-radius2 R2 | -wall] -hamaker A -zeta z1 [-zeta2 z2]\n"
        "           -salt c [-valence z] [-temperature T] [-permittivity eps_r]\n"
        "           [-vdwOuterCutoff h] [-doubleLayerOuterCutoff h] [-innerCutoff h]\n"
        "           [-form linearSuperposition|hoggHealyFuerstenau] [-cutoffForm shifted|faded]\n"
        "           [-ccc height_kT] [-zetaAt height_kT]\n"
        "           [-csv file] [-stabilityRatio [-viscosity mu] [-lubricationInnerCutoff h]\n"
        "           [-lubricationOuterCutoff h] [-touchingGap h] [-solidsFraction phi]]\n"
        "       (SI units: m, J, V, mol/m^3 = mM, K)\n";
    std::exit(1);
}

double number(const std::string& option, const char* text)
{
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (end == text || *end != '\0' || std::isnan(v))
    {
        usage("option " + option + ": '" + text + "' is not a number");
    }
    return v;
}

Options parse(int argc, char** argv)
{
    Options o;
    for (int k = 1; k < argc; k++)
    {
        const std::string a = argv[k];
        if (a == "-wall") { o.wall = true; continue; }
        if (a == "-stabilityRatio") { o.stability = true; continue; }
        if (k + 1 >= argc) usage("option " + a + " needs a value");
        const char* v = argv[++k];
        if (a == "-radius") o.R1 = number(a, v);
        else if (a == "-radius2") o.R2 = number(a, v);
        else if (a == "-hamaker") o.hamaker = number(a, v);
        else if (a == "-zeta") o.zeta1 = number(a, v);
        else if (a == "-zeta2") o.zeta2 = number(a, v);
        else if (a == "-salt") o.salt = number(a, v);
        else if (a == "-valence")
        {
            const double z = number(a, v);
            if (z != std::floor(z)) usage("option -valence: '" + std::string(v) + "' is not an integer (1..4)");
            o.valence = static_cast<int>(z);
        }
        else if (a == "-temperature") o.temperature = number(a, v);
        else if (a == "-permittivity") o.permittivity = number(a, v);
        else if (a == "-vdwOuterCutoff") o.vdwOuter = number(a, v);
        else if (a == "-doubleLayerOuterCutoff") o.dlOuter = number(a, v);
        else if (a == "-innerCutoff") o.inner = number(a, v);
        else if (a == "-ccc") o.cccHeight = number(a, v);
        else if (a == "-zetaAt") o.zetaHeight = number(a, v);
        else if (a == "-csv") o.csv = v;
        else if (a == "-viscosity") o.viscosity = number(a, v);
        else if (a == "-lubricationInnerCutoff") o.lubInner = number(a, v);
        else if (a == "-lubricationOuterCutoff") o.lubOuter = number(a, v);
        else if (a == "-touchingGap") o.touchingGap = number(a, v);
        else if (a == "-solidsFraction") o.solidsFraction = number(a, v);
        else if (a == "-cutoffForm")
        {
            const std::string f = v;
            if (f != "shifted" && f != "faded")
            {
                usage("option -cutoffForm: '" + f + "' is not shifted or faded");
            }
            o.fade = f == "faded";
        }
        else if (a == "-form")
        {
            const std::string f = v;
            if (f == "linearSuperposition") o.form = colloid::DoubleLayerForm::linearSuperposition;
            else if (f == "hoggHealyFuerstenau") o.form = colloid::DoubleLayerForm::hoggHealyFuerstenau;
            else usage("option -form: '" + f + "'; allowed: linearSuperposition, hoggHealyFuerstenau");
        }
        else usage("unknown option '" + a + "'");
    }
    if (!(o.R1 > 0)) usage("option -radius: must be given, > 0 [m]");
    if (o.wall && o.R2 > 0) usage("give -radius2 or -wall, not both");
    if (o.wall) o.R2 = colloid::wallRadius;
    else if (o.R2 < 0) o.R2 = o.R1;
    else if (!(o.R2 > 0)) usage("option -radius2: must be > 0 [m]");
    if (!(o.salt > 0)) usage("option -salt: must be given, > 0 [mol/m^3]");
    if (std::isnan(o.zeta2)) o.zeta2 = o.zeta1;
    if (!std::isnan(o.zetaHeight) && (o.zeta2 != o.zeta1 || o.zeta1 == 0))
        usage("option -zetaAt: needs one non-zero -zeta for both surfaces (its sign is kept)");
    if (o.stability)
    {
        if (o.wall) usage("option -stabilityRatio: pairs of particles only, not -wall");
        if (std::isnan(o.touchingGap)) o.touchingGap = 0.01*std::min(o.R1, o.R2);
        if (!(o.touchingGap >= 0.5*o.inner) || !(o.touchingGap < 1e-6))
            usage("option -touchingGap: " + std::to_string(o.touchingGap)
                  + " m; allowed: half the inner cut-off (" + std::to_string(0.5*o.inner)
                  + " m) <= h < 1e-6 m");
        if (!std::isnan(o.solidsFraction) && !(o.solidsFraction > 0 && o.solidsFraction < 0.74))
            usage("option -solidsFraction: " + std::to_string(o.solidsFraction)
                  + "; allowed: 0 < phi < 0.74");
    }
    else if (!std::isnan(o.touchingGap) || !std::isnan(o.solidsFraction))
    {
        usage("options -touchingGap and -solidsFraction need -stabilityRatio");
    }
    return o;
}

// The pair's force [N] at gap h [m] at salt concentration c: the kernels
// with the run's cut-offs
struct Pair
{
    colloid::VanDerWaals vdw;
    colloid::DoubleLayer dl;
    double R1, R2;

    static colloid::VanDerWaalsParameters vdwParameters(const Options& o)
    {
        colloid::VanDerWaalsParameters p;
        p.hamakerConstant = o.hamaker;
        p.innerCutoff = o.inner;
        p.outerCutoff = o.vdwOuter;
        p.fade = o.fade;
        return p;
    }
    static colloid::DoubleLayerParameters dlParameters(const Options& o, double c)
    {
        colloid::DoubleLayerParameters p;
        p.electrolyte.concentration = c;
        p.electrolyte.valence = o.valence;
        p.electrolyte.temperature = o.temperature;
        p.electrolyte.relativePermittivity = o.permittivity;
        p.zeta1 = o.zeta1;
        p.zeta2 = o.zeta2;
        p.form = o.form;
        p.innerCutoff = o.inner;
        p.outerCutoff = o.dlOuter;
        p.fade = o.fade;
        return p;
    }
    Pair(const Options& o, double c)
    :
        vdw(vdwParameters(o)), dl(dlParameters(o, c)), R1(o.R1), R2(o.R2)
    {}

    double force(double h) const { return vdw.force(R1, R2, h) + dl.force(R1, R2, h); }
};

struct Curve
{
    std::vector<double> h, F, U;    // gap [m], force [N], energy [J]
};

// U(h) = integral of F from h to the end of the range, on gaps from half
// the inner cut-off to the end (geometric), where F vanishes (or to 30
// Debye lengths and 1 um when an outer cut-off is infinite)
Curve energy(const Pair& p, const Options& o)
{
    double end = std::max(o.vdwOuter, o.dlOuter);
    if (!std::isfinite(end)) end = std::max({30*p.dl.debyeLength(), 1e-6, std::isfinite(o.vdwOuter) ? o.vdwOuter : 0.0});
    const int n = 40000;
    const double start = 0.5*o.inner;
    Curve c;
    c.h.resize(n);
    c.F.resize(n);
    c.U.assign(n, 0.0);
    for (int k = 0; k < n; k++)
    {
        c.h[k] = start*std::pow(end/start, double(k)/(n - 1));
        c.F[k] = p.force(c.h[k]);
    }
    for (int k = n - 2; k >= 0; k--)
    {
        c.U[k] = c.U[k + 1] + 0.5*(c.F[k] + c.F[k + 1])*(c.h[k + 1] - c.h[k]);
    }
    return c;
}

struct Barrier
{
    double height = 0, gap = 0;             // the largest U beyond the inner cut-off
    double contact = 0;                     // U at the inner cut-off
    double secondary = 0, secondaryGap = 0; // the lowest U beyond the barrier
    // the largest repulsive F beyond the inner cut-off [N] (0, at gap 0,
    // when the pair only attracts): the push a flow must exceed to press
    // a pair over the barrier without Brownian motion
    double repulsion = 0, repulsionGap = 0;
};

Barrier barrier(const Curve& c, const Options& o)
{
    Barrier b;
    b.height = -std::numeric_limits<double>::infinity();
    std::size_t top = 0;
    bool first = true;
    for (std::size_t k = 0; k < c.h.size(); k++)
    {
        if (c.h[k] < o.inner) continue;
        if (first) { b.contact = c.U[k]; first = false; }
        if (c.U[k] > b.height) { b.height = c.U[k]; b.gap = c.h[k]; top = k; }
        if (c.F[k] > b.repulsion) { b.repulsion = c.F[k]; b.repulsionGap = c.h[k]; }
    }
    for (std::size_t k = top; k < c.h.size(); k++)
    {
        if (c.U[k] < b.secondary) { b.secondary = c.U[k]; b.secondaryGap = c.h[k]; }
    }
    return b;
}

// I = integral from h_t to infinity of beta(h) exp(U(h)/kT)/(S + h)^2 dh
// [1/m] (header); U from the curve (linear between its gaps, 0 beyond
// it), or 0 everywhere without colloid forces.  Trapezoidal rule on 40 000
// geometric gaps up to where U and the lubrication have ended, then the
// tail 1/(S + H) in closed form.
double encounterIntegral(const Curve& c, const Options& o, double kT, bool withForces)
{
    colloid::LubricationParameters lp;
    lp.viscosity = o.viscosity;
    lp.innerCutoff = o.lubInner;
    lp.outerCutoff = o.lubOuter;
    lp.fade = o.fade;
    const colloid::Lubrication lub(lp);
    const double S = o.R1 + o.R2;
    const double zetaRed = 6*colloid::constants::pi*o.viscosity*o.R1*o.R2/S;
    auto U = [&](double h)
    {
        if (!withForces || h >= c.h.back()) return 0.0;
        const std::size_t k = std::upper_bound(c.h.begin(), c.h.end(), h) - c.h.begin();
        if (k == 0) return c.U.front();
        const double t = (h - c.h[k - 1])/(c.h[k] - c.h[k - 1]);
        return (1 - t)*c.U[k - 1] + t*c.U[k];
    };
    auto integrand = [&](double h)
    {
        const double beta = 1 + lub.resistance(o.R1, o.R2, h)/zetaRed;
        return beta*std::exp(U(h)/kT)/((S + h)*(S + h));
    };
    const double H = std::max(c.h.back(), o.lubOuter);
    const int n = 40000;
    double I = 0, hPrev = o.touchingGap, gPrev = integrand(hPrev);
    for (int k = 1; k < n; k++)
    {
        const double h = o.touchingGap*std::pow(H/o.touchingGap, double(k)/(n - 1));
        const double g = integrand(h);
        I += 0.5*(g + gPrev)*(h - hPrev);
        hPrev = h;
        gPrev = g;
    }
    return I + 1/(S + H);
}

} // namespace


int main(int argc, char** argv)
{
    const Options o = parse(argc, argv);
    const double kT = colloid::constants::boltzmann*o.temperature;
    try
    {
        const Pair p(o, o.salt);
        const Curve c = energy(p, o);
        const Barrier b = barrier(c, o);
        std::printf("debyeLength = %.6g m\n", p.dl.debyeLength());
        std::printf("barrier = %.6g kT\nbarrierGap = %.6g m\n", b.height/kT, b.gap);
        std::printf("contactEnergy = %.6g kT\n", b.contact/kT);
        std::printf("secondaryMinimum = %.6g kT\nsecondaryMinimumGap = %.6g m\n",
                    b.secondary/kT, b.secondaryGap);
        std::printf("largestRepulsion = %.6g N\nlargestRepulsionGap = %.6g m\n",
                    b.repulsion, b.repulsionGap);
        if (o.stability)
        {
            const double S = o.R1 + o.R2;
            const double I = encounterIntegral(c, o, kT, true);
            const double I0 = encounterIntegral(c, o, kT, false);
            const double Dinf = kT*(o.R1 + o.R2)/(6*colloid::constants::pi*o.viscosity*o.R1*o.R2);
            const double k = 4*colloid::constants::pi*Dinf/I;
            std::printf("stabilityRatio = %.6g\nhydrodynamicRetardation = %.6g\n"
                        "perikineticRate = %.6g m^3/s\ntouchingGap = %.6g m\n",
                        S*I, S*I0, k, o.touchingGap);
            if (!std::isnan(o.solidsFraction))
            {
                const double n = o.solidsFraction/(4.0/3.0*colloid::constants::pi*std::pow(o.R1, 3));
                std::printf("brownianContactsPerParticle = %.6g 1/s\n", k*n);
            }
        }
        if (!o.csv.empty())
        {
            std::ofstream out(o.csv);
            out.precision(10);
            out << "gap,force,energy_kT\n";
            for (std::size_t k = 0; k < c.h.size(); k += 20)
                out << c.h[k] << ',' << c.F[k] << ',' << c.U[k]/kT << '\n';
            if (!out) { std::cerr << "colloidBarrier: cannot write " << o.csv << "\n"; return 1; }
        }
        if (!std::isnan(o.cccHeight))
        {
            // the barrier falls as salt screens the double layer
            auto height = [&](double salt)
            {
                const Pair q(o, salt);
                return barrier(energy(q, o), o).height/kT;
            };
            double lo = 1e-4, hi = 1e4;
            if (height(lo) < o.cccHeight || height(hi) > o.cccHeight)
            {
                std::cerr << "colloidBarrier: option -ccc: a barrier of " << o.cccHeight
                          << " kT is not reached between 1e-4 and 1e4 mol/m^3 of salt\n";
                return 1;
            }
            for (int it = 0; it < 60; it++)
            {
                const double mid = std::sqrt(lo*hi);
                (height(mid) > o.cccHeight ? lo : hi) = mid;
            }
            const double ccc = std::sqrt(lo*hi);
            std::printf("saltAtBarrier = %.6g mol/m^3\nbarrierHeight = %.6g kT\n"
                        "debyeLengthAtBarrier = %.6g m\n",
                        ccc, o.cccHeight, Pair(o, ccc).dl.debyeLength());
        }
        if (!std::isnan(o.zetaHeight))
        {
            // the barrier grows with |zeta|
            const double sign = o.zeta1 > 0 ? 1 : -1;
            auto height = [&](double magnitude)
            {
                Options q = o;
                q.zeta1 = q.zeta2 = sign*magnitude;
                return barrier(energy(Pair(q, o.salt), q), q).height/kT;
            };
            double lo = 0, hi = 0.3;
            if (height(hi) < o.zetaHeight)
            {
                std::cerr << "colloidBarrier: option -zetaAt: a barrier of " << o.zetaHeight
                          << " kT is not reached with |zeta| up to 0.3 V\n";
                return 1;
            }
            for (int it = 0; it < 60; it++)
            {
                const double mid = 0.5*(lo + hi);
                (height(mid) > o.zetaHeight ? hi : lo) = mid;
            }
            std::printf("zetaAtBarrier = %.6g V\nbarrierHeight = %.6g kT\n",
                        sign*0.5*(lo + hi), o.zetaHeight);
        }
    }
    catch (const std::invalid_argument& e)
    {
        std::cerr << "colloidBarrier: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
