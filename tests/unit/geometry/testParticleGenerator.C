/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// particleGenerator on scratch cases: bodies, counts and fields, densities
// from the property files, no overlap of fluid with walls or solids, 0/ as
// written and read back, and every bad input stopping with a message that
// names file, line and keyword.

#include "lattice.H"
#include "../testPrecision.H"
#include "latticeMembers.H"
#include "particleGenerator.H"
#include "pointLocator.H"
#include "testGeometryTools.H"
#include "vcpmBeam.H"
#include "timeDirectory.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

using namespace sphvcpm;
using test::catchFatal;
using test::expectError;
using test::expectMessage;
using test::lineOf;
using test::scratchDir;
using test::writeText;

namespace fs = std::filesystem;

namespace
{

// The example of the generator's documentation, 2D.
const std::string exampleDict =
R"(nDimensions     2;          // 2: particles in the x-y plane (z = 0)
dp              0.01;       // particle spacing [m]
latticeOrigin   (0 0 0);
bodies
{
    tank
    {
        type        wall;
        container { min (0 0 0); max (1 0.8 0); layers 3; openTop no; }
    }
    water
    {
        type        fluid;
        U           (0.5 0 0);
        shapes
        {
            column { shape box; min (0 0 0); max (0.4 0.3 0); }
            hole   { shape sphere; centre (0.2 0.1 0); radius 0.05; operation subtract; }
        }
    }
    gate
    {
        type        solid;
        latticeOrigin (0.5 0 0);
        shapes { plate { shape box; min (0.5 0 0); max (0.52 0.2 0); } }
    }
}
)";

const std::string fluidProperties =
    "rho0            [1 -3 0 0 0 0 0] 1000;\nnu 1e-6;\n";

const std::string solidProperties =
    "gate\n{\n    model vcpm;\n    rho [1 -3 0 0 0 0 0] 2700;\n"
    "    E 1e9;\n    nu 0.3;\n}\n";

// A scratch case with the generator's dictionary and property files.
struct testCase
{
    scratchDir dir{"generator"};

    explicit testCase
    (
        const std::string& dict,
        const std::string& fluid = fluidProperties,
        const std::string& solid = solidProperties
    )
    {
        writeText(dictFile(), dict);
        if (!fluid.empty())
        {
            writeText(dir.path()/"constant"/"fluidProperties", fluid);
        }
        if (!solid.empty())
        {
            writeText(dir.path()/"constant"/"solidProperties", solid);
        }
    }

    fs::path dictFile() const
    {
        return dir.path()/"system"/"generateParticlesDict";
    }
    const fs::path& path() const { return dir.path(); }
};

std::string replaced(std::string text, const std::string& from,
                     const std::string& to)
{
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "no \"" << from << "\" to replace";
    if (at != std::string::npos)
    {
        text.replace(at, from.size(), to);
    }
    return text;
}

const particleBody& bodyNamed(const particleGenerator& gen,
                              const std::string& name)
{
    for (const particleBody& b : gen.bodies())
    {
        if (b.name() == name)
        {
            return b;
        }
    }
    ADD_FAILURE() << "no body " << name;
    return gen.bodies().front();
}

// Smallest distance from any particle of a to any particle of b.
scalar minDistance(const particleBody& a, const particleBody& b)
{
    scalar best = std::numeric_limits<scalar>::max();
    for (const point& p : a.position())
    {
        for (const point& q : b.position())
        {
            best = std::min(best, scalar(magSqr(p - q)));
        }
    }
    return std::sqrt(best);
}

// Fields as written: position, U, rho, mass = rho dp^d, ids 0..N-1.
void expectFields(const particleBody& b, const vec3& U, scalar rho)
{
    EXPECT_EQ(b.fieldNames(),
              (std::vector<std::string>{"U", "id", "mass", "position",
                                        "rho"}));
    const scalar mass = rho*std::pow(b.dp(), b.nDimensions());
    for (label i = 0; i < b.size(); ++i)
    {
        ASSERT_EQ(b.id()[i], i);
        ASSERT_EQ(b.vectorField("U")[i], U);
        ASSERT_EQ(b.scalarField("rho")[i], rho);
        ASSERT_DOUBLE_EQ(b.scalarField("mass")[i], mass);
        if (b.nDimensions() == 2)
        {
            ASSERT_EQ(b.position()[i].z, 0);
        }
    }
}

} // End anonymous namespace


TEST(particleGenerator, exampleCase)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    testCase c(exampleDict);
    particleGenerator gen(c.path());
    EXPECT_EQ(gen.nDimensions(), 2);
    EXPECT_EQ(gen.dp(), 0.01);
    gen.generate();

    // Solids first, then walls, then fluids.
    ASSERT_EQ(gen.bodies().size(), 3u);
    EXPECT_EQ(gen.bodies()[0].name(), "gate");
    EXPECT_EQ(gen.bodies()[1].name(), "tank");
    EXPECT_EQ(gen.bodies()[2].name(), "water");

    const std::size_t nHole = test::countNodes(
        "h { shape sphere; centre (0.2 0.1 0); radius 0.05; }", 2, 0.01);
    const particleBody& gate = bodyNamed(gen, "gate");
    const particleBody& tank = bodyNamed(gen, "tank");
    const particleBody& water = bodyNamed(gen, "water");
    EXPECT_EQ(gate.size(), 2*20);
    EXPECT_EQ(tank.size(), 106*86 - 100*80);
    EXPECT_EQ(std::size_t(water.size()), 1200 - nHole);
    EXPECT_EQ(gate.type(), bodyType::solid);
    EXPECT_EQ(tank.type(), bodyType::wall);
    // The water's nodes half a spacing from the tank's faces: its first
    // layer at the contact gap.
    EXPECT_LT(gen.summaries()[2].gapExcess, 1e-6);
    EXPECT_EQ(water.type(), bodyType::fluid);

    expectFields(gate, {0, 0, 0}, 2700);
    expectFields(tank, {0, 0, 0}, 1000);
    expectFields(water, {0.5, 0, 0}, 1000);

    // The log lines.
    std::ostringstream os;
    gen.printSummary(os);
    const std::string log = os.str();
    EXPECT_NE(log.find("    gate (solid): 40 particles, volume 0.004 m^2"
                       " (shapes 0.004 m^2, error +0.00 %)\n"),
              std::string::npos) << log;
    EXPECT_NE(log.find("    tank (wall): 1116 particles"), std::string::npos)
        << log;
    EXPECT_NE(log.find("    water (fluid): "
                       + std::to_string(1200 - nHole) + " particles"),
              std::string::npos) << log;
    EXPECT_NE(log.find("Total: " + std::to_string(40 + 1116 + 1200 - nHole)
                       + " particles in 3 bodies"), std::string::npos) << log;
    // A fluid's U is its initial velocity: no note (walls only).
    EXPECT_EQ(log.find("surface velocity"), std::string::npos) << log;

    // 0/ as written reads back (bodies come back by name).
    gen.write();
    const std::vector<particleBody> back = readTimeDirectory(c.path(), "0");
    ASSERT_EQ(back.size(), 3u);
    for (const particleBody& b : back)
    {
        const particleBody& orig = bodyNamed(gen, b.name());
        ASSERT_EQ(b.size(), orig.size());
        EXPECT_EQ(b.fieldNames(), orig.fieldNames());
        EXPECT_EQ(b.type(), orig.type());
        EXPECT_EQ(b.dp(), orig.dp());
        for (label i = 0; i < b.size(); ++i)
        {
            ASSERT_NEAR(mag(b.position()[i] - orig.position()[i]), 0, 1e-12);
        }
    }
    // Generating again replaces 0/.
    gen.write();
    EXPECT_EQ(readTimeDirectory(c.path(), "0").size(), 3u);
}


