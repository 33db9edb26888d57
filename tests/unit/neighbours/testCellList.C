/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The cell-linked list against brute force, in 2D and 3D: uniform and
// clustered clouds, particles exactly on cell faces (dyadic and decimal
// cell sizes), particles outside the grid and non-finite positions, cell
// divisors 1, 2 and 3 (the GPU's default), serial and OpenMP builds (which must agree exactly),
// the host's ranges (a walk per row of cells) against the GPU's (a search
// per cell),
// the kind ranges and the walks of one kind, the walks around a point
// that reach only the cells within the support, and the errors of
// makeCellGrid.

#include "cellList.H"
#include "../testPrecision.H"
#include "../testTools.H"
#include "error.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>
#include <limits>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

using namespace sphvcpm;

namespace
{

const scalar NaN = std::numeric_limits<scalar>::quiet_NaN();
const scalar Inf = std::numeric_limits<scalar>::infinity();

struct cloud
{
    std::string name;
    point lower, upper;
    scalar support;
    int nDim;
    std::vector<point> x;
};

// The ranges of the GPU's pass (fillCellRanges: a search per cell) from
// the list's sorted keys equal the host's (buildCellList: a walk per row).
void expectGpuRangesEqual(const cellList& l)
{
    const cellGrid& g = l.grid;
    const label n = label(l.keys.size());
    std::vector<label> rowStart(g.nRows() + 1), cellStart(g.nCells() + 1);
    std::vector<label> kindEnd(2*g.nCells());
    std::vector<std::uint32_t> flags(g.nBlocks());
    fillCellRanges(serialExec{}, g, l.keys.data(), n, rowStart.data(),
                   cellStart.data(), kindEnd.data(), flags.data());
    EXPECT_TRUE(rowStart == l.rowStart);
    EXPECT_TRUE(cellStart == l.cellStart);
    EXPECT_TRUE(kindEnd == l.kindEnd);
    EXPECT_TRUE(flags == l.blockHasFluid);
}

// Calls visit(c) for every cell c of the stencil st: the reach cells each
// way around a cell, which the block flags and the walks are measured
// against.
template<class F>
void forEachCellOf(const cellGrid& g, const stencil& st, const F& visit)
{
    for (int z = st.z0; z <= st.z1; ++z)
    {
        for (int y = st.y0; y <= st.y1; ++y)
        {
            const label row = g.rowStart(z, y);
            for (int x = st.x0; x <= st.x1; ++x)
            {
                visit(row + x);
            }
        }
    }
}

scalar uniform(std::mt19937_64& gen, const scalar a, const scalar b)
{
    return std::uniform_real_distribution<scalar>(a, b)(gen);
}

// n points uniformly in [lower, upper] (z = 0 in 2D).
void addUniform(cloud& c, std::mt19937_64& gen, const label n)
{
    for (label k = 0; k < n; ++k)
    {
        c.x.push_back({uniform(gen, c.lower.x, c.upper.x),
                       uniform(gen, c.lower.y, c.upper.y),
                       c.nDim == 3 ? uniform(gen, c.lower.z, c.upper.z) : 0});
    }
}

// Gaussian clusters of width sigma (some points fall outside the domain),
// and a pile of particles at one identical position.
void addClusters(cloud& c, std::mt19937_64& gen, const int nClusters,
                 const label perCluster, const scalar sigma)
{
    std::normal_distribution<scalar> normal(0, sigma);
    for (int k = 0; k < nClusters; ++k)
    {
        const point centre{uniform(gen, c.lower.x, c.upper.x),
                          uniform(gen, c.lower.y, c.upper.y),
                          c.nDim == 3 ? uniform(gen, c.lower.z, c.upper.z) : 0};
        for (label m = 0; m < perCluster; ++m)
        {
            c.x.push_back({centre.x + normal(gen), centre.y + normal(gen),
                           c.nDim == 3 ? centre.z + normal(gen) : 0});
        }
    }
    const point pile{uniform(gen, c.lower.x, c.upper.x),
                    uniform(gen, c.lower.y, c.upper.y),
                    c.nDim == 3 ? uniform(gen, c.lower.z, c.upper.z) : 0};
    for (int m = 0; m < 25; ++m)
    {
        c.x.push_back(pile);
    }
}

// Points on the faces of the cells of both divisors: a lattice of spacing
// support/perSupport (2 or 4) from the lower corner (many pairs exactly
// support apart), the upper corner, and random points with one coordinate
// on a face.
void addFacePoints(cloud& c, std::mt19937_64& gen, const int perSupport,
                   const label nRandom)
{
    const scalar s = c.support/perSupport;
    const int nx = int(std::floor((c.upper.x - c.lower.x)/s + 1e-9)) + 1;
    const int ny = int(std::floor((c.upper.y - c.lower.y)/s + 1e-9)) + 1;
    const int nz = c.nDim == 3
        ? int(std::floor((c.upper.z - c.lower.z)/s + 1e-9)) + 1 : 1;
    for (int k = 0; k < nz; ++k)
    {
        for (int j = 0; j < ny; ++j)
        {
            for (int i = 0; i < nx; ++i)
            {
                c.x.push_back({c.lower.x + i*s, c.lower.y + j*s,
                               c.nDim == 3 ? c.lower.z + k*s : 0});
            }
        }
    }
    c.x.push_back({c.upper.x, c.upper.y, c.nDim == 3 ? c.upper.z : 0});
    std::uniform_int_distribution<int> axis(0, c.nDim - 1);
    for (label m = 0; m < nRandom; ++m)
    {
        point p{uniform(gen, c.lower.x, c.upper.x),
               uniform(gen, c.lower.y, c.upper.y),
               c.nDim == 3 ? uniform(gen, c.lower.z, c.upper.z) : 0};
        const int a = axis(gen);
        const scalar half = c.support/2;   // a face for divisors 1 and 2
        const int nFaces = int((c.upper[a] - c.lower[a])/half);
        p[a] = c.lower[a]
             + std::uniform_int_distribution<int>(0, nFaces)(gen)*half;
        c.x.push_back(p);
    }
}

// Particles outside every grid the cloud gives, and non-finite ones.
void addOutside(cloud& c)
{
    const scalar s = c.support;
    const point mid = 0.5*(c.lower + c.upper);
    const scalar zMid = c.nDim == 3 ? mid.z : 0;
    c.x.push_back({c.lower.x - 0.3*s, mid.y, zMid});
    c.x.push_back({mid.x, c.lower.y - 1e-3*s, zMid});
    c.x.push_back({c.upper.x + 1.1*s, mid.y, zMid});   // past the last cell
    c.x.push_back({mid.x, c.upper.y + 5*s, zMid});
    c.x.push_back({-1e30, 1e30, zMid});
    if (c.nDim == 3)
    {
        c.x.push_back({mid.x, mid.y, c.lower.z - 0.5*s});
        c.x.push_back({mid.x, mid.y, c.upper.z + 1.5*s});
    }
    else
    {
        c.x.push_back({mid.x, mid.y, 0.6*s});   // off the one 2D layer
    }
    c.x.push_back({NaN, NaN, NaN});
    c.x.push_back({mid.x, NaN, zMid});
    c.x.push_back({Inf, mid.y, zMid});
}

// Where a point lies with respect to the grid: clearly inside, clearly
// outside (or not finite), or within rounding of the grid boundary.
enum class where { inside, outside, boundary };

where classify(const cellGrid& g, const point& x)
{
    const scalar tol = 1e-9*g.cellSize;
    const int n[3] = {g.nx, g.ny, g.nz};
    bool boundary = false;
    for (int d = 0; d < 3; ++d)
    {
        if (!std::isfinite(x[d]))
        {
            return where::outside;
        }
        const scalar lo = g.origin[d];
        const scalar hi = g.origin[d] + n[d]*g.cellSize;
        if (x[d] < lo - tol || x[d] > hi + tol)
        {
            return where::outside;
        }
        if (x[d] < lo + tol || x[d] > hi - tol)
        {
            boundary = true;
        }
    }
    return boundary ? where::boundary : where::inside;
}

// Every check of one list built from positions x0.
void checkList(const cellList& list, const std::vector<point>& x0,
               const scalar support)
{
    const cellGrid& g = list.grid;
    const label n = label(x0.size());
    const label nCells = g.nCells();
    const scalar support2 = support*support;

    // order is a permutation, stable within each cell.
    ASSERT_EQ(label(list.order.size()), n);
    ASSERT_EQ(label(list.keys.size()), n);
    {
        std::vector<label> sorted(list.order);
        std::sort(sorted.begin(), sorted.end());
        std::vector<label> iota(n);
        std::iota(iota.begin(), iota.end(), label(0));
        ASSERT_EQ(sorted, iota) << "order is not a permutation";
    }
    std::vector<point> x(n);
    for (label k = 0; k < n; ++k)
    {
        x[k] = x0[list.order[k]];
    }

    // Keys: sorted, those of the reordered positions, order stable.
    EXPECT_TRUE(std::is_sorted(list.keys.begin(), list.keys.end()));
    for (label k = 0; k < n; ++k)
    {
        ASSERT_EQ(cellOfKey(list.keys[k]), g.cellOf(x[k])) << "k = " << k;
        if (k > 0 && list.keys[k] == list.keys[k - 1])
        {
            ASSERT_LT(list.order[k - 1], list.order[k]) << "unstable sort";
        }
    }

    // cellStart: monotone, ranges of the cells, total nInside.
    ASSERT_EQ(label(list.cellStart.size()), nCells + 1);
    EXPECT_EQ(list.cellStart[0], 0);
    EXPECT_EQ(list.cellStart[nCells], list.nInside);
    EXPECT_GE(list.nInside, 0);
    EXPECT_LE(list.nInside, n);
    for (label c = 0; c < nCells; ++c)
    {
        ASSERT_LE(list.cellStart[c], list.cellStart[c + 1]) << "c = " << c;
        for (label k = list.cellStart[c]; k < list.cellStart[c + 1]; ++k)
        {
            ASSERT_EQ(cellOfKey(list.keys[k]), c);
        }
    }

    // Each particle lies geometrically in its cell; the outside ones last.
    const scalar tol = 1e-9*g.cellSize;
    for (label k = 0; k < n; ++k)
    {
        const where w = classify(g, x[k]);
        if (k < list.nInside)
        {
            ASSERT_NE(w, where::outside)
                << "particle " << list.order[k] << " at (" << x[k].x << ' '
                << x[k].y << ' ' << x[k].z << ") is outside the grid but"
                << " sorted before nInside";
            const label c = cellOfKey(list.keys[k]);
            const int idx[3] =
                {int(c % g.nx), int((c/g.nx) % g.ny), int(c/(label(g.nx)*g.ny))};
            for (int d = 0; d < 3; ++d)
            {
                const scalar lo = g.origin[d] + idx[d]*g.cellSize;
                const scalar hi = lo + g.cellSize;
                ASSERT_GE(x[k][d], lo - tol) << "k " << k << " dir " << d;
                ASSERT_LE(x[k][d], hi + tol) << "k " << k << " dir " << d;
            }
        }
        else
        {
            ASSERT_NE(w, where::inside)
                << "particle " << list.order[k] << " at (" << x[k].x << ' '
                << x[k].y << ' ' << x[k].z << ") is inside the grid but"
                << " sorted after nInside";
            ASSERT_EQ(cellOfKey(list.keys[k]), nCells);
        }
    }

    // Neighbours within the support: stencil walk == brute force, and no
    // candidate is visited twice.
    std::vector<int> visits(n, 0);
    std::vector<label> found, brute;
    label nPairs = 0;
    for (label i = 0; i < list.nInside; ++i)
    {
        found.clear();
        brute.clear();
        bool outOfRange = false;
        forEachCandidate(g, list.cellStart.data(), x[i], [&](const label j)
        {
            if (j < 0 || j >= list.nInside)
            {
                outOfRange = true;
                return;
            }
            ++visits[j];
            if (magSqr(x[i] - x[j]) < support2)
            {
                found.push_back(j);
            }
        });
        ASSERT_FALSE(outOfRange) << "candidate index outside [0, nInside)";
        for (label j = 0; j < list.nInside; ++j)
        {
            if (visits[j] > 1)
            {
                ADD_FAILURE() << "candidate " << j << " visited " << visits[j]
                    << " times from particle " << i;
            }
            visits[j] = 0;
            if (magSqr(x[i] - x[j]) < support2)
            {
                brute.push_back(j);
            }
        }
        std::sort(found.begin(), found.end());
        if (found != brute)
        {
            std::vector<label> missed;
            std::set_difference(brute.begin(), brute.end(), found.begin(),
                                found.end(), std::back_inserter(missed));
            std::string msg;
            for (const label j : missed)
            {
                msg += " " + std::to_string(j) + " (r/support - 1 = "
                     + std::to_string(mag(x[i] - x[j])/support - 1)
                     + ", cells " + std::to_string(cellOfKey(list.keys[i])) + " "
                     + std::to_string(cellOfKey(list.keys[j])) + ")";
            }
            ADD_FAILURE() << "particle " << i << " at (" << x[i].x << ' '
                << x[i].y << ' ' << x[i].z << "): stencil finds "
                << found.size() << " neighbours, brute force "
                << brute.size() << "; missed:" << msg;
            return;
        }
        nPairs += label(brute.size());
    }
    // The clouds are dense enough that the comparison means something.
    if (list.nInside > 100)
    {
        EXPECT_GT(nPairs, 4*list.nInside);
    }
}

// Builds the lists of one cloud for divisors 1, 2 and 3 with both host
// backends, checks each and compares them.
void checkCloud(const cloud& c)
{
    for (const int divisor : {1, 2, 3})
    {
        SCOPED_TRACE(c.name + ", " + std::to_string(c.nDim) + "D, divisor "
                     + std::to_string(divisor));
        const cellGrid g =
            makeCellGrid(c.lower, c.upper, c.support, divisor, c.nDim);
        EXPECT_EQ(g.reach, divisor);
        // A relative 1e-9 larger than support/divisor (rounding margin).
        EXPECT_NEAR(g.cellSize/(c.support/divisor), 1 + 1e-9, 1e-12);
        // The grid covers the bounds, upper faces included (the count uses
        // the same arithmetic as cellOf, so upper itself is inside even
        // when the last cell ends on it).
        EXPECT_LT(g.cellOf(c.lower), g.nCells());
        EXPECT_LT(g.cellOf(c.upper), g.nCells());
        EXPECT_GE(g.origin.x + g.nx*g.cellSize, c.upper.x);
        EXPECT_GE(g.origin.y + g.ny*g.cellSize, c.upper.y);
        if (c.nDim == 3)
        {
            EXPECT_GE(g.origin.z + g.nz*g.cellSize, c.upper.z);
        }
        else
        {
            EXPECT_EQ(g.nz, 1);
            EXPECT_DOUBLE_EQ(g.origin.z, -0.5*g.cellSize);
        }

        // The expected number inside, where no point is ambiguous.
        label nIn = 0;
        bool ambiguous = false;
        for (const point& p : c.x)
        {
            const where w = classify(g, p);
            nIn += w == where::inside;
            ambiguous = ambiguous || w == where::boundary;
        }

        const label n = label(c.x.size());
        cellList serialList, openmpList;
        buildCellList(serialExec{}, g, c.x.data(), nullptr, n, serialList);
        buildCellList(openmpExec{}, g, c.x.data(), nullptr, n, openmpList);
        if (!ambiguous)
        {
            EXPECT_EQ(serialList.nInside, nIn);
        }
        EXPECT_LT(serialList.nInside, n);   // every cloud has outsiders

        {
            SCOPED_TRACE("serialExec");
            checkList(serialList, c.x, c.support);
        }
        {
            SCOPED_TRACE("openmpExec");
            checkList(openmpList, c.x, c.support);
        }
        EXPECT_EQ(serialList.nInside, openmpList.nInside);
        EXPECT_TRUE(serialList.keys == openmpList.keys);
        EXPECT_TRUE(serialList.order == openmpList.order);
        EXPECT_TRUE(serialList.cellStart == openmpList.cellStart);
        expectGpuRangesEqual(openmpList);
    }
}

cloud makeCloud(const std::string& name, const int nDim, const point& lower,
                const point& upper, const scalar support)
{
    cloud c;
    c.name = name;
    c.nDim = nDim;
    c.lower = nDim == 3 ? lower : point{lower.x, lower.y, 0};
    c.upper = nDim == 3 ? upper : point{upper.x, upper.y, 0};
    c.support = support;
    return c;
}

// A decimal (non-dyadic) domain and support, as in a case file.
const point decLower{-0.3, -0.2, -0.1};
const point decUpper{0.7, 0.5, 0.4};
const scalar decSupport = 0.07;

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests  * * * * * * * * * * * * * * * * //

TEST(cellList, uniformClouds)
{
    // Exact cell membership of points on cell faces, in double digits.
    SPHVCPM_DOUBLE_ONLY();
    for (const int nDim : {2, 3})
    {
        std::mt19937_64 gen(11 + nDim);
        cloud c = makeCloud("uniform", nDim, decLower, decUpper, decSupport);
        addUniform(c, gen, nDim == 3 ? 3000 : 2500);
        addOutside(c);
        std::shuffle(c.x.begin(), c.x.end(), gen);
        checkCloud(c);
    }
}

TEST(cellList, clusteredClouds)
{
    // Exact cell membership of points on cell faces, in double digits.
    SPHVCPM_DOUBLE_ONLY();
    for (const int nDim : {2, 3})
    {
        std::mt19937_64 gen(23 + nDim);
        cloud c = makeCloud("clustered", nDim, decLower, decUpper, decSupport);
        addClusters(c, gen, 4, 500, 0.4*decSupport);
        addUniform(c, gen, 300);
        addOutside(c);
        std::shuffle(c.x.begin(), c.x.end(), gen);
        checkCloud(c);
    }
}

// Dyadic sizes: the faces and the pair distances are exact, so many pairs
// are exactly one support apart (not neighbours: r < support is strict).
TEST(cellList, pointsOnFacesDyadic)
{
    // Exact cell membership of points on cell faces, in double digits.
    SPHVCPM_DOUBLE_ONLY();
    for (const int nDim : {2, 3})
    {
        std::mt19937_64 gen(37 + nDim);
        cloud c = makeCloud("faces (dyadic)", nDim, {0, 0, 0},
                            {1.0, 0.75, 0.5}, 0.25);
        addFacePoints(c, gen, 4, 500);
        addOutside(c);
        std::shuffle(c.x.begin(), c.x.end(), gen);
        checkCloud(c);
    }
}

// Decimal sizes: the face coordinates and distances carry rounding, so a
// pair nominally one support apart may measure a hair less than it.
TEST(cellList, pointsOnFacesDecimal)
{
    // Exact cell membership of points on cell faces, in double digits.
    SPHVCPM_DOUBLE_ONLY();
    for (const int nDim : {2, 3})
    {
        std::mt19937_64 gen(41 + nDim);
        cloud c = makeCloud("faces (decimal)", nDim, decLower, decUpper,
                            decSupport);
        addFacePoints(c, gen, nDim == 3 ? 2 : 4, 500);
        addOutside(c);
        std::shuffle(c.x.begin(), c.x.end(), gen);
        checkCloud(c);
    }
}

// Large enough that the OpenMP sort and loops run on several blocks; the
// neighbour sets are checked on a sample.
TEST(cellList, largeCloudSerialEqualsOpenmp)
{
    std::mt19937_64 gen(53);
    cloud c = makeCloud("large", 3, {0, 0, 0}, {1, 1, 1}, 0.05);
    addUniform(c, gen, 60000);
    addOutside(c);
    std::shuffle(c.x.begin(), c.x.end(), gen);
    const label n = label(c.x.size());
    for (const int divisor : {1, 2, 3})
    {
        const cellGrid g = makeCellGrid(c.lower, c.upper, c.support,
                                        divisor, 3);
        cellList a, b;
        buildCellList(serialExec{}, g, c.x.data(), nullptr, n, a);
        buildCellList(openmpExec{}, g, c.x.data(), nullptr, n, b);
        EXPECT_EQ(a.nInside, 60000);
        EXPECT_EQ(a.nInside, b.nInside);
        EXPECT_TRUE(a.keys == b.keys);
        EXPECT_TRUE(a.order == b.order);
        EXPECT_TRUE(a.cellStart == b.cellStart);
        EXPECT_TRUE(std::is_sorted(b.keys.begin(), b.keys.end()));

        std::vector<point> x(n);
        for (label k = 0; k < n; ++k)
        {
            x[k] = c.x[b.order[k]];
        }
        const scalar s2 = c.support*c.support;
        std::uniform_int_distribution<label> pick(0, b.nInside - 1);
        for (int m = 0; m < 300; ++m)
        {
            const label i = pick(gen);
            std::vector<label> found, brute;
            forEachCandidate(g, b.cellStart.data(), x[i], [&](const label j)
            {
                if (magSqr(x[i] - x[j]) < s2) found.push_back(j);
            });
            for (label j = 0; j < b.nInside; ++j)
            {
                if (magSqr(x[i] - x[j]) < s2) brute.push_back(j);
            }
            std::sort(found.begin(), found.end());
            ASSERT_EQ(found, brute) << "particle " << i;
        }
    }
}

// Particles of three kinds (fluid 0, wall 1, solid 2): each cell holds
// its fluid, then its walls, then its solids, split at kindEnd; the fluid
// and wall walks find exactly their kind's part of forEachCandidate's
// candidates; and the forward walks, with walls and solids walking only
// fluid, meet every pair within the support that has a fluid particle
// exactly once (the pair loop's rule: fluidPairRatesOp).
TEST(cellList, kindRangesAndWalks)
{
    for (const int nDim : {2, 3})
    {
        std::mt19937_64 gen(61 + nDim);
        cloud c = makeCloud("kinds", nDim, {0, 0, 0}, {0.4, 0.3, 0.2}, 0.05);
        addUniform(c, gen, nDim == 3 ? 4000 : 1500);
        // A dense block (a fine solid in coarse cells) and a pile.
        addClusters(c, gen, 2, 300, 0.01);
        const label n = label(c.x.size());
        // All kinds mixed for x < 0.15, walls and solids only beyond:
        // cells far from any fluid for the block flags below.
        std::vector<std::uint8_t> kind(n);
        std::uniform_int_distribution<int> pickKind(0, 2), pickDry(1, 2);
        for (label i = 0; i < n; ++i)
        {
            kind[i] = std::uint8_t(c.x[i].x < 0.15 ? pickKind(gen)
                                                   : pickDry(gen));
        }

        for (const int divisor : {1, 2, 3})
        {
            const cellGrid g = makeCellGrid(c.lower, c.upper, c.support,
                                            divisor, nDim);
            cellList l;
            buildCellList(openmpExec{}, g, c.x.data(), kind.data(), n, l);
            expectGpuRangesEqual(l);
            std::vector<point> x(l.nInside);
            std::vector<std::uint8_t> k(l.nInside);
            for (label s = 0; s < l.nInside; ++s)
            {
                x[s] = c.x[l.order[s]];
                k[s] = kind[l.order[s]];
            }
            ASSERT_EQ(label(l.kindEnd.size()), 2*g.nCells());
            for (label cell = 0; cell < g.nCells(); ++cell)
            {
                const label b = l.cellStart[cell], f = l.kindEnd[2*cell];
                const label w = l.kindEnd[2*cell + 1];
                const label e = l.cellStart[cell + 1];
                ASSERT_TRUE(b <= f && f <= w && w <= e) << "cell " << cell;
                for (label s = b; s < e; ++s)
                {
                    ASSERT_EQ(g.cellOf(x[s]), cell);
                    ASSERT_EQ(cellOfKey(l.keys[s]), cell);
                    ASSERT_EQ(k[s], s < f ? 0 : (s < w ? 1 : 2))
                        << "cell " << cell << " particle " << s;
                }
            }

            const scalar s2 = c.support*c.support;
            std::set<std::pair<label, label>> expected, met;
            for (label i = 0; i < l.nInside; ++i)
            {
                std::vector<label> all, fluid, walls;
                forEachCandidate(g, l.cellStart.data(), x[i], [&](label j)
                {
                    all.push_back(j);
                    if (j > i && magSqr(x[i] - x[j]) < s2
                     && (k[i] == 0 || k[j] == 0))
                    {
                        expected.insert({i, j});
                    }
                });
                std::vector<label> solids;
                forEachFluidCandidate(g, l.cellStart.data(), l.kindEnd.data(),
                    k.data(), x[i], [&](label j) { fluid.push_back(j); });
                forEachWallCandidate(g, l.cellStart.data(), l.kindEnd.data(),
                    k.data(), x[i], [&](label j) { walls.push_back(j); });
                forEachCandidateOfKind(g, l.cellStart.data(),
                    l.kindEnd.data(), k.data(), solidKind, x[i],
                    [&](label j) { solids.push_back(j); });
                std::vector<label> allFluid, allWalls, allSolids;
                for (const label j : all)
                {
                    if (k[j] == 0) allFluid.push_back(j);
                    if (k[j] == 1) allWalls.push_back(j);
                    if (k[j] == 2) allSolids.push_back(j);
                }
                for (auto* list : {&fluid, &walls, &solids, &allFluid,
                                   &allWalls, &allSolids})
                {
                    std::sort(list->begin(), list->end());
                }
                ASSERT_EQ(fluid, allFluid) << "particle " << i;
                ASSERT_EQ(walls, allWalls) << "particle " << i;
                ASSERT_EQ(solids, allSolids) << "particle " << i;

                auto meet = [&](label j)
                {
                    if (magSqr(x[i] - x[j]) >= s2) return;
                    if (k[i] != 0 && k[j] != 0) return;
                    const auto p = std::make_pair(std::min(i, j),
                                                  std::max(i, j));
                    ASSERT_TRUE(met.insert(p).second)
                        << "pair " << i << " " << j << " met twice";
                };
                const label cell = cellOfKey(l.keys[i]);
                if (k[i] == 0)
                {
                    forEachForwardCandidate(g, l.cellStart.data(), cell, i,
                                            meet);
                }
                else
                {
                    forEachForwardFluidCandidate(g, l.cellStart.data(),
                        l.kindEnd.data(), cell, [&](label j)
                    {
                        ASSERT_EQ(k[j], 0);
                        meet(j);
                    });
                }
            }
            EXPECT_GT(expected.size(), 1000u);
            EXPECT_TRUE(met == expected) << "met " << met.size()
                << " pairs, expected " << expected.size();

            // The blocks that hold fluid: flagged exactly, and every cell
            // with fluid in its stencil sees a flagged block around its
            // own (the walls' "fluid near" test, a superset).
            ASSERT_EQ(label(l.blockHasFluid.size()), g.nBlocks());
            std::vector<std::uint32_t> blockFluid(g.nBlocks(), 0);
            for (label cell = 0; cell < g.nCells(); ++cell)
            {
                if (l.kindEnd[2*cell] > l.cellStart[cell])
                {
                    blockFluid[g.blockOf(cell)] = 1;
                }
            }
            ASSERT_EQ(l.blockHasFluid, blockFluid);
            label nNear = 0, nFar = 0;
            for (label cell = 0; cell < g.nCells(); ++cell)
            {
                bool fluidInStencil = false;
                forEachCellOf(g, g.stencilOf(cell), [&](const label o)
                {
                    fluidInStencil = fluidInStencil
                        || l.kindEnd[2*o] > l.cellStart[o];
                });
                const bool seen =
                    anyBlockFlagAround(g, cell, l.blockHasFluid.data());
                if (fluidInStencil) ASSERT_TRUE(seen) << "cell " << cell;
                ++(seen ? nNear : nFar);
            }
            EXPECT_GT(nFar, 0) << "divisor " << divisor;
            EXPECT_GT(nNear, 0) << "divisor " << divisor;
        }
    }
}

// A pair a few ulp inside the support whose cell indices, rounded
// separately, would lie more than reach cells apart with cells of exactly
// support/divisor (found by a search over decimal domains and supports);
// makeCellGrid makes cells a relative 1e-9 larger to leave that margin.
// The walks around a point, both shapes (forEachRowAround): they meet every
// pair within the support after the particles moved by up to searchSkin
// since the sort, and they walk the share of the stencil's candidates
// that their shape gives, well under it for the ball. The host's
// forEachCandidate is the box walk.
TEST(cellList, walksAroundAPointFindMovedParticles)
{
    for (const int nDim : {2, 3})
    {
        std::mt19937_64 gen(71 + nDim);
        cloud c = makeCloud("moved", nDim, {0, 0, 0}, {0.4, 0.3, 0.2}, 0.05);
        addUniform(c, gen, nDim == 3 ? 6000 : 2000);
        const label n = label(c.x.size());
        for (const int divisor : {1, 2, 3})
        {
            const cellGrid g = makeCellGrid(c.lower, c.upper, c.support,
                                            divisor, nDim);
            cellList l;
            buildCellList(serialExec{}, g, c.x.data(), nullptr, n, l);
            ASSERT_EQ(l.nInside, n);
            // Each particle moved since the sort, by just under the skin.
            const scalar step = 0.999*searchSkin*c.support;
            std::vector<point> x(n);
            for (label s = 0; s < n; ++s)
            {
                const vec3 d{uniform(gen, -1, 1), uniform(gen, -1, 1),
                             nDim == 3 ? uniform(gen, -1, 1) : 0};
                x[s] = c.x[l.order[s]]
                     + (step/std::max(mag(d), scalar(1e-12)))*d;
            }
            const scalar s2 = c.support*c.support;

            // The candidates of particle i's walk of shape `shape`.
            auto walk = [&](const walkShape shape, const label i)
            {
                std::vector<label> all;
                auto rows = [&](const label row, const int x0, const int x1)
                {
                    for (label j = l.cellStart[row + x0];
                         j < l.cellStart[row + x1 + 1]; ++j)
                    {
                        all.push_back(j);
                    }
                };
                if (shape == walkShape::ball)
                {
                    forEachRowAround<walkShape::ball>(g, x[i], rows);
                }
                else
                {
                    forEachRowAround<walkShape::box>(g, x[i], rows);
                }
                return all;
            };

            for (const walkShape shape : {walkShape::ball, walkShape::box})
            {
                const bool ball = shape == walkShape::ball;
                SCOPED_TRACE(std::to_string(nDim) + "D, divisor "
                    + std::to_string(divisor) + (ball ? ", ball" : ", box"));
                label walked = 0, stencilWalked = 0;
                for (label i = 0; i < n; ++i)
                {
                    const std::vector<label> all = walk(shape, i);
                    walked += label(all.size());
                    std::vector<label> found, brute;
                    for (const label j : all)
                    {
                        if (magSqr(x[i] - x[j]) < s2) found.push_back(j);
                    }
                    for (label j = 0; j < n; ++j)
                    {
                        if (magSqr(x[i] - x[j]) < s2) brute.push_back(j);
                    }
                    std::sort(found.begin(), found.end());
                    std::vector<label> missed;
                    std::set_difference(brute.begin(), brute.end(),
                        found.begin(), found.end(), std::back_inserter(missed));
                    for (const label j : missed)
                    {
                        ADD_FAILURE() << "particle " << i << " at " << x[i].x
                            << " " << x[i].y << " " << x[i].z << " misses "
                            << j << " at " << x[j].x << " " << x[j].y << " "
                            << x[j].z << " of cell " << cellOfKey(l.keys[j])
                            << ", r/support " << mag(x[i] - x[j])/c.support;
                    }
                    ASSERT_EQ(found, brute) << "particle " << i;
                    // The whole stencil of its cell.
                    forEachCellOf(g, g.stencilOf(cellOfKey(l.keys[i])),
                                  [&](const label o)
                    {
                        stencilWalked += l.cellStart[o + 1] - l.cellStart[o];
                    });
                    if (!ball && i % 7 == 0)
                    {
                        std::vector<label> host;
                        forEachCandidate(g, l.cellStart.data(), x[i],
                                         [&](label j) { host.push_back(j); });
                        ASSERT_EQ(host, all) << "particle " << i;
                    }
                }
                // The walk's cells against the stencil's, averaged over
                // points uniform in a cell (computed apart) for divisors
                // 1, 2, 3: the ball of 1.05 supports 0.964, 0.931, 0.914
                // (2D) and 0.834, 0.752, 0.712 (3D); its box
                // ((2.1 d + 1)/(2 d + 1))^dim, 1.068, 1.082, 1.088 and
                // 1.103, 1.125, 1.134. The cloud's edges, which cut both,
                // move it a little.
                const double expected[2][2][3] =
                    {{{0.964, 0.931, 0.914}, {0.834, 0.752, 0.712}},
                     {{1.068, 1.082, 1.088}, {1.103, 1.125, 1.134}}};
                const double fraction = double(walked)/stencilWalked;
                std::cout << nDim << "D, divisor " << divisor
                          << (ball ? ", ball" : ", box") << ": walked "
                          << fraction << " of the stencil's candidates\n";
                EXPECT_NEAR(fraction, expected[!ball][nDim - 2][divisor - 1],
                            0.04);
            }
        }
    }
}

TEST(cellList, pairJustInsideSupportIsFound)
{
    // Exact cell membership of points on cell faces, in double digits.
    SPHVCPM_DOUBLE_ONLY();
    struct pairCase
    {
        scalar lower, support;
        int divisor;
        scalar xi, xj;
    };
    const pairCase cases[] =
    {
        {-0.52048505510999099, 0.011952130235981713, 1,
         -0.018495585198759056, -0.0065434549627773463},
        {-0.63523121831373608, 0.018945319364465453, 2,
         -0.08581695674423799, -0.10476227610870344},
    };
    for (const pairCase& pc : cases)
    {
        const std::vector<point> x{{pc.xi, 0.5, 0}, {pc.xj, 0.5, 0}};
        ASSERT_LT(magSqr(x[0] - x[1]), pc.support*pc.support);
        const cellGrid g = makeCellGrid({pc.lower, 0, 0},
            {pc.lower + 1, 1, 0}, pc.support, pc.divisor, 2);
        cellList list;
        buildCellList(serialExec{}, g, x.data(), nullptr, 2, list);
        ASSERT_EQ(list.nInside, 2);
        for (label i = 0; i < 2; ++i)
        {
            int found = 0;
            forEachCandidate(g, list.cellStart.data(), x[list.order[i]],
                             [&](const label j) { found += j != i; });
            EXPECT_EQ(found, 1)
                << "divisor " << pc.divisor << ": particle " << i
                << " in cell " << cellOfKey(list.keys[i]) << " does not see its"
                << " neighbour in cell " << cellOfKey(list.keys[1 - i]) << " at r/support"
                << " - 1 = " << mag(x[0] - x[1])/pc.support - 1;
        }
    }
}


TEST(cellList, emptyAndAllOutside)
{
    const cellGrid g = makeCellGrid({0, 0, 0}, {1, 1, 0}, 0.1, 1, 2);
    for (const int backend : {0, 1})
    {
        cellList list;
        if (backend == 0)
        {
            buildCellList(serialExec{}, g, nullptr, nullptr, 0, list);
        }
        else
        {
            buildCellList(openmpExec{}, g, nullptr, nullptr, 0, list);
        }
        EXPECT_EQ(list.nInside, 0);
        ASSERT_EQ(label(list.cellStart.size()), g.nCells() + 1);
        for (const label s : list.cellStart)
        {
            EXPECT_EQ(s, 0);
        }

        const std::vector<point> out{{-1, 0.5, 0}, {NaN, 0, 0}, {2, 2, 0}};
        if (backend == 0)
        {
            buildCellList(serialExec{}, g, out.data(), nullptr, 3, list);
        }
        else
        {
            buildCellList(openmpExec{}, g, out.data(), nullptr, 3, list);
        }
        EXPECT_EQ(list.nInside, 0);
        for (const label s : list.cellStart)
        {
            EXPECT_EQ(s, 0);
        }

        // One particle in the last cell, one outside.
        const std::vector<point> one{{2, 2, 0}, {1, 1, 0}};
        if (backend == 0)
        {
            buildCellList(serialExec{}, g, one.data(), nullptr, 2, list);
        }
        else
        {
            buildCellList(openmpExec{}, g, one.data(), nullptr, 2, list);
        }
        EXPECT_EQ(list.nInside, 1);
        EXPECT_EQ(list.order[0], 1);
        EXPECT_EQ(list.order[1], 0);
        const label last = g.cellOf({1, 1, 0});
        EXPECT_LT(last, g.nCells());
        for (label c = 0; c <= g.nCells(); ++c)
        {
            EXPECT_EQ(list.cellStart[c], c <= last ? 0 : 1) << "c = " << c;
        }
    }
}

TEST(cellList, cellOfOutsideAndNonFinite)
{
    // Exact cell membership of points on cell faces, in double digits.
    SPHVCPM_DOUBLE_ONLY();
    const cellGrid g = makeCellGrid({-1, -1, -1}, {1, 1, 1}, 0.3, 2, 3);
    EXPECT_EQ(g.cellOf({NaN, 0, 0}), g.nCells());
    EXPECT_EQ(g.cellOf({0, NaN, 0}), g.nCells());
    EXPECT_EQ(g.cellOf({0, 0, NaN}), g.nCells());
    EXPECT_EQ(g.cellOf({Inf, 0, 0}), g.nCells());
    EXPECT_EQ(g.cellOf({0, -Inf, 0}), g.nCells());
    EXPECT_EQ(g.cellOf({-1 - 1e-12, 0, 0}), g.nCells());
    EXPECT_EQ(g.cellOf({-1, -1, -1}), 0);
    EXPECT_EQ(g.cellOf({1, 1, 1}), g.nCells() - 1);
    // Large coordinates must not overflow into a valid cell index (near
    // the largest scalar of either precision).
    const scalar huge = scalar(sizeof(scalar) == 8 ? 1e300 : 1e38);
    EXPECT_EQ(g.cellOf({huge, 0, 0}), g.nCells());
    EXPECT_EQ(g.cellOf({-huge, 0, 0}), g.nCells());

    const cellGrid g2 = makeCellGrid({-1, -1, 0}, {1, 1, 0}, 0.3, 1, 2);
    EXPECT_EQ(g2.nz, 1);
    EXPECT_LT(g2.cellOf({0, 0, 0}), g2.nCells());
    EXPECT_EQ(g2.cellOf({0, 0, 0.2}), g2.nCells());   // off the 2D layer
}

TEST(cellList, makeCellGridErrors)
{
    // Exact cell membership of points on cell faces, in double digits.
    SPHVCPM_DOUBLE_ONLY();
    const point lo{0, 0, 0}, hi{1, 1, 1};
    EXPECT_THROW(makeCellGrid(lo, hi, 0, 1, 3), FatalError);
    EXPECT_THROW(makeCellGrid(lo, hi, -0.1, 1, 3), FatalError);
    EXPECT_THROW(makeCellGrid(lo, hi, NaN, 1, 3), FatalError);
    EXPECT_THROW(makeCellGrid(lo, hi, 0.1, 0, 3), FatalError);
    EXPECT_THROW(makeCellGrid(lo, hi, 0.1, -2, 2), FatalError);
    // Absurd cell counts: one direction, and the total.
    EXPECT_THROW(makeCellGrid(lo, {1e7, 1, 1}, 1e-3, 1, 3), FatalError);
    EXPECT_THROW(makeCellGrid(lo, hi, 1e-7, 1, 2), FatalError);
    EXPECT_THROW(makeCellGrid(lo, {100, 100, 100}, 0.01, 1, 3), FatalError);
    EXPECT_THROW(makeCellGrid(lo, {5000, 5000, 0}, 0.1, 1, 2), FatalError);
    // A particle thrown far away: numbers as %g, not 300 digits, and where
    // to look.
    const FatalError far = test::catchFatal([&]
    {
        makeCellGrid(lo, {1e300, 1, 1}, 0.1, 1, 3);
    });
    test::expectMessage(far, {"cells in one direction (length 1e+300 m",
                              "system/sphSchemes", "constant/motion"});
    EXPECT_LT(far.message().size(), 600u);
    // Bounds that are inverted or not finite.
    EXPECT_THROW(makeCellGrid(hi, lo, 0.1, 1, 3), FatalError);
    EXPECT_THROW(makeCellGrid(lo, {NaN, 1, 1}, 0.1, 1, 3), FatalError);
    EXPECT_THROW(makeCellGrid(lo, {Inf, 1, 1}, 0.1, 1, 3), FatalError);
    EXPECT_THROW(makeCellGrid(lo, {1, 1, NaN}, 0.1, 1, 3), FatalError);

    // Valid: 2D ignores the z bounds; a domain thinner than a cell.
    EXPECT_NO_THROW(makeCellGrid(lo, {1, 1, NaN}, 0.1, 1, 2));
    const cellGrid thin = makeCellGrid(lo, {1, 0, 0}, 0.1, 2, 3);
    EXPECT_EQ(thin.ny, 1);
    EXPECT_EQ(thin.nz, 1);
    EXPECT_EQ(thin.nx, 20);    // floor(1/(0.05 (1 + 1e-9))) + 1
}

// The divisor a case that gives none gets: cells of h on the CPU, of 2h/3
// on the GPU unless they would far outnumber the particles, and of 2h
// where cells of h would not fit the 32-bit cell keys; makeCellGrid then
// accepts it.
TEST(cellList, defaultCellDivisor)
{
    const point lo{0, 0, 0};
    const scalar support = 0.003;
    // A 0.3 m cube: 300^3 = 2.7e7 cells of 2h/3 = 1 mm.
    const point cube{0.3, 0.3, 0.3};
    EXPECT_EQ(defaultCellDivisor(lo, cube, support, 3, 2000000, true), 3);
    EXPECT_EQ(defaultCellDivisor(lo, cube, support, 3, 2000000, false), 2);
    // Few particles in it: cells of 2h/3 would be 16 times as many.
    EXPECT_EQ(defaultCellDivisor(lo, cube, support, 3, 1000000, true), 2);
    // 1.6 m: 1067^3 cells of h = 1.5 mm pass 2^30; 534^3 of 2h do not.
    const point large{1.6, 1.6, 1.6};
    for (const bool gpu : {true, false})
    {
        const int divisor =
            defaultCellDivisor(lo, large, support, 3, 500000000, gpu);
        EXPECT_EQ(divisor, 1);
        EXPECT_THROW(makeCellGrid(lo, large, support, 2, 3), FatalError);
        const cellGrid g = makeCellGrid(lo, large, support, divisor, 3);
        EXPECT_EQ(g.nx, 534);
    }
    // 2D counts two directions only.
    EXPECT_EQ(defaultCellDivisor(lo, {1.5, 1.5, 1e9}, support, 2, 1000000,
                                 true), 3);
}
