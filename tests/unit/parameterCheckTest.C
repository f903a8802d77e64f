/*---------------------------------------------------------------------------*\
    Unit tests of parameterCheck.H and pairGeometry.H: the error message of a
    parameter out of range names the parameter, its value and the allowed
    range (the plugin/solver prefixes the file and keyword); a wall is the
    limit of a large sphere.
\*---------------------------------------------------------------------------*/
#include "pairGeometry.H"
#include "parameterCheck.H"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace colloid;

TEST(ParameterCheck, MessageNamesParameterValueAndRange)
{
    try
    {
        check::range("innerCutoff", -2e-9, 0.0, false, 1e-6, true, "m");
        FAIL() << "out-of-range value accepted";
    }
    catch (const std::invalid_argument& e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("'innerCutoff'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("-2e-09 m"), std::string::npos) << msg;
        EXPECT_NE(msg.find("(0, 1e-06] m"), std::string::npos) << msg;
    }
    EXPECT_NO_THROW(check::range("x", 1e-6, 0.0, false, 1e-6, true, "m"));
    EXPECT_THROW(check::range("x", 0.0, 0.0, false, 1e-6, true, "m"), std::invalid_argument);
    EXPECT_THROW(check::positive("x", NAN, "m"), std::invalid_argument);
    EXPECT_THROW(check::positive("x", HUGE_VAL, "m"), std::invalid_argument);
}

TEST(PairGeometry, WallIsTheLimitOfALargeSphere)
{
    EXPECT_EQ(effectiveRadius(2e-6, wallRadius), 2e-6);
    EXPECT_EQ(effectiveRadius(wallRadius, 2e-6), 2e-6);
    EXPECT_NEAR(effectiveRadius(2e-6, 1e3), 2e-6, 1e-8*2e-6);
    EXPECT_NEAR(effectiveRadius(1e-6, 3e-6), 0.75e-6, 1e-15*0.75e-6);
    EXPECT_EQ(reducedMass(1e-15, wallRadius), 1e-15);
    EXPECT_NEAR(reducedMass(1e-15, 1e-15), 0.5e-15, 1e-15*0.5e-15);
}