TEST(particleGenerator, fluidTouchingContainer)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    // The fluid box reaches into the wall layers: the nodes there go, the
    // ones a spacing away from the wall stay, so the count is exact.
    const std::string dict = replaced(replaced(exampleDict,
        "min (0 0 0); max (0.4 0.3 0); }",
        "min (-0.03 -0.03 0); max (0.4 0.3 0); }"),
        "            hole   { shape sphere; centre (0.2 0.1 0); radius 0.05;"
        " operation subtract; }\n", "");
    testCase c(dict);
    particleGenerator gen(c.path());
    gen.generate();
    const particleBody& water = bodyNamed(gen, "water");
    const particleBody& tank = bodyNamed(gen, "tank");
    EXPECT_EQ(water.size(), 1200);
    EXPECT_EQ(gen.summaries().back().nDropped, 43*33 - 1200);
    EXPECT_GE(minDistance(water, tank), 0.01*(1 - 1e-6));
    EXPECT_NEAR(minDistance(water, tank), 0.01, 1e-12);

    // Off the walls' lattice: nothing closer than dp either.
    testCase shifted(replaced(dict, "        U           (0.5 0 0);\n",
        "        U           (0.5 0 0);\n"
        "        latticeOrigin (0.0037 -0.0021 0);\n"));
    particleGenerator gen2(shifted.path());
    gen2.generate();
    const particleBody& water2 = bodyNamed(gen2, "water");
    EXPECT_GE(minDistance(water2, bodyNamed(gen2, "tank")),
              0.01*(1 - 1e-6));
    EXPECT_GT(gen2.summaries().back().nDropped, 0);
    EXPECT_GT(water2.size(), 1000);
}


TEST(particleGenerator, fluidOverlappingSolid)
{
    // The water spans the gate, on a lattice shifted from the gate's.
    // (A gate reaching into the tank's floor is an error: badInput.)
    std::string dict = replaced(exampleDict, "max (0.4 0.3 0); }",
                                "max (0.8 0.3 0); }");
    dict = replaced(dict, "latticeOrigin (0.5 0 0);",
                    "latticeOrigin (0.5031 0.0047 0);");
    dict = replaced(dict, "min (0.5 0 0); max (0.52 0.2 0);",
                    "min (0.5 0.0047 0); max (0.53 0.2 0);");
    testCase c(dict);
    particleGenerator gen(c.path());
    testing::internal::CaptureStderr();
    gen.generate();
    const std::string err = testing::internal::GetCapturedStderr();
    const particleBody& gate = bodyNamed(gen, "gate");
    const particleBody& tank = bodyNamed(gen, "tank");
    const particleBody& water = bodyNamed(gen, "water");
    const scalar dmin = 0.01*(1 - 1e-6);
    // The gate's faces between the water's nodes: the water's first layer
    // stands off the contact gap (0.31 dp left of the gate, 0.69 dp right
    // of it), which the generator says.
    EXPECT_GT(gen.summaries()[2].gapExcess,
              particleGenerator::gapExcessWarned);
    EXPECT_LT(gen.summaries()[2].gapExcess, 1);
    EXPECT_NE(err.find("Fluid body 'water': its first layer of particles"
                       " stands on average"), std::string::npos) << err;
    EXPECT_GE(minDistance(water, gate), dmin);
    EXPECT_GE(minDistance(water, tank), dmin);
    EXPECT_GE(minDistance(tank, gate), dmin);
    EXPECT_EQ(gate.size(), 3*20);                 // solids keep everything
    EXPECT_EQ(gen.summaries()[1].nDropped, 0);    // tank
    EXPECT_GT(gen.summaries()[2].nDropped, 0);    // water
    // The water lost little more than the gate's area.
    EXPECT_GT(water.size(), 2400 - 100 - 150);

    std::ostringstream os;
    gen.printSummary(os);
    EXPECT_NE(os.str().find("dropped next to walls or solids"),
              std::string::npos) << os.str();
}


TEST(particleGenerator, unequalGapsAcrossASolidAreWarned)
{
    // A plate 0.75 fluid spacings thick (3 layers of dp/4) in water that
    // spans it: its left face half a spacing from the water's nodes, its
    // right face a quarter spacing off them, so the first layers stand
    // about 0 and 0.27 dp beyond the contact gap. Still water pushes such
    // a plate toward its wider gap (a new user's bent 8.5 mm in 1 s); the
    // warning gives the move of the solid that evens them out, and moved
    // so, it is not warned of.
    std::string dict = replaced(exampleDict, "max (0.4 0.3 0); }",
                                "max (0.8 0.3 0); }");
    const std::string plate = replaced(dict,
        "min (0.5 0 0); max (0.52 0.2 0);", "min (0.5 0 0); max (0.5075 0.2 0);");
    testCase c(replaced(plate, "        latticeOrigin (0.5 0 0);\n",
                        "        dp 0.0025;\n        latticeOrigin (0.5 0 0);\n"));
    testing::internal::CaptureStderr();
    particleGenerator(c.path()).generate();
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("Fluid body 'water' lies on both sides of solid 'gate'"
                       " along x, with gaps that differ"), std::string::npos)
        << err;
    EXPECT_NE(err.find("0.0124 dp beyond the contact gap on the -x face and"
                       " 0.268 dp on the +x face"), std::string::npos) << err;
    EXPECT_NE(err.find("The solid moved by 0.00128 m along x (its shapes,"
                       " clamp and latticeOrigin together) makes the two"
                       " equal (0.14 dp each)"), std::string::npos) << err;

    testCase moved(replaced(replaced(dict, "min (0.5 0 0); max (0.52 0.2 0);",
                                     "min (0.50128 0 0); max (0.50878 0.2 0);"),
        "        latticeOrigin (0.5 0 0);\n",
        "        dp 0.0025;\n        latticeOrigin (0.50128 0 0);\n"));
    testing::internal::CaptureStderr();
    particleGenerator(moved.path()).generate();
    const std::string movedErr = testing::internal::GetCapturedStderr();
    EXPECT_EQ(movedErr.find("with gaps that differ"), std::string::npos)
        << movedErr;
}


