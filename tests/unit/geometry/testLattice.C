/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Lattice filling: exact counts for boxes and containers (no rounding loss
// with faces on nodes or anywhere between), curved shapes against their
// volume, subtraction, alignment of the nodes, and region volumes.

#include "boxShape.H"
#include "../testPrecision.H"
#include "lattice.H"
#include "sphereShape.H"
#include "testGeometryTools.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <sstream>
#include <tuple>

using namespace sphvcpm;
using test::catchFatal;
using test::countNodes;
using test::expectMessage;
using test::shapesRegion;

namespace
{

std::string vecText(const vec3& v)
{
    std::ostringstream os;
    os.precision(17);
    os << '(' << v.x << ' ' << v.y << ' ' << v.z << ')';
    return os.str();
}

std::string boxText(const vec3& min, const vec3& max)
{
    return "b { shape box; min " + vecText(min) + "; max " + vecText(max)
        + "; }";
}

// Count of a container around [0, n dp) per axis with layers and openTop.
std::size_t containerCount(int nDim, const std::vector<int>& n, int layers,
                           bool openTop, scalar dp)
{
    std::ostringstream os;
    os.precision(17);
    os << "c { shape container; min (0 0 0); max (" << n[0]*dp << ' '
       << n[1]*dp << ' ' << (nDim == 3 ? n[2]*dp : 0) << "); layers "
       << layers << "; openTop " << (openTop ? "yes" : "no") << "; }";
    return countNodes(os.str(), nDim, dp);
}

// Relative difference of the node count's volume from the analytic one.
scalar volumeError(const std::string& text, int nDim, scalar dp,
                   scalar exact)
{
    const std::size_t n = countNodes(text, nDim, dp);
    return std::abs(n*std::pow(dp, nDim) - exact)/exact;
}

} // End anonymous namespace


TEST(lattice, boxCountsExact)
{
    EXPECT_EQ(countNodes(boxText({0, 0, 0}, {0.4, 0.3, 0}), 2, 0.01), 1200u);
    EXPECT_EQ(countNodes(boxText({0, 0, 0}, {0.1, 0.2, 0.3}), 3, 0.01),
              6000u);
    // Faces through nodes: min face in, max face out.
    EXPECT_EQ(countNodes(boxText({0.005, 0.005, 0}, {0.405, 0.305, 0}), 2,
                         0.01), 1200u);
    EXPECT_EQ(countNodes(boxText({0.005, 0.005, 0.005},
                                 {0.105, 0.205, 0.305}), 3, 0.01), 6000u);
    // The tutorials' bodies.
    EXPECT_EQ(countNodes(boxText({0, 0, 0}, {1, 0.5, 0}), 2, 0.01), 5000u);
    EXPECT_EQ(countNodes(boxText({0, 0, 0}, {0.5, 0.5, 0.3}), 3, 0.0125),
              40u*40u*24u);
}


TEST(lattice, boxCountsExactAnywhere)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    // A box n dp long holds n nodes per axis wherever it starts: on a
    // node, half-way between nodes, or at a random fraction.
    std::mt19937_64 gen(11);
    std::uniform_int_distribution<int> size(1, 40), shift(-50, 50);
    std::uniform_real_distribution<scalar> frac(0, 1);
    const scalar dps[] = {0.01, 0.0125, 1.0/3.0, 2.5e-4};
    for (int trial = 0; trial < 300; ++trial)
    {
        const int nDim = 2 + trial % 2;
        const scalar dp = dps[trial % 4];
        const vec3 origin{0.1*frac(gen), -0.3*frac(gen), 0.2*frac(gen)};
        const scalar f =
            trial % 3 == 0 ? 0.0 : (trial % 3 == 1 ? 0.5 : frac(gen));
        vec3 min, max;
        std::size_t expected = 1;
        for (int d = 0; d < 3; ++d)
        {
            const int n = size(gen);
            min[d] = origin[d] + (shift(gen) + f)*dp;
            max[d] = min[d] + n*dp;
            if (d < nDim)
            {
                expected *= n;
            }
        }
        EXPECT_EQ(countNodes(boxText(min, max), nDim, dp, origin), expected)
            << "trial " << trial << " dp " << dp << " f " << f;
    }
}


