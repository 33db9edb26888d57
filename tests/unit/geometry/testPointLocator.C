/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// pointLocator against brute force, in 2D and 3D, with a dense cell array
// and with sparse cell keys (two clusters far apart).

#include "pointLocator.H"
#include "../testPrecision.H"
#include "testGeometryTools.H"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace sphvcpm;
using test::catchFatal;
using test::expectMessage;

namespace
{

bool bruteAnyWithin(const std::vector<vec3>& points, const vec3& p,
                    scalar d)
{
    for (const vec3& q : points)
    {
        if (magSqr(q - p) < d*d)
        {
            return true;
        }
    }
    return false;
}

scalar bruteNearest(const std::vector<vec3>& points, const vec3& p)
{
    scalar best = std::numeric_limits<scalar>::max();
    for (const vec3& q : points)
    {
        best = std::min(best, mag(q - p));
    }
    return best;
}

// Random points in the box [lo, hi), z = 0 in 2D.
std::vector<vec3> randomPoints(std::mt19937_64& gen, std::size_t n,
                               const vec3& lo, const vec3& hi, int nDim)
{
    std::uniform_real_distribution<scalar> u(0, 1);
    std::vector<vec3> points(n);
    for (vec3& p : points)
    {
        for (int d = 0; d < 3; ++d)
        {
            p[d] = lo[d] + u(gen)*(hi[d] - lo[d]);
        }
        if (nDim == 2)
        {
            p.z = 0;
        }
    }
    return points;
}

void compareWithBruteForce(const std::vector<vec3>& points,
                           const std::vector<vec3>& queries, scalar cell)
{
    const pointLocator locator(points, cell);
    ASSERT_EQ(locator.size(), points.size());
    int nNear = 0;
    for (const vec3& p : queries)
    {
        for (const scalar d : {cell, scalar(0.5*cell), scalar(0.1*cell)})
        {
            const bool want = bruteAnyWithin(points, p, d);
            ASSERT_EQ(locator.anyWithin(p, d), want)
                << "query (" << p.x << ' ' << p.y << ' ' << p.z << ") d "
                << d;
            nNear += want;
        }
        const scalar nearest = bruteNearest(points, p);
        ASSERT_NEAR(locator.nearestWithinCell(p),
                    nearest < cell ? nearest : cell, 1e-15);
    }
    // The sample must test both answers.
    EXPECT_GT(nNear, 0);
    EXPECT_LT(nNear, int(3*queries.size()));
}

} // End anonymous namespace


TEST(pointLocator, denseGridMatchesBruteForce)
{
    std::mt19937_64 gen(3);
    for (const int nDim : {2, 3})
    {
        const auto points =
            randomPoints(gen, 2000, {0, 0, 0}, {1, 1, 1}, nDim);
        const auto queries =
            randomPoints(gen, 2000, {-0.2, -0.2, -0.2}, {1.2, 1.2, 1.2},
                         nDim);
        compareWithBruteForce(points, queries, nDim == 2 ? 0.02 : 0.08);
    }
}


TEST(pointLocator, sparseKeysMatchBruteForce)
{
    // Two small clusters 1e4 cells apart per axis: too many cells for a
    // dense array.
    std::mt19937_64 gen(5);
    auto points = randomPoints(gen, 500, {0, 0, 0}, {0.1, 0.1, 0.1}, 3);
    const auto far =
        randomPoints(gen, 500, {100, 100, 100}, {100.1, 100.1, 100.1}, 3);
    points.insert(points.end(), far.begin(), far.end());
    auto queries =
        randomPoints(gen, 500, {-0.05, -0.05, -0.05}, {0.15, 0.15, 0.15}, 3);
    const auto farQueries = randomPoints(gen, 500, {99.95, 99.95, 99.95},
                                         {100.15, 100.15, 100.15}, 3);
    queries.insert(queries.end(), farQueries.begin(), farQueries.end());
    queries.push_back({50, 50, 50});
    queries.push_back({-1e30, 1e30, 0});
    compareWithBruteForce(points, queries, 0.01);
}


TEST(pointLocator, latticeNeighbours)
{
    // On a lattice of spacing dp, a node's neighbours are at dp exactly:
    // "within dp" must exclude them and "within dp (1 + 1e-6)" find them.
    const scalar dp = 0.01;
    std::vector<vec3> nodes;
    for (int j = 0; j < 10; ++j)
    {
        for (int i = 0; i < 10; ++i)
        {
            nodes.push_back({(i + 0.5)*dp, (j + 0.5)*dp, 0});
        }
    }
    const pointLocator locator(nodes, dp);
    const vec3 offLattice{10.5*dp, 4.5*dp, 0};    // one column out
    EXPECT_FALSE(locator.anyWithin(offLattice, dp*(1 - 1e-6)));
    EXPECT_TRUE(locator.anyWithin(offLattice + vec3{-1e-5*dp, 0, 0}, dp));
    EXPECT_TRUE(locator.anyWithin(nodes[55], 0.5*dp));
}


TEST(pointLocator, emptyAndErrors)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    const pointLocator none({}, 0.1);
    EXPECT_FALSE(none.anyWithin({0, 0, 0}, 0.1));
    EXPECT_EQ(none.nearestWithinCell({0, 0, 0}), 0.1);

    const pointLocator one({{0, 0, 0}}, 0.1);
    expectMessage(catchFatal([&]
    {
        one.anyWithin({0, 0, 0}, 0.2);
    }), {"query distance", "exceeds the cell size"});
    expectMessage(catchFatal([]
    {
        pointLocator({{0, 0, 0}}, 0);
    }), {"cell size must be positive"});
}