TEST(particleGenerator, gapExcessIsTakenFaceByFace)
{
    // A gate of dp/2, 0.025 m thick, in water spanning it: its left face
    // lies half a fluid spacing from the water's nodes (the first layer at
    // the contact gap, 0.0075 m), its right face on them (the first layer
    // kept 0.0125 m off, 0.5 dp beyond the gap; its corner's nodes a
    // little more). Averaged with the left face's 0 it fell below the
    // warning; face by face it is warned of, and named.
    std::string dict = replaced(exampleDict, "max (0.4 0.3 0); }",
                                "max (0.8 0.3 0); }");
    dict = replaced(dict, "min (0.5 0 0); max (0.52 0.2 0);",
                    "min (0.5 0 0); max (0.525 0.2 0);");
    dict = replaced(dict, "        latticeOrigin (0.5 0 0);\n",
                    "        dp 0.005;\n        latticeOrigin (0.5 0 0);\n");
    testCase c(dict);
    particleGenerator gen(c.path());
    testing::internal::CaptureStderr();
    gen.generate();
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_GT(gen.summaries()[2].gapExcess,
              particleGenerator::gapExcessWarned);
    EXPECT_LT(gen.summaries()[2].gapExcess, 0.6);
    EXPECT_NE(err.find("dp farther from the +x face of body 'gate'"),
              std::string::npos) << err;
}


TEST(particleGenerator, finerSolidsBesideACoarseOneDoNotOverlap)
{
    // Solids of one type are kept (dp + dp_o)/2 apart by their own
    // spacings: two at dp/4, 5.5 mm apart between their nearest particles
    // (beyond (dp/4 + dp/4)/2), are no overlap, with a solid at dp listed
    // before them (its spacing gave (dp/4 + dp)/2 = 6.25 mm for both).
    std::string dict = replaced(exampleDict,
        R"(    gate
    {
        type        solid;
        latticeOrigin (0.5 0 0);
        shapes { plate { shape box; min (0.5 0 0); max (0.52 0.2 0); } }
    })",
        R"(    coarse
    {
        type        solid;
        latticeOrigin (0.8 0 0);
        shapes { plate { shape box; min (0.8 0 0); max (0.83 0.2 0); } }
    }
    left
    {
        type        solid;
        dp          0.0025;
        latticeOrigin (0.5 0 0);
        shapes { plate { shape box; min (0.5 0 0); max (0.51 0.2 0); } }
    }
    right
    {
        type        solid;
        dp          0.0025;
        latticeOrigin (0.513 0 0);
        shapes { plate { shape box; min (0.513 0 0); max (0.523 0.2 0); } }
    })");
    const std::string material = "{ rho 2700; E 1e9; nu 0.3; }\n";
    testCase c(dict, fluidProperties, "coarse " + material + "left "
        + material + "right " + material);
    particleGenerator gen(c.path());
    gen.generate();
    const scalar gap = minDistance(bodyNamed(gen, "left"),
                                   bodyNamed(gen, "right"));
    EXPECT_NEAR(gap, 0.0055, 1e-9);

    // Nearer than their own (dp/4 + dp/4)/2 they do overlap.
    const std::string near = replaced(replaced(dict,
        "latticeOrigin (0.513 0 0);", "latticeOrigin (0.5095 0 0);"),
        "min (0.513 0 0); max (0.523 0.2 0);",
        "min (0.5095 0 0); max (0.5195 0.2 0);");
    testCase overlapping(near, fluidProperties, "coarse " + material
        + "left " + material + "right " + material);
    const FatalError err = catchFatal([&]
    {
        particleGenerator(overlapping.path()).generate();
    });
    expectMessage(err, {"Body 'right' (solid) overlaps the solid body left:"});
}


TEST(particleGenerator, threeDimensionalTank)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    const std::string dict =
        "nDimensions 3;\ndp 0.0125;\nbodies\n{\n"
        "    tank { type wall; rho 1000; container { min (0 0 0);"
        " max (0.5 0.5 0.45); layers 3; openTop yes; } }\n"
        "    water { type fluid; rho 998; shapes { column { shape box;"
        " min (0 0 0); max (0.5 0.5 0.3); }\n"
        "        ball { shape sphere; centre (0.25 0.25 0.4); radius 0.04; }"
        " } }\n}\n";
    testCase c(dict, "", "");      // no property files: rho given
    particleGenerator gen(c.path());
    gen.generate();
    const particleBody& tank = bodyNamed(gen, "tank");
    const particleBody& water = bodyNamed(gen, "water");
    EXPECT_EQ(tank.size(), 46*46*39 - 40*40*36);
    const std::size_t nBall = test::countNodes("b { shape sphere;"
        " centre (0.25 0.25 0.4); radius 0.04; }", 3, 0.0125);
    EXPECT_EQ(std::size_t(water.size()), 40*40*24 + nBall);
    expectFields(tank, {0, 0, 0}, 1000);
    expectFields(water, {0, 0, 0}, 998);
    EXPECT_NEAR(water.scalarField("mass")[0], 998*std::pow(0.0125, 3),
                1e-18);

    // Only the fluid's nearest neighbours are checked, with a locator.
    const pointLocator walls(toVectors(tank.position()), 0.0125);
    for (const point& p : water.position())
    {
        ASSERT_FALSE(walls.anyWithin(toVec3(p), 0.0125*(1 - 1e-6)));
    }

    std::ostringstream os;
    gen.printSummary(os);
    EXPECT_NE(os.str().find("m^3"), std::string::npos) << os.str();
}


TEST(particleGenerator, controlDictWriteSettings)
{
    testCase c(exampleDict);
    writeText(c.path()/"system"/"controlDict",
              "application sphVcpmFsi;\nwriteFormat binary;\n"
              "writePrecision 12;\nendTime 1;\n");
    particleGenerator gen(c.path());
    EXPECT_EQ(gen.format(), writeFormat::binary);
    EXPECT_EQ(gen.precision(), 12);
    gen.generate();
    gen.write();
    const std::string position =
        [&]
        {
            std::ifstream is(c.path()/"0"/"water"/"position");
            std::ostringstream os;
            os << is.rdbuf();
            return os.str();
        }();
    EXPECT_NE(position.find("format      binary;"), std::string::npos);
    // Binary is exact.
    for (const particleBody& b : readTimeDirectory(c.path(), "0"))
    {
        const particleBody& orig = bodyNamed(gen, b.name());
        ASSERT_EQ(b.size(), orig.size());
        EXPECT_EQ(std::memcmp(b.position().data(), orig.position().data(),
                              b.size()*sizeof(vec3)), 0);
    }

    // Without the settings: ascii, 10 digits.
    testCase plain(exampleDict);
    writeText(plain.path()/"system"/"controlDict", "endTime 1;\n");
    const particleGenerator gen2(plain.path());
    EXPECT_EQ(gen2.format(), writeFormat::ascii);
    EXPECT_EQ(gen2.precision(), 10);
}


TEST(particleGenerator, wallSurfaceVelocityNoted)
{
    // A wall stays where it is: its U is what the fluid sees at its face
    // (a belt, a cavity's lid), which the log says.
    testCase c(replaced(exampleDict, "type        wall;",
                        "type        wall; U (0.25 0 0);"));
    particleGenerator gen(c.path());
    gen.generate();
    expectFields(bodyNamed(gen, "tank"), {0.25, 0, 0}, 1000);
    std::ostringstream os;
    gen.printSummary(os);
    EXPECT_NE(os.str().find("    tank (wall): 1116 particles, volume 0.1116"
                            " m^2 (shapes 0.1116 m^2, error +0.00 %),"
                            " surface velocity U (0.25 0 0) m/s, in"
                            " place (a motion goes in constant/motion)\n"),
              std::string::npos) << os.str();
}