TEST(lattice, touchingBoxesShareNoNode)
{
    // The common face lies on a row of nodes: they go to the upper box.
    const std::string a = boxText({0.005, 0, 0}, {0.105, 0.1, 0});
    const std::string b = boxText({0.105, 0, 0}, {0.205, 0.1, 0});
    EXPECT_EQ(countNodes(a, 2, 0.01), 100u);
    EXPECT_EQ(countNodes(b, 2, 0.01), 100u);
    const std::string both =
        "a { shape box; min (0.005 0 0); max (0.105 0.1 0); }"
        "b { shape box; min (0.105 0 0); max (0.205 0.1 0); }";
    EXPECT_EQ(countNodes(both, 2, 0.01), 200u);
}


TEST(lattice, containerCountsByFormula)
{
    const scalar dp = 0.01;
    for (int layers = 1; layers <= 4; ++layers)
    {
        const int nx = 37, ny = 23, nz = 11, N = layers;
        // 2D: the outer rectangle less the inner one; an open top has
        // no layers above the box.
        EXPECT_EQ(containerCount(2, {nx, ny}, N, false, dp),
                  std::size_t((nx + 2*N)*(ny + 2*N) - nx*ny));
        EXPECT_EQ(containerCount(2, {nx, ny}, N, true, dp),
                  std::size_t((nx + 2*N)*(ny + N) - nx*ny));
        EXPECT_EQ(containerCount(3, {nx, ny, nz}, N, false, dp),
                  std::size_t((nx + 2*N)*(ny + 2*N)*(nz + 2*N) - nx*ny*nz));
        EXPECT_EQ(containerCount(3, {nx, ny, nz}, N, true, dp),
                  std::size_t((nx + 2*N)*(ny + 2*N)*(nz + N) - nx*ny*nz));
    }
    // The tutorials' tanks.
    EXPECT_EQ(containerCount(2, {100, 80}, 3, true, 0.01),
              std::size_t(106*83 - 100*80));
    EXPECT_EQ(containerCount(3, {40, 40, 36}, 3, true, 0.0125),
              std::size_t(46*46*39 - 40*40*36));
}


TEST(lattice, curvedShapesMatchTheirVolume)
{
    const scalar pi = M_PI;
    EXPECT_LT(volumeError("c { shape sphere; centre (0.3 0.2 0);"
        " radius 0.1; }", 2, 0.002, pi*0.01), 0.02);
    EXPECT_LT(volumeError("s { shape sphere; centre (0.3 0.2 0.1);"
        " radius 0.1; }", 3, 0.005, 4.0/3.0*pi*1e-3), 0.02);
    EXPECT_LT(volumeError("c { shape cylinder; point1 (0.1 0.2 0.3);"
        " point2 (0.3 0.5 0.4); radius 0.05; }", 3, 0.004,
        pi*0.0025*std::sqrt(0.04 + 0.09 + 0.01)), 0.02);
    // 2D cuts of cylinders: a disc and a rectangle.
    EXPECT_LT(volumeError("c { shape cylinder; point1 (0.5 0.5 -1);"
        " point2 (0.5 0.5 1); radius 0.2; }", 2, 0.002, pi*0.04), 0.02);
    EXPECT_LT(volumeError("c { shape cylinder; point1 (0 0 0);"
        " point2 (0.6 0.8 0); radius 0.05; }", 2, 0.002, 0.1*1.0), 0.02);
}


TEST(lattice, subtraction)
{
    const std::string box = "b { shape box; min (0 0 0); max (0.4 0.3 0); }";
    EXPECT_EQ(countNodes(box + "h { shape box; min (0.1 0.1 0);"
        " max (0.2 0.2 0); operation subtract; }", 2, 0.01), 1100u);

    // A circular hole: 1200 less the nodes of the circle.
    const std::string hole = "h { shape sphere; centre (0.2 0.1 0);"
        " radius 0.05; operation subtract; }";
    const std::size_t nHole =
        countNodes("h { shape sphere; centre (0.2 0.1 0); radius 0.05; }",
                   2, 0.01);
    EXPECT_EQ(countNodes(box + hole, 2, 0.01), 1200u - nHole);
    EXPECT_LT(volumeError(box + hole, 2, 0.001, 0.12 - M_PI*0.0025), 0.02);

    // Order matters: a shape added after the hole fills it again.
    EXPECT_EQ(countNodes(box + hole + "p { shape sphere; centre (0.2 0.1 0);"
        " radius 0.05; }", 2, 0.01), 1200u);

    // Subtracting from nothing is refused.
    expectMessage(catchFatal([&]
    {
        countNodes(hole + box, 2, 0.01);
    }), {"Shape 'h' subtracts from nothing"});
}


