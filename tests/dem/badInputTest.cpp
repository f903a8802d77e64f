/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: bad input to the plugin. A property out of its
    allowed range, or missing, stops the run of the stock "liggghts"
    program (plugin preloaded) with a non-zero exit and a message that
    names the property, its value in SI and the allowed range.

    Reference: the valid script runs (exit 0); each test changes one
    property; the SI value in the message is the input value times the
    micro-to-SI factor computed here (stiffness nN/um = 1e-3 N/m, energy
    fJ = 1e-15 J), the ranges those of the kernels (src/colloidModels).
\*---------------------------------------------------------------------------*/
#include "liggghtsProcess.H"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

using namespace demTest;

namespace
{

// one "fix ... property/global" line per property, by name
typedef std::map<std::string, std::string> Properties;

Properties validProperties()
{
    return {
        {"loadingStiffness", "peratomtypepair 2 100 100 100 100"},
        {"coefficientRestitution", "peratomtypepair 2 0.5 0.5 0.5 0.5"},
        {"coefficientFriction", "peratomtypepair 2 0.3 0.3 0.3 0.3"},
        {"hamakerConstant", "peratomtypepair 2 1e-5 1e-5 1e-5 1e-5"},
        {"vdwOuterCutoff", "scalar 0.05"},
        {"zetaPotential", "peratomtype -0.03 -0.03"},
        {"saltConcentration", "scalar 1.0"},
        {"doubleLayerOuterCutoff", "scalar 0.05"},
        {"liquidViscosity", "scalar 1.0"}};
}

// two particles 30 nm apart, all colloid terms on, 10 steps
std::string script(const Properties& properties)
{
    std::string s = boxHeader();
    int n = 0;
    for (const auto& p : properties)
    {
        s += "fix p" + std::to_string(++n) + " all property/global " + p.first + ' ' + p.second + '\n';
    }
    s +=
        "pair_style gran model walton_braun tangential history cohesion colloid/vdw/dl/lub\n"
        "pair_coeff * *\n"
        "timestep 1e-4\n"
        "fix integrate all nve/sphere\n"
        "create_atoms 1 single 0 0 0 units box\n"
        "create_atoms 1 single 1.03 0 0 units box\n"
        "set atom * diameter 1 density 2.5\n"
        "run 10\n";
    return s;
}

// run with one property replaced (or removed: empty value)
ProcessResult runWith(const std::string& test, const std::string& name, const std::string& value)
{
    Properties p = validProperties();
    if (value.empty()) p.erase(name);
    else p[name] = value;
    return runLiggghts(test, script(p));
}

// the run stopped with a message naming the property, the value in SI
// (after "= ") and the range
void expectRangeError
(
    const ProcessResult& r,
    const std::string& property,
    double valueSI,
    const std::string& range
)
{
    EXPECT_GT(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("ERROR"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("property/global '" + property + "'"), std::string::npos) << r.output;
    const double v = numberAfter(r.output, "' = ");
    EXPECT_NEAR(v, valueSI, 1e-5*std::fabs(valueSI)) << r.output;
    EXPECT_NE(r.output.find("allowed " + range), std::string::npos) << r.output;
}

} // namespace


TEST(badInput, badInputValidScriptRuns)
{
    const ProcessResult r = runLiggghts("badInputValidScriptRuns", script(validProperties()));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.find("ERROR"), std::string::npos) << r.output;
}


TEST(badInput, badInputNegativeStiffness)
{
    // -100 nN/um = -0.1 N/m
    const ProcessResult r = runWith("badInputNegativeStiffness", "loadingStiffness",
                                    "peratomtypepair 2 -100 100 100 100");
    expectRangeError(r, "loadingStiffness", -100*1e-3, "(0, inf) N/m");
}


TEST(badInput, badInputRestitutionAboveOne)
{
    const ProcessResult r = runWith("badInputRestitutionAboveOne", "coefficientRestitution",
                                    "peratomtypepair 2 1.2 1.2 1.2 1.2");
    expectRangeError(r, "coefficientRestitution", 1.2, "(0, 1]");
}


TEST(badInput, badInputZetaAbove300mV)
{
    const ProcessResult r = runWith("badInputZetaAbove300mV", "zetaPotential", "peratomtype -0.35 -0.03");
    expectRangeError(r, "zetaPotential", -0.35, "[-0.3, 0.3] V");
}


TEST(badInput, badInputHamakerTooLarge)
{
    // 1e-1 fJ = 1e-16 J, ten times the largest allowed
    const ProcessResult r = runWith("badInputHamakerTooLarge", "hamakerConstant",
                                    "peratomtypepair 2 1e-1 1e-1 1e-1 1e-1");
    expectRangeError(r, "hamakerConstant", 1e-1*1e-15, "[-1e-17, 1e-17] J");
}


TEST(badInput, badInputNoSalt)
{
    // no salt at all: the Debye length is infinite; the smallest allowed
    // concentration is above 0 (pure water: ~1e-4 mol/m^3, 1 um)
    const ProcessResult r = runWith("badInputNoSalt", "saltConcentration", "scalar 0");
    expectRangeError(r, "saltConcentration", 0.0, "(0, 10000] mol/m^3");
}


TEST(badInput, badInputMissingRestitution)
{
    const ProcessResult r = runWith("badInputMissingRestitution", "coefficientRestitution", "");
    EXPECT_GT(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("ERROR"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("coefficientRestitution"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("walton_braun"), std::string::npos) << r.output;
}


TEST(badInput, badInputMisspeltOptionalProperty)
{
    // lubricationInnerCutoff is optional: misspelt, it would be ignored
    // and the default used
    Properties p = validProperties();
    p["lubricationInnerCutof"] = "scalar 0.002";
    const ProcessResult r = runLiggghts("badInputMisspeltOptionalProperty", script(p));
    EXPECT_GT(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("property/global 'lubricationInnerCutof'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("did you mean 'lubricationInnerCutoff'?"), std::string::npos) << r.output;
}