TEST(particleGenerator, propertyFileDensities)
{
    // rho0 without dimensions, and a dimensioned solid rho.
    testCase c(exampleDict, "rho0 997;\n",
               "gate { rho 1200; E 1e9; nu 0.3; }\nother { rho 5; }\n");
    particleGenerator gen(c.path());
    gen.generate();
    EXPECT_EQ(bodyNamed(gen, "water").scalarField("rho")[0], 997);
    // rho equal to rho0 may be written out.
    testCase same(replaced(replaced(exampleDict, "type        wall;",
        "type        wall; rho 997;"), "type        solid;",
        "type        solid; rho 1200;"), "rho0 997;\n",
        "gate { rho 1200; E 1e9; nu 0.3; }\n");
    EXPECT_NO_THROW(particleGenerator(same.path()).generate());
    EXPECT_EQ(bodyNamed(gen, "tank").scalarField("rho")[0], 997);
    EXPECT_EQ(bodyNamed(gen, "gate").scalarField("rho")[0], 1200);

    // A body's own rho wins, and then no property file is needed.
    testCase own(replaced(replaced(replaced(exampleDict,
        "type        fluid;", "type        fluid;\n        rho 1025;"),
        "type        wall;", "type        wall; rho 1025;"),
        "type        solid;", "type        solid; rho [1 -3 0 0 0 0 0] 7800;"),
        "", "");
    particleGenerator gen2(own.path());
    gen2.generate();
    EXPECT_EQ(bodyNamed(gen2, "water").scalarField("rho")[0], 1025);
    EXPECT_EQ(bodyNamed(gen2, "gate").scalarField("rho")[0], 7800);
}


// * * * * * * * * * * * * * * * * Bad input * * * * * * * * * * * * * * * //