TEST(lattice, alignment)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    const vec3 origin{0.0123, -0.4, 0.7};
    const scalar dp = 0.013;
    for (const int nDim : {2, 3})
    {
        const lattice L(origin, dp, nDim);
        const std::vector<vec3> nodes = L.fill(shapesRegion(
            "s { shape sphere; centre (0.1 0.2 0.7); radius 0.15; }"
            "c { shape container; min (-0.3 -0.2 0.5); max (0.4 0.5 0.9);"
            " layers 2; }", nDim, dp));
        ASSERT_GT(nodes.size(), 100u);
        std::set<std::tuple<long, long, long>> seen;
        for (const vec3& p : nodes)
        {
            long idx[3] = {0, 0, 0};
            for (int d = 0; d < nDim; ++d)
            {
                const scalar i = (p[d] - origin[d])/dp - 0.5;
                ASSERT_NEAR(i, std::round(i), 1e-9) << "axis " << d;
                idx[d] = std::lround(i);
            }
            if (nDim == 2)
            {
                ASSERT_EQ(p.z, 0);
            }
            // Each node once, even where shapes overlap.
            ASSERT_TRUE(seen.insert({idx[0], idx[1], idx[2]}).second);
        }
        // Nodes come x fastest, then y, then z.
        for (std::size_t i = 1; i < nodes.size(); ++i)
        {
            const vec3& a = nodes[i - 1];
            const vec3& b = nodes[i];
            ASSERT_TRUE(std::make_tuple(a.z, a.y, a.x)
                      < std::make_tuple(b.z, b.y, b.x));
        }
    }
}


TEST(lattice, regionVolume)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    const scalar dp = 0.01;
    EXPECT_NEAR(shapesRegion("b { shape box; min (0 0 0);"
        " max (0.4 0.3 0); }", 2, dp).volume(), 0.12, 1e-15);
    EXPECT_NEAR(shapesRegion("b { shape box; min (0 0 0); max (0.4 0.3 0); }"
        "h { shape sphere; centre (0.2 0.1 0); radius 0.05;"
        " operation subtract; }", 2, dp).volume(),
        0.12 - M_PI*0.0025, 1e-15);
    EXPECT_NEAR(shapesRegion("a { shape box; min (0 0 0); max (1 1 1); }"
        "b { shape sphere; centre (3 0 0); radius 1; }", 3, dp).volume(),
        1 + 4.0/3.0*M_PI, 1e-14);
    // Overlapping additions, or a hole reaching out of its box: unknown.
    EXPECT_LT(shapesRegion("a { shape box; min (0 0 0); max (1 1 0); }"
        "b { shape box; min (0.5 0.5 0); max (2 2 0); }", 2, dp).volume(),
        0);
    EXPECT_LT(shapesRegion("a { shape box; min (0 0 0); max (1 1 0); }"
        "h { shape sphere; centre (1 0.5 0); radius 0.2;"
        " operation subtract; }", 2, dp).volume(), 0);
}


TEST(lattice, limits)
{
    // A region whose shapes all lie out of the z = 0 plane is empty.
    EXPECT_EQ(countNodes("c { shape cylinder; point1 (0 0 1); point2 (0 0 2);"
        " radius 0.5; }", 2, 0.01), 0u);
    // Bounds far too big for the spacing.
    expectMessage(catchFatal([]
    {
        countNodes("b { shape box; min (0 0 0); max (1000 1000 1000); }", 3,
                   1e-3);
    }), {"span more than 2^31 lattice nodes"});
    expectMessage(catchFatal([]
    {
        lattice({0, 0, 0}, 0, 2);
    }), {"dp must be positive"});
    // More nodes inside than the memory takes: stopped during the fill
    // (the 1200 nodes of a box fit in 1200, not in 1199), with the sizes.
    const region box = shapesRegion(boxText({0, 0, 0}, {0.4, 0.3, 0}), 2,
                                    0.01);
    EXPECT_EQ(lattice({0, 0, 0}, 0.01, 2).fill(box, "box", 1200).size(),
              1200u);
    expectMessage(catchFatal([&]
    {
        lattice({0, 0, 0}, 0.01, 2).fill(box, "body 'water' (fluid)", 1199);
    }), {"body 'water' (fluid) holds more than 1199 particles at dp 0.01",
         "(its bounds (0 0 0) to (0.4 0.3 0))", "lengths are in metres",
         "millimetres give 10^6 times"});
}
