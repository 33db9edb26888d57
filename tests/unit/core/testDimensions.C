/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Dimensioned values: [name] [dims] value [units], 5 or 7 exponents, named
// units, getDimensioned checks and its errors.

#include "dictionary.H"
#include "dimensionSet.H"
#include "error.H"
#include "../testTools.H"

#include <gtest/gtest.h>

using namespace sphvcpm;
using test::catchFatal;
using test::expectError;

namespace
{

// The dimensions written for key, read through getDimensioned: equal to
// expected when no error is thrown.
bool hasDimensions(const dictionary& d, const std::string& key,
                   const dimensionSet& expected)
{
    try
    {
        d.getDimensioned<double>(key, expected);
        return true;
    }
    catch (const FatalError&)
    {
        return false;
    }
}

} // End anonymous namespace


TEST(dimensionSet, equalityAndText)
{
    EXPECT_EQ(dimensions::density(), dimensionSet(1, -3, 0));
    EXPECT_NE(dimensions::density(), dimensions::pressure());
    EXPECT_EQ(dimensions::kinematicViscosity().str(), "[0 2 -1 0 0 0 0]");
    EXPECT_EQ(dimensionSet(0, 0.5, 0).str(), "[0 0.5 0 0 0 0 0]");
    EXPECT_EQ(dimensionSet().str(), "[0 0 0 0 0 0 0]");
}


TEST(dimensionedValues, allWrittenForms)
{
    const auto d = dictionary::fromString
    (
        "nu1 [0 2 -1 0 0 0 0] 1e-06;\n"
        "nu2 nu [0 2 -1 0 0 0 0] 1e-06;\n"
        "nu3 [0 2 -1 0 0] 1e-06;\n"
        "nu4 1e-06 [m^2/s];\n"
        "nu5 nu 1e-06 [m^2 s^-1];\n"
        "nu6 [ m^2 / s ] 1e-06;\n"
        "nu7 [kinematicViscosity] 1e-06;\n"
        "rho [kg/m^3] 1000;\n"
        "rho2 [kg m^-3] 1000;\n"
        "p [Pa] 101325;\n"
        "p2 [N/m^2] 101325;\n"
        "p3 [kg/(m*s^2)] 101325;\n"
        "p4 [kg*m^-1*s^-2] 101325;\n"
        "E [J/m^3] 1e9;\n"
        "P [W] 5;\n"
        "P2 [J/s] 5;\n"
        "f [Hz] 50;\n"
        "f2 [1/s] 50;\n"
        "T [K] 300;\n"
        "n [mol] 2;\n"
        "I [A] 1;\n"
        "L [cd] 1;\n"
        "sq [m^(2)] 4;\n"
        "none [] 3;\n"
        "ratio [0 0 0 0 0 0 0] 0.5;\n"
        "g [0 1 -2 0 0 0 0] (0 -9.81 0);\n"
        "g2 g (0 0 -9.81) [m/s^2];\n"
        "plain 2.5;\n"
    );
    const auto nuDims = dimensions::kinematicViscosity();
    for (const char* k : {"nu1", "nu2", "nu3", "nu4", "nu5", "nu6", "nu7"})
    {
        EXPECT_EQ(d.get<double>(k), 1e-06) << k;
        EXPECT_EQ(d.getDimensioned<double>(k, nuDims), 1e-06) << k;
    }
    EXPECT_EQ(d.getDimensioned<double>("rho", dimensions::density()), 1000);
    EXPECT_EQ(d.getDimensioned<double>("rho2", dimensions::density()), 1000);
    for (const char* k : {"p", "p2", "p3", "p4", "E"})
    {
        EXPECT_TRUE(hasDimensions(d, k, dimensions::pressure())) << k;
    }
    const dimensionSet power(1, 2, -3);
    EXPECT_TRUE(hasDimensions(d, "P", power));
    EXPECT_TRUE(hasDimensions(d, "P2", power));
    EXPECT_TRUE(hasDimensions(d, "f", dimensionSet(0, 0, -1)));
    EXPECT_TRUE(hasDimensions(d, "f2", dimensionSet(0, 0, -1)));
    EXPECT_TRUE(hasDimensions(d, "T", dimensionSet(0, 0, 0, 1)));
    EXPECT_TRUE(hasDimensions(d, "n", dimensionSet(0, 0, 0, 0, 1)));
    EXPECT_TRUE(hasDimensions(d, "I", dimensionSet(0, 0, 0, 0, 0, 1)));
    EXPECT_TRUE(hasDimensions(d, "L", dimensionSet(0, 0, 0, 0, 0, 0, 1)));
    EXPECT_TRUE(hasDimensions(d, "sq", dimensionSet(0, 2, 0)));
    EXPECT_TRUE(hasDimensions(d, "none", dimensions::none()));
    EXPECT_TRUE(hasDimensions(d, "ratio", dimensions::none()));
    EXPECT_FALSE(hasDimensions(d, "ratio", dimensions::length()));
    EXPECT_EQ(d.getDimensioned<vec3>("g", dimensions::acceleration()),
              (vec3{0, -9.81, 0}));
    EXPECT_EQ(d.getDimensioned<vec3>("g2", dimensions::acceleration()),
              (vec3{0, 0, -9.81}));
    // Dimensions are optional: nothing written, nothing to check.
    EXPECT_EQ(d.getDimensioned<double>("plain", dimensions::length()), 2.5);
    // get ignores the dimensions.
    EXPECT_EQ(d.get<double>("E"), 1e9);
    EXPECT_EQ(d.get<vec3>("g2"), (vec3{0, 0, -9.81}));
}