namespace
{

enum class where { dict, fluidProperties, solidProperties, controlDict,
                   none };

struct badCase
{
    const char* name;
    std::string dict;          // the generator's dictionary
    where file;                // the file the error names
    std::string lineOf;        // text on the line it names ("" any line)
    std::vector<std::string> parts;
    std::string fluid = fluidProperties;
    std::string solid = solidProperties;
    std::string control = "";
};

std::vector<badCase> badCases()
{
    const std::string& d = exampleDict;
    const std::string hole = "            hole   { shape sphere; centre"
        " (0.2 0.1 0); radius 0.05; operation subtract; }";
    return
    {
        {"dpZero", replaced(d, "0.01;  ", "0;     "), where::dict, "dp  ",
         {"Keyword 'dp'", "expected a positive number", "found 0"}},
        {"dpNegative", replaced(d, "0.01;  ", "-0.01; "), where::dict,
         "dp  ", {"Keyword 'dp'", "expected a positive number",
         "found -0.01"}},
        {"unknownShape", replaced(d, "shape sphere", "shape ball"),
         where::dict, "hole", {"Keyword 'shape'", "unknown value 'ball'",
         "(box container cylinder polygon seedFill sphere stl"
         " surfaceLayers)"}},
        {"unknownBodyType", replaced(d, "type        fluid;",
         "type        liquid;"), where::dict, "liquid",
         {"Keyword 'type'", "unknown value 'liquid'", "(fluid solid wall)"}},
        {"misspelledTopKeyword", replaced(d, "dp              0.01;",
         "dpp             0.01;"), where::dict, "dpp",
         {"Unknown keyword 'dpp'", "Did you mean 'dp'?", "nDimensions",
          "latticeOrigin", "bodies"}},
        {"misspelledBodyKeyword", replaced(d, "latticeOrigin (0.5",
         "latticeOrign (0.5"), where::dict, "latticeOrign",
         {"Unknown keyword 'latticeOrign'", "Did you mean 'latticeOrigin'?",
          "container", "shapes"}},
        {"misspelledShapeKeyword", replaced(d, "radius 0.05",
         "raduis 0.05"), where::dict, "raduis",
         {"Unknown keyword 'raduis'", "Did you mean 'radius'?",
          "operation"}},
        {"misspelledOperation", replaced(d, "operation subtract",
         "operation substract"), where::dict, "substract",
         {"Keyword 'operation'", "unknown value 'substract'",
          "(add subtract)"}},
        {"maxNotAboveMin", replaced(d, "max (0.4 0.3 0)", "max (0.4 0 0)"),
         where::dict, "column",
         {"max (0.4 0) is not above min (0 0) in y"}},
        {"containerMaxNotAboveMin", replaced(d, "max (1 0.8 0)",
         "max (0 0.8 0)"), where::dict, "container",
         {"max (0 0.8) is not above min (0 0) in x"}},
        {"zeroRadius", replaced(d, "radius 0.05", "radius 0"), where::dict,
         "hole", {"Keyword 'radius'", "expected a positive number"}},
        {"cylinderWithoutAxis", replaced(d, hole, "            hole"
         "   { shape cylinder; point1 (0.2 0.1 0); point2 (0.2 0.1 0);"
         " radius 0.05; operation subtract; }"), where::dict, "hole",
         {"point1 == point2", "no direction"}},
        {"bodyNamedTwice", replaced(d, "    water\n", "    tank\n"),
         where::dict, "    tank\n    {\n        type        fluid",
         {"Body 'tank' is given twice in 'bodies' (first at line",
          "Give each body its own name"}},
        {"containerOnFluid", replaced(d, "type        fluid;",
         "type        fluid;\n        container { min (2 0 0); max (3 1 0);"
         " layers 1; }"), where::dict, "container { min (2 0 0)",
         {"Keyword 'container': body 'water' is a fluid",
          "for wall bodies"}},
        {"zeroLayers", replaced(d, "layers 3", "layers 0"), where::dict,
         "layers", {"at least one layer", "found 0"}},
        {"emptyBody", replaced(d, "min (0.5 0 0); max (0.52 0.2 0);",
         "min (0.501 0 0); max (0.504 0.2 0);"), where::dict, "    gate",
         {"Body 'gate' (solid) has no particles", "no node of its lattice",
          "spacing 0.01"}},
        {"fluidAllInsideWall", replaced(d, "min (0 0 0); max (0.4 0.3 0);",
         "min (-0.03 0 0); max (0 0.3 0);"), where::dict, "    water",
         {"Body 'water' (fluid) has no particles", "all 90 lattice nodes",
          "closer than dp to wall or solid particles"}},
        {"nDimensions4", replaced(d, "nDimensions     2;",
         "nDimensions     4;"), where::dict, "nDimensions",
         {"Keyword 'nDimensions'", "expected 2", "or 3, found 4"}},
        {"nDimensionsNotInteger", replaced(d, "nDimensions     2;",
         "nDimensions     2.5;"), where::dict, "nDimensions",
         {"nDimensions"}},
        {"missingFluidProperties", d, where::dict, "    tank",
         {"Body 'tank' (wall) has no rho", "constant/fluidProperties",
          "does not exist", "rho0"}, ""},
        {"fluidPropertiesWithoutRho0", d, where::fluidProperties, "",
         {"Keyword 'rho0' is undefined", "Did you mean"}, "rho 1000;\n"},
        {"rho0WrongDimensions", d, where::fluidProperties, "rho0",
         {"dimensions do not match", "[1 -3 0 0 0 0 0]"},
         "rho0 [0 2 -1 0 0 0 0] 1000;\n"},
        {"rho0Negative", d, where::fluidProperties, "rho0",
         {"Keyword 'rho0'", "must be positive"}, "rho0 -1000;\n"},
        {"missingSolidProperties", d, where::dict, "    gate",
         {"Body 'gate' (solid) has no rho", "constant/solidProperties",
          "does not exist"}, fluidProperties, ""},
        {"solidPropertiesWithoutBody", d, where::solidProperties, "",
         {"Keyword 'gate' is undefined"}, fluidProperties,
         "plate { rho 2700; }\n"},
        {"negativeRho", replaced(d, "type        fluid;",
         "type        fluid;\n        rho -5;"), where::dict, "rho -5",
         {"Keyword 'rho'", "must be positive", "'water'"}},
        // One fluid density for fluids and walls: a wall's material, or a
        // second fluid, would be silently wrong in the solver.
        {"wallRhoOfItsMaterial", replaced(d, "type        wall;",
         "type        wall; rho 7800;"), where::dict, "rho 7800",
         {"Keyword 'rho' of wall body 'tank': 7800 differs from rho0 1000",
          "leave rho out"}},
        {"secondFluidDensity", replaced(d, "type        fluid;",
         "type        fluid;\n        rho 800;"), where::dict, "rho 800",
         {"Keyword 'rho' of fluid body 'water': 800 differs from rho0 1000",
          "one fluid phase", "or set rho0"}},
        // The solver takes the material's rho: a second one would hold
        // only in 0/ (the masses), and be undone without a word.
        {"solidRhoOtherThanMaterial", replaced(d, "type        solid;",
         "type        solid; rho 900;"), where::dict, "rho 900",
         {"Keyword 'rho' of solid body 'gate': 900 differs from rho 2700",
          "constant/solidProperties/gate", "give the density in one place"}},
        {"velocityOutOfPlane", replaced(d, "U           (0.5 0 0);",
         "U           (0.5 0 1);"), where::dict, "(0.5 0 1)",
         {"Keyword 'U'", "z component"}},
        {"reservedBodyName", replaced(d, "    water\n", "    uniform\n"),
         where::dict, "uniform", {"Invalid body name 'uniform'"}},
        {"bodyWithoutShapes", replaced(d, "        shapes { plate { shape"
         " box; min (0.5 0 0); max (0.52 0.2 0); } }\n", ""), where::dict,
         "    gate", {"Body 'gate' has neither 'shapes' nor 'container'"}},
        {"shapeNotADictionary", replaced(d, hole, "            hole 3;"),
         where::dict, "hole 3", {"Entry 'hole' of 'shapes' is not a shape"}},
        {"firstShapeSubtracts", replaced(d, "max (0.4 0.3 0); }",
         "max (0.4 0.3 0); operation subtract; }"), where::dict, "column",
         {"Shape 'column' subtracts from nothing"}},
        {"emptyBodies", "nDimensions 2;\ndp 0.01;\nbodies\n{\n}\n",
         where::dict, "bodies", {"Dictionary 'bodies' is empty"}},
        {"clampHoldsNothing", replaced(d, "max (0.52 0.2 0); } }",
         "max (0.52 0.2 0); } }\n        clamp { s { shape box;"
         " min (0.6 0 0); max (0.7 0.1 0); } }"), where::dict, "clamp",
         {"Solid 'gate': its clamp holds none of its 40 particles",
          "(0.6 0) to (0.7 0.1)"}},
        {"clampOnFluid", replaced(d, "U           (0.5 0 0);",
         "U           (0.5 0 0);\n        clamp { s { shape box;"
         " min (0 0 0); max (1 1 0); } }"), where::dict, "clamp",
         {"Keyword 'clamp'", "body 'water' is a fluid",
          "only solids have clamps"}},
        {"solidDpNotADivisor", replaced(d, "        latticeOrigin (0.5 0 0);",
         "        latticeOrigin (0.5 0 0);\n        dp 0.0032;"), where::dict,
         "dp 0.0032", {"Keyword 'dp' of solid 'gate'", "expected the"
         " top-level dp 0.01 divided by 1, 2, 3 or 4 (0.01, 0.005,"
         " 0.003333333333 or 0.0025, to 1 %), found 0.0032 (ratio 3.125)"}},
        {"solidTooThin", replaced(d, "max (0.52 0.2 0)", "max (0.51 0.2 0)"),
         where::dict, "    gate", {"Solid 'gate' is too thin",
         "a member only 1 particle thick", "no second-neighbour bonds"}},
        {"nuAboveHalf", d, where::solidProperties, "nu",
         {"Keyword 'nu' of solid 'gate'", "nu = 0.6",
          "outside the admissible range (-0.5, 0.5)"}, fluidProperties,
         "gate { rho 2700; E 1e9; nu 0.6; }\n"},
        {"nuBelowPlaneStressBound", d, where::solidProperties, "nu",
         {"Keyword 'nu' of solid 'gate'", "nu = -0.4",
          "(-0.333333, 0.5)", "plane-stress"}, fluidProperties,
         "gate { rho 2700; E 1e9; nu -0.4; plane planeStress; }\n"},
        {"negativeE", d, where::solidProperties, "E",
         {"Keyword 'E' of solid 'gate'", "E = -1e+09", "must be positive"},
         fluidProperties, "gate { rho 2700; E -1e9; nu 0.3; }\n"},
        {"missingNu", d, where::solidProperties, "",
         {"Keyword 'nu' is undefined"}, fluidProperties,
         "gate { rho 2700; E 1e9; }\n"},
        {"wrongLattice", d, where::solidProperties, "lattice",
         {"Keyword 'lattice'", "solid 'gate' is 2D", "square2D"},
         fluidProperties,
         "gate { rho 2700; E 1e9; nu 0.3; lattice simpleCubic3D; }\n"},
        // Drawn in millimetres with dp in metres: refused before the fill
        // (1.9e9 nodes, 310 GB), not left to the out-of-memory killer.
        {"sizesInMillimetres", replaced(d, "max (0.4 0.3 0); }",
         "max (440 440 0); }"), where::dict, "    water",
         {"body 'water' (fluid) holds more than", "particles at dp 0.01",
          "memory this machine has free", "lengths are in metres"}},
        {"latticeTooLarge", replaced(d, "max (0.4 0.3 0); }",
         "max (4e5 3e5 0); }"), where::dict, "    water",
         {"body 'water' (fluid)", "span more than 2^31 lattice nodes"}},
        {"wallOverlapsSolid", replaced(d, "min (0.5 0 0); max (0.52 0.2 0);",
                                       "min (0.5 -0.02 0); max (0.52 0.2 0);"),
         where::dict, "tank",
         {"Wall body 'tank' overlaps the solid body (gate): 4 of its lattice"
          " nodes lie within (dp + dp_s)/2 of solid particles, from"
          " (0.505 -0.015) to (0.515 -0.005)", "clamp"},
         fluidProperties, solidProperties},
        {"badWriteFormat", d, where::controlDict, "writeFormat",
         {"Keyword 'writeFormat'", "unknown value 'text'",
          "(ascii binary)"}, fluidProperties, solidProperties,
         "writeFormat text;\n"},
    };
}

} // End anonymous namespace


