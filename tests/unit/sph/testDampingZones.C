/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Damping zones: the rate profile, the decay exp(-rate t) the two time
// schemes give a particle at rest in a zone, and the reader's errors.
#include "dampingZones.H"
#include "error.H"
#include "fluidInteractions.H"
#include "parallel.H"
#include "../testPrecision.H"
#include "../testTools.H"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace sphvcpm;
using test::catchFatal;
using test::expectError;

namespace
{

// Rounding of a few operations on numbers of order 1.
const double eps = test::tol(1e-12, 2e-6);

// A zone from start to end (the reader's form) with the full rate.
dampingZone zoneOf(const vec3& start, const vec3& end, const scalar rate)
{
    const scalar l2 = magSqr(end - start);
    return {toPoint(start), (1/l2)*(end - start), rate};
}

} // End anonymous namespace


TEST(dampingZones, rateRisesAsTheSquareAcrossTheZone)
{
    dampingZones d;
    d.n = 1;
    d.zone[0] = zoneOf({1, 0, 0}, {3, 0, 0}, 10);
    EXPECT_EQ(d.rate({0.5, 0, 0}), 0);
    EXPECT_EQ(d.rate({1, 0, 0}), 0);
    EXPECT_NEAR(d.rate({2, 0, 0}), 2.5, eps);
    EXPECT_NEAR(d.rate({2.5, 0, 0}), 5.625, eps);
    EXPECT_NEAR(d.rate({3, 0, 0}), 10, eps);
    EXPECT_NEAR(d.rate({9, 0, 0}), 10, eps);
    // A half-space: the same across the flume and at any height.
    EXPECT_NEAR(d.rate({2, 7, -3}), 2.5, eps);
    EXPECT_EQ(d.factor({0, 0, 0}, 0.1), 1);
    EXPECT_NEAR(d.factor({9, 0, 0}, 0.1), std::exp(scalar(-1)),
                eps);

    // A slanted zone, and two zones adding up where they overlap.
    d.n = 2;
    d.zone[1] = zoneOf({0, 0, 0}, {0, 2, 2}, 4);
    EXPECT_NEAR(d.rate({2, 1, 1}), 2.5 + 4*0.25, eps);
    EXPECT_NEAR(d.rate({0, 1, 1}), 1, eps);
    EXPECT_EQ(d.rate({0, 1, -3}), 0);
}

// A fluid particle coasting beyond a zone's end, with no force: both time
// schemes relax its velocity as exp(-rate t), whatever the step; a wall
// particle is left alone.
TEST(dampingZones, velocityDecaysAtTheRateInBothSchemes)
{
    const scalar rate = 5;
    dampingZones d;
    d.n = 1;
    d.zone[0] = zoneOf({-2, 0, 0}, {-1, 0, 0}, rate);
    const taitEquationOfState eos{1000, 20, 7};
    const vec3 g{0, 0, 0}, v0{0.2, -0.1, 0.05};
    const scalar dt = 1e-3;
    const int steps = 200;

    for (const bool verlet : {false, true})
    {
        particleFields f;
        f.resize(2, false, false, verlet);
        for (label k = 0; k < 2; ++k)
        {
            f.position[k] = {0, 0, 0};
            f.velocity[k] = v0;
            f.acceleration[k] = {0, 0, 0};
            f.rho[k] = 1000;
            f.drho[k] = 0;
            f.mass[k] = 1;
            f.kind[k] = k == 0 ? fluidKind : wallKind;
        }
        for (int s = 0; s < steps; ++s)
        {
            if (verlet)
            {
                // An Euler step first and every 40, the leapfrog between.
                const scalar span = s % 40 == 0 ? 0 : 2*dt;
                EXPECT_EQ(parallelReduce(serialExec{}, f.size(),
                    verletOp{f.view(), eos, g, dt, span, d}, f.size(),
                    minOp()), f.size());
            }
            else
            {
                parallelFor(serialExec{}, f.size(),
                            predictorOp{f.view(), eos, g, dt});
                EXPECT_EQ(parallelReduce(serialExec{}, f.size(),
                    correctorOp{f.view(), eos, g, dt, false, 0, 0, 2, 0, d},
                    f.size(), minOp()), f.size());
            }
        }
        const scalar decay = std::exp(-rate*steps*dt);
        for (int c = 0; c < 3; ++c)
        {
            EXPECT_NEAR(f.velocity[0][c], decay*v0[c], eps)
                << (verlet ? "verlet" : "symplectic") << " component " << c;
        }
        EXPECT_EQ(f.velocity[1], v0);
    }
}

TEST(dampingZones, read)
{
    test::scratchDir dir("damping");
    // No file: no zones.
    EXPECT_EQ(readDampingZones(dir.path(), 2).n, 0);

    const auto file = dir.write("constant/dampingZones",
        "beach\n{\n    start (2.5 0 0);\n    end (4 0 0);\n    rate 20;\n}\n"
        "side { start (0 1 0); end (0 3 0); rate [0 0 -1 0 0 0 0] 2; }\n");
    std::vector<std::string> lines;
    const dampingZones d = readDampingZones(dir.path(), 2, &lines);
    ASSERT_EQ(d.n, 2);
    EXPECT_NEAR(d.rate({3.25, 0.5, 0}), 5, eps);
    EXPECT_NEAR(d.rate({4, 2, 0}), 20.5, eps);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "beach: from (2.5 0 0) to (4 0 0), rate 20 1/s");

    const std::string f = file.string();
    auto expectBad = [&](const std::string& text, const int line,
                         const std::vector<std::string>& parts)
    {
        test::writeText(file, text);
        expectError(catchFatal([&] { readDampingZones(dir.path(), 2); }), f,
                    line, parts);
    };
    expectBad("beach 3;\n", 1, {"every entry is a damping zone"});
    expectBad("beach\n{\n    start (1 0 0);\n    end (1 0 0);\n    rate 1;\n}\n",
              4, {"end (1 0 0) must differ from start"});
    expectBad("beach { start (0 0 0); end (1 0 0);\nrate -2; }\n", 2,
              {"expected a relaxation rate > 0", "-2"});
    expectBad("beach { start (0 0 0); end (1 0 0);\nrate [0 1 -1 0 0 0 0] 2; }\n",
              2, {"rate"});
    expectBad("beach { start (0 0 1); end (1 0 0); rate 2; }\n", 1,
              {"2D case lies in the x-y plane"});
    expectBad("beach { start (0 0 0); end (1 0 0); rat 2; }\n", 1,
              {"rat", "rate"});
    std::string many;
    for (int z = 0; z <= dampingZones::maxZones; ++z)
    {
        many += "z" + std::to_string(z)
              + " { start (0 0 0); end (1 0 0); rate 1; }\n";
    }
    expectBad(many, dampingZones::maxZones + 1, {"at most 8 damping zones"});
    // 3D: all three components are needed.
    test::writeText(file, "beach { start (0 0); end (1 0 0); rate 2; }\n");
    expectError(catchFatal([&] { readDampingZones(dir.path(), 3); }), f, 1,
                {"start"});
}