TEST(dimensionedValues, mismatchShowsExpectedAndFound)
{
    const std::string file = "case/constant/fluidProperties";
    const auto d = dictionary::fromString
    (
        "rho0 [1 -3 0 0 0 0 0] 1000;\nnu [m^2/s^2] 1e-6;\n"
        "g (0 -9.81 0) [m/s];\n", file
    );
    expectError
    (
        catchFatal([&]
        {
            d.getDimensioned<double>("nu", dimensions::kinematicViscosity());
        }),
        file, 2,
        {"Keyword 'nu'", "dimensions do not match",
         "expected [0 2 -1 0 0 0 0]", "found [0 2 -2 0 0 0 0]"}
    );
    expectError
    (
        catchFatal([&]
        {
            d.getDimensioned<vec3>("g", dimensions::acceleration());
        }),
        file, 3,
        {"expected [0 1 -2 0 0 0 0]", "found [0 1 -1 0 0 0 0]"}
    );
    EXPECT_EQ(d.getDimensioned<double>("rho0", dimensions::density()), 1000);
}


TEST(dimensionedValues, malformedDimensions)
{
    const std::string file = "case/constant/transportProperties";
    struct badCase
    {
        const char* text;
        int line;
        std::vector<std::string> parts;
    };
    const std::vector<badCase> cases =
    {
        {"x 1;\nrho [kgg/m^3] 1000;\n", 2,
         {"Keyword 'rho'", "unknown unit 'kgg'", "did you mean 'kg'?",
          "known units are (kg m s K mol A cd N Pa J W Hz", "[kgg/m^3]"}},
        {"rho [furlong] 1;\n", 1, {"unknown unit 'furlong'"}},
        {"E [MPa] 2;\n", 1, {"unknown unit 'MPa' (units take no prefix:"
         " values are in SI units, so write the value in Pa: 1 MPa is [Pa]"
         " 1e6)"}},
        {"amplitude [mm] 10;\n", 1, {"unknown unit 'mm' (units take no"
         " prefix: values are in SI units, so write the value in m: 1 mm is"
         " [m] 0.001)"}},
        {"nu [0 2 -1 0] 1;\n", 1,
         {"expected 5 or 7 dimension exponents, found 4"}},
        {"nu [0 2 -1 0 0 0 0 0] 1;\n", 1,
         {"expected 5 or 7 dimension exponents, found 8"}},
        {"nu\n    [0 2 -1 0 0 0 0 1e-06;\n", 2,
         {"expected ']' to close the dimensions '[' opened at line 2"}},
        {"nu [m^2/s] 1e-6 [m^2/s];\n", 1,
         {"dimensions are given both before and after the value"}},
        {"nu [m^] 1;\n", 1, {"expected a number after '^'"}},
        {"nu [m^2/] 1;\n", 1, {"expected a unit name, found the end"}},
        {"nu [2 m] 1;\n", 1, {"unexpected number 2 among named units"}},
        {"nu [m%s] 1;\n", 1, {"unexpected character '%'"}},
        {"nu nu 1e-6;\n", 1, {"expected a number", "found word 'nu'"}},
        {"nu [0 2 -1 0 0 0 0] 1e-6 2;\n", 1,
         {"unexpected integer 2 after the value"}},
    };
    for (const auto& c : cases)
    {
        const auto d = dictionary::fromString(c.text, file);
        SCOPED_TRACE(c.text);
        const auto key = d.keys().back();
        expectError(catchFatal([&]{ d.get<double>(key); }), file, c.line,
                    c.parts);
    }
}