TEST(particleGenerator, badInput)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    for (const badCase& b : badCases())
    {
        SCOPED_TRACE(b.name);
        testCase c(b.dict, b.fluid, b.solid);
        if (!b.control.empty())
        {
            writeText(c.path()/"system"/"controlDict", b.control);
        }
        const FatalError err = catchFatal([&]
        {
            particleGenerator gen(c.path());
            gen.generate();
        });

        fs::path file;
        std::string text;
        switch (b.file)
        {
            case where::dict:
                file = c.dictFile();
                text = b.dict;
                break;
            case where::fluidProperties:
                file = c.path()/"constant"/"fluidProperties";
                text = b.fluid;
                break;
            case where::solidProperties:
                file = c.path()/"constant"/"solidProperties";
                text = b.solid;
                break;
            case where::controlDict:
                file = c.path()/"system"/"controlDict";
                text = b.control;
                break;
            case where::none:
                break;
        }
        if (b.file == where::none)
        {
            expectMessage(err, b.parts);
            continue;
        }
        const int line = b.lineOf.empty() ? -1 : lineOf(text, b.lineOf);
        EXPECT_NE(line, 0) << "no \"" << b.lineOf << "\" in the file";
        expectError(err, file.string(), line, b.parts);
    }
}


TEST(particleGenerator, missingDictionary)
{
    scratchDir dir("generator");
    expectMessage(catchFatal([&]
    {
        particleGenerator gen(dir.path());
    }), {"The particle generation dictionary",
         "system/generateParticlesDict does not exist"});
    std::filesystem::create_directories(dir.path()/"system");
    expectMessage(catchFatal([&]
    {
        particleGenerator gen(dir.path(), "system");
    }), {"The particle generation dictionary", "is a directory, not a file"});
}


// * * * * * * * * * * * * * * * * * Solids * * * * * * * * * * * * * * * //

namespace
{

// A 2D gate plate clamped at its top, dp 0.01.
std::string gateDict(const std::string& max, const std::string& clampMin)
{
    return "nDimensions 2;\ndp 0.01;\nbodies\n{\n    gate\n    {\n"
        "        type solid;\n"
        "        shapes { plate { shape box; min (0 0 0); max " + max + "; } }\n"
        "        clamp { top { shape box; min " + clampMin
        + "; max (1 1 0); } }\n    }\n}\n";
}

// Nodes of an nx x ny block of the unit lattice, shifted.
std::vector<vec3> block(label nx, label ny, scalar x0 = 0, scalar y0 = 0)
{
    std::vector<vec3> p;
    for (label i = 0; i < nx; ++i)
        for (label j = 0; j < ny; ++j)
            p.push_back({x0 + i + 0.5, y0 + j + 0.5, 0});
    return p;
}

} // End anonymous namespace


TEST(particleGenerator, clampedSolid)
{
    testCase c(gateDict("(0.05 0.4 0)", "(-1 0.38 0)"), "",
        "gate { rho 1100; E 12e6; nu 0.4; plane planeStress; }\n");
    particleGenerator gen(c.path());
    gen.generate();
    const particleBody& gate = gen.bodies().front();
    ASSERT_EQ(gate.size(), 5*40);
    const std::vector<label>& clamped = gate.labelField("clamped");
    label n = 0;
    for (label p = 0; p < gate.size(); ++p)
    {
        // The top two rows: y = 0.385, 0.395.
        EXPECT_EQ(clamped[p], gate.position()[p].y > 0.38 ? 1 : 0);
        n += clamped[p];
    }
    EXPECT_EQ(n, 2*5);
    EXPECT_EQ(gen.summaries().front().nClamped, 10);
    // Only members under the 5 % minimum are searched: 4 layers with the
    // surface correction (the default), so the 5-layer gate is none.
    EXPECT_EQ(gen.summaries().front().thinnestLayers, -1);
    std::ostringstream os;
    gen.printSummary(os);
    EXPECT_NE(os.str().find("200 particles"), std::string::npos);
    EXPECT_NE(os.str().find(", 10 clamped"), std::string::npos) << os.str();

    // Written and read back as a label field.
    gen.write();
    const std::vector<particleBody> back =
        readTimeDirectory(c.path(), "0");
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(back[0].labelField("clamped"), clamped);

    // A clamp round the whole body holds it rigid: a warning, no error.
    testCase all(gateDict("(0.05 0.4 0)", "(-1 -1 0)"), "",
        "gate { rho 1100; E 12e6; nu 0.4; plane planeStress; }\n");
    particleGenerator genAll(all.path());
    testing::internal::CaptureStderr();
    genAll.generate();
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(genAll.summaries().front().nClamped, 200);
    EXPECT_NE(err.find("its clamp holds all of its 200 particles, so it"
                       " cannot deform"), std::string::npos) << err;

    // A clamp box that grazes one corner particle: a pivot, a warning.
    testCase corner(gateDict("(0.05 0.4 0)", "(0.04 0.39 0)"), "",
        "gate { rho 1100; E 12e6; nu 0.4; plane planeStress; }\n");
    particleGenerator genCorner(corner.path());
    testing::internal::CaptureStderr();
    genCorner.generate();
    const std::string errCorner = testing::internal::GetCapturedStderr();
    EXPECT_EQ(genCorner.summaries().front().nClamped, 1);
    EXPECT_NE(errCorner.find("Solid 'gate': its clamp holds only 1 of its 200"
        " particles, one point, about which the solid can turn freely"),
        std::string::npos) << errCorner;
    // Two rows of 5 (the default above) are no pivot: no warning there,
    // checked by the captures of the thin-solid tests' clamps too.
}


// Bodies from an #include'd file completed or overridden in the
// dictionary (OpenFOAM's merge): allowed, with a warning naming both
// places; within one file a repeated name is an error (badInput).
TEST(particleGenerator, includedBodyOverridden)
{
    testCase c("nDimensions 2;\ndp 0.01;\nbodies\n{\n"
        "    #include \"baseBodies\"\n"
        "    water { shapes { column { max (0.2 0.1 0); } } }\n}\n");
    writeText(c.path()/"system"/"baseBodies",
        "water\n{\n    type fluid;\n    shapes { column { shape box;"
        " min (0 0 0); max (0.1 0.1 0); } }\n}\n");
    testing::internal::CaptureStderr();     // the bodies are read here
    particleGenerator gen(c.path());
    gen.generate();
    const std::string err = testing::internal::GetCapturedStderr();
    ASSERT_EQ(gen.bodies().size(), 1u);
    EXPECT_EQ(gen.bodies().front().size(), 20*10);   // the override's box
    EXPECT_NE(err.find("Body 'water' of " + (c.path()/"system"/"baseBodies")
        .string() + " line 1 is given again here"), std::string::npos) << err;
    EXPECT_NE(err.find("generateParticlesDict at line 6"), std::string::npos)
        << err;
}


TEST(particleGenerator, solidDpIsAnExactDivisor)
{
    // 'dp 0.00333;' under a top-level 0.01 (3 digits, as one types it) is
    // 0.01/3 to the last bit, the lattices nesting; the summary says so.
    testCase c(replaced(exampleDict, "        latticeOrigin (0.5 0 0);",
                        "        latticeOrigin (0.5 0 0);\n        dp 0.00333;"));
    particleGenerator gen(c.path());
    gen.generate();
    const particleBody& gate = bodyNamed(gen, "gate");
    EXPECT_EQ(gate.dp(), scalar(0.01)/3);
    EXPECT_EQ(gate.size(), 6*60);
    std::ostringstream os;
    gen.printSummary(os);
    EXPECT_NE(os.str().find("    gate (solid): 360 particles, volume 0.004"
                            " m^2 (shapes 0.004 m^2, error +0.00 %),"
                            " dp 0.00333333 (dp/3, for the dp 0.00333"
                            " given)"), std::string::npos) << os.str();
}


TEST(particleGenerator, solidOutsideTheSceneWarns)
{
    // The gate half a metre beyond the tank (a slip of a coordinate): no
    // water can reach it, which the warning says with where each lies.
    // Inside the tank, in the air or the water, nothing is said.
    const auto warnings = [](const std::string& dict)
    {
        testCase c(dict);
        particleGenerator gen(c.path());
        testing::internal::CaptureStderr();
        gen.generate();
        return testing::internal::GetCapturedStderr();
    };
    const std::string out = warnings(replaced(replaced(exampleDict,
        "min (0.5 0 0); max (0.52 0.2 0);", "min (1.5 0 0); max (1.52 0.2 0);"),
        "latticeOrigin (0.5 0 0);", "latticeOrigin (1.5 0 0);"));
    EXPECT_NE(out.find("Solid 'gate' lies outside the box of the fluid and"
                       " the walls ((-0.025 -0.025) to (1.025 0.825)): its"
                       " particles span (1.505 0.005) to (1.515 0.195)"),
              std::string::npos) << out;
    EXPECT_EQ(warnings(exampleDict).find("lies outside"), std::string::npos);
}


TEST(particleGenerator, thinSolidWarns)
{
    // Surface correction on (the default): 2 layers at nu = 0.4 plane
    // stress are about 40 % soft, 3 layers within 0.3 %.
    testCase c(gateDict("(0.02 0.4 0)", "(-1 0.38 0)"), "",
        "gate { rho 1100; E 12e6; nu 0.4; plane planeStress; }\n");
    particleGenerator gen(c.path());
    testing::internal::CaptureStderr();
    gen.generate();
    std::string err = testing::internal::GetCapturedStderr();
    label minLayers = minimumLayers(0.05, 0.4, planeModel::planeStress, true);
    EXPECT_EQ(minLayers, 3);
    EXPECT_NE(err.find("Solid 'gate': its thinnest member is 2 layers"),
              std::string::npos) << err;
    EXPECT_NE(err.find("3 layers give at most 5 % at nu = 0.4 (surface"
                       " correction on)"), std::string::npos) << err;
    // The hint names a spacing the solid may have (top-level dp over 1 to
    // 4), the coarsest fine enough: 0.01 m/2 for 0.0067 m.
    EXPECT_NE(err.find("refine dp to at most 0.00667 m (the solid's own dp"
                       " may be the top-level dp 0.01 divided by 1 to 4:"
                       " 'dp 0.005;' in its entry gives at least 4 layers)"),
              std::string::npos) << err;

    // 3 layers: no warning.
    testCase three(gateDict("(0.03 0.4 0)", "(-1 0.38 0)"), "",
        "gate { rho 1100; E 12e6; nu 0.4; plane planeStress; }\n");
    particleGenerator gen3(three.path());
    testing::internal::CaptureStderr();
    gen3.generate();
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");

    // Plane strain near incompressibility needs more: 5 layers at
    // nu = 0.49 warn, 6 give 5 %.
    testCase nearlyIncompressible(gateDict("(0.05 0.4 0)", "(-1 0.38 0)"),
        "", "gate { rho 1100; E 12e6; nu 0.49; plane planeStrain; }\n");
    particleGenerator genNi(nearlyIncompressible.path());
    testing::internal::CaptureStderr();
    genNi.generate();
    err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("Solid 'gate': its thinnest member is 5 layers"),
              std::string::npos) << err;
    EXPECT_NE(err.find("6 layers give at most 5 % at nu = 0.49 (surface"
                       " correction on)"), std::string::npos) << err;

    // 5 layers: no warning with the correction, about -20 % without it.
    testCase five(gateDict("(0.05 0.4 0)", "(-1 0.38 0)"), "",
        "gate { rho 1100; E 12e6; nu 0.4; plane planeStress; }\n");
    particleGenerator gen5(five.path());
    testing::internal::CaptureStderr();
    gen5.generate();
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");

    testCase off(gateDict("(0.05 0.4 0)", "(-1 0.38 0)"), "",
        "gate { rho 1100; E 12e6; nu 0.4; plane planeStress;"
        " surfaceCorrection off; }\n");
    particleGenerator genOff(off.path());
    testing::internal::CaptureStderr();
    genOff.generate();
    err = testing::internal::GetCapturedStderr();
    minLayers = minimumLayers(0.05, 0.4, planeModel::planeStress, false);
    EXPECT_EQ(minLayers, 19);
    EXPECT_NE(err.find("Solid 'gate': its thinnest member is 5 layers"),
              std::string::npos) << err;
    EXPECT_NE(err.find(std::to_string(minLayers) + " layers give at most 5 %"
                       " at nu = 0.4 (surface correction off)"),
              std::string::npos) << err;

    // Finer than a quarter of the top-level dp: the hint says to refine
    // that (2 layers, 19 needed without the correction).
    testCase thinOff(gateDict("(0.02 0.4 0)", "(-1 0.38 0)"), "",
        "gate { rho 1100; E 12e6; nu 0.4; plane planeStress;"
        " surfaceCorrection off; }\n");
    particleGenerator genThinOff(thinOff.path());
    testing::internal::CaptureStderr();
    genThinOff.generate();
    err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("finer than the top-level dp 0.01 divided by 4, the"
                       " finest a solid's own dp may be: refine the top-level"
                       " dp"), std::string::npos) << err;

    // Thick enough: no warning.
    testCase thick(gateDict("(0.3 0.4 0)", "(-1 0.38 0)"), "",
        "gate { rho 1100; E 12e6; nu 0.4; plane planeStress; }\n");
    particleGenerator gen2(thick.path());
    testing::internal::CaptureStderr();
    gen2.generate();
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    EXPECT_EQ(gen2.summaries().front().thinnestLayers, -1);
}


TEST(latticeMembers, thickness)
{
    // A plate 3 thick, 20 long: 3 layers, either way round.
    EXPECT_EQ(findThinMembers(block(20, 3), 1, 2, 100).thinnestLayers, 3);
    EXPECT_EQ(findThinMembers(block(3, 20), 1, 2, 100).thinnestLayers, 3);
    // Only members thinner than maxLayers are looked for.
    EXPECT_EQ(findThinMembers(block(20, 3), 1, 2, 3).thinnestLayers, -1);
    // A square block is no member; a thin beam on it is.
    EXPECT_EQ(findThinMembers(block(10, 10), 1, 2, 100).thinnestLayers, -1);
    std::vector<vec3> beam = block(10, 10);
    for (const vec3& p : block(30, 4, 10, 3)) beam.push_back(p);
    EXPECT_EQ(findThinMembers(beam, 1, 2, 100).thinnestLayers, 4);

    // A disc: the odd particle at its top is not a member.
    std::vector<vec3> disc;
    for (label i = -12; i <= 12; ++i)
        for (label j = -12; j <= 12; ++j)
            if (i*i + j*j < 10.01*10.01) disc.push_back({scalar(i), scalar(j), 0});
    const latticeMembers d = findThinMembers(disc, 1, 2, 100);
    EXPECT_EQ(d.thinnestLayers, -1);
    EXPECT_TRUE(d.hasSecondNeighbours);

    // One row: 1 layer, no diagonal bonds; one particle: no member either.
    const latticeMembers row = findThinMembers(block(10, 1), 1, 2, 100);
    EXPECT_EQ(row.thinnestLayers, 1);
    EXPECT_FALSE(row.hasSecondNeighbours);
    EXPECT_FALSE(findThinMembers(block(1, 1), 1, 2, 100).hasSecondNeighbours);

    // 3D: a plate 2 thick in z.
    std::vector<vec3> plate;
    for (const vec3& p : block(12, 12))
        for (label k = 0; k < 2; ++k) plate.push_back({p.x, p.y, scalar(k)});
    EXPECT_EQ(findThinMembers(plate, 1, 3, 100).thinnestLayers, 2);

    // Spacing dp and an offset lattice.
    std::vector<vec3> scaled;
    for (const vec3& p : block(20, 3)) scaled.push_back({0.01*p.x + 0.3, 0.01*p.y, 0});
    EXPECT_EQ(findThinMembers(scaled, 0.01, 2, 100).thinnestLayers, 3);
}


TEST(latticeMembers, skipEdges)
{
    // A wall 3 thick in y whose top edge (z = 12) thins to 2 along all x,
    // as the rounded rim of an open surface's layers does.
    std::vector<vec3> wall;
    for (label i = 0; i < 12; ++i)
        for (label k = 0; k < 12; ++k)
            for (label j = 0; j < 3; ++j)
                wall.push_back({scalar(i), scalar(j), scalar(k)});
    for (label i = 0; i < 12; ++i)
        for (label j = 1; j < 3; ++j)
            wall.push_back({scalar(i), scalar(j), 12});
    EXPECT_EQ(findThinMembers(wall, 1, 3, 100).thinnestLayers, 2);
    // Away from the edges the wall is 3 thick.
    EXPECT_EQ(findThinMembers(wall, 1, 3, 100, true).thinnestLayers, 3);
    EXPECT_EQ(findThinMembers(wall, 1, 3, 3, true).thinnestLayers, -1);
    // A thin member is still found away from its ends, even a narrow one.
    EXPECT_EQ(findThinMembers(block(30, 2), 1, 2, 3, true).thinnestLayers, 2);
    EXPECT_EQ(findThinMembers(block(6, 2), 1, 2, 3, true).thinnestLayers, 2);
}


TEST(latticeMembers, onOneLattice)
{
    std::vector<vec3> scaled, turned;
    for (const vec3& p : block(20, 3))
    {
        scaled.push_back({0.01*p.x + 0.3, 0.01*p.y - 0.002, 0});
        // Turned by 10 degrees about the first point: off the lattice.
        const scalar c = std::cos(0.1745), s = std::sin(0.1745);
        turned.push_back({0.01*(c*p.x - s*p.y), 0.01*(s*p.x + c*p.y), 0});
    }
    EXPECT_TRUE(onOneLattice(scaled, 0.01));
    EXPECT_FALSE(onOneLattice(turned, 0.01));
    EXPECT_FALSE(onOneLattice(scaled, 0.013));
    scaled[5].x = std::nan("");
    EXPECT_FALSE(onOneLattice(scaled, 0.01));
}


// Several bodies measured as one: each owner's thinnest member. A floor
// 40 x 4 with two baffles 1 thick and 10 high standing on it, and a
// third body 6 x 6 beside them: both baffles are named, the floor and the
// block have no thin member (the baffles' feet make the floor no thinner).
TEST(latticeMembers, thinnestPerOwner)
{
    std::vector<vec3> points;
    std::vector<label> owner;
    auto add = [&](const std::vector<vec3>& body, const label o)
    {
        points.insert(points.end(), body.begin(), body.end());
        owner.insert(owner.end(), body.size(), o);
    };
    add(block(40, 4), 0);
    add(block(1, 10, 10, 4), 1);
    add(block(1, 10, 20, 4), 2);
    add(block(6, 6, 30, 4), 3);
    const std::vector<latticeMembers> thin =
        findThinMembersByOwner(points, owner, 4, 1, 2, 3, true);
    ASSERT_EQ(thin.size(), 4u);
    EXPECT_EQ(thin[0].thinnestLayers, -1);
    EXPECT_EQ(thin[1].thinnestLayers, 1);
    EXPECT_EQ(owner[thin[1].where], 1);
    EXPECT_EQ(thin[2].thinnestLayers, 1);
    EXPECT_EQ(owner[thin[2].where], 2);
    EXPECT_EQ(thin[3].thinnestLayers, -1);
    // As one body: the thinnest member only.
    EXPECT_EQ(findThinMembers(points, 1, 2, 3, true).thinnestLayers, 1);
    // Owners that are not one per point, or out of range: an error.
    owner.pop_back();
    EXPECT_THROW(findThinMembersByOwner(points, owner, 4, 1, 2, 3),
                 FatalError);
    owner.push_back(4);
    EXPECT_THROW(findThinMembersByOwner(points, owner, 4, 1, 2, 3),
                 FatalError);
}


// The lattice through a given node: a body of one spacing on a shifted
// lattice is not on it.
TEST(latticeMembers, onLatticeThrough)
{
    const std::vector<vec3> floor = block(20, 3);
    const std::vector<vec3> onIt = block(4, 4, 5, 3);
    const std::vector<vec3> shifted = block(4, 4, 5.5, 3.5);
    EXPECT_TRUE(onLatticeThrough(onIt, floor.front(), 1));
    EXPECT_FALSE(onLatticeThrough(shifted, floor.front(), 1));
    EXPECT_TRUE(onLatticeThrough(shifted, shifted.front(), 1));
    EXPECT_TRUE(onOneLattice({}, 1));
}
