/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Filling on STL surfaces: the nearest-point search (against brute force),
// seed filling of open and closed containers (exact counts, leaks and
// seeds outside as errors) and wall layers on either side of open and
// closed surfaces (against exact distances to a box); the same in 2D on
// the cut of the surface by z = 0.

#include "lattice.H"
#include "../testPrecision.H"
#include "particleGenerator.H"
#include "polygonShape.H"
#include "seedFillShape.H"
#include "segmentDistance.H"
#include "surfaceLayersShape.H"
#include "testGeometryTools.H"
#include "testStlSurfaces.H"
#include "triSurfaceDistance.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

using namespace sphvcpm;
using namespace sphvcpm::test;
namespace fs = std::filesystem;

namespace
{

const scalar pi = M_PI;

// The unit cube without its top face (z = 1): an open tank, normals out.
soup openTank(const vec3& lo = {0, 0, 0}, const vec3& hi = {1, 1, 1})
{
    soup s = cube(lo, hi);
    s.erase(s.begin() + 6, s.begin() + 12);
    return s;
}

// A shape of text in a scratch case whose constant/geometry holds files.
struct surfaceCase
{
    scratchDir dir{"surfaceFill"};

    void add(const std::string& file, const soup& s) const
    {
        writeFile(dir.path()/"constant"/"geometry"/file, asciiSTL(s));
    }

    std::string dictFile() const
    {
        return (dir.path()/"system"/"generateParticlesDict").string();
    }

    std::unique_ptr<shape> New(const std::string& text, scalar dp,
                               const vec3& origin = {0, 0, 0}) const
    {
        const dictionary d = dictionary::fromString("s {" + text + "}",
                                                    dictFile());
        return shape::New("s", d.subDict("s"), 3, dp, {}, dir.path(),
                          origin);
    }

    std::vector<vec3> fill(const std::string& text, scalar dp,
                           const vec3& origin = {0, 0, 0}) const
    {
        region r(3);
        r.add(New(text, dp, origin));
        return lattice(origin, dp, 3).fill(r);
    }
};

// Distance from p to the surface of the box [lo, hi] and whether p is
// inside it.
scalar boxDistance(const vec3& p, const vec3& lo, const vec3& hi, bool& in)
{
    vec3 out{0, 0, 0};
    scalar depth = 1e300;
    in = true;
    for (int d = 0; d < 3; ++d)
    {
        out[d] = std::max({lo[d] - p[d], p[d] - hi[d], scalar(0)});
        in = in && out[d] == 0;
        depth = std::min({depth, p[d] - lo[d], hi[d] - p[d]});
    }
    return in ? depth : mag(out);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Nearest point * * * * * * * * * * * * * * //

TEST(surfaceFill, nearestPointMatchesBruteForce)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    const triSurface surf(icosphere({0.3, 0.2, 0.1}, 0.5, 3), 1e-9);
    const scalar radius = 0.2;
    const triSurfaceDistance near(surf, radius);

    std::mt19937_64 gen(5);
    std::uniform_real_distribution<scalar> u(-0.5, 1.0);
    int nFound = 0;
    for (int i = 0; i < 3000; ++i)
    {
        const vec3 p{u(gen), u(gen) - 0.1, u(gen) - 0.2};
        scalar best = 1e300;
        for (const triSurface::face& f : surf.faces())
        {
            // Brute force: the nearest of the plane projection (when
            // inside) and dense samples of the edges.
            const vec3& a = surf.points()[f[0]];
            const vec3& b = surf.points()[f[1]];
            const vec3& c = surf.points()[f[2]];
            const vec3 q = triSurfaceDistance::nearestOnTriangle(p, a, b, c);
            best = std::min(best, mag(p - q));
            for (int k = 0; k <= 50; ++k)
            {
                const scalar t = k/50.0;
                best = std::min({best, mag(p - (a + t*(b - a))),
                                 mag(p - (b + t*(c - b))),
                                 mag(p - (c + t*(a - c)))});
            }
        }
        const triSurfaceDistance::nearest n = near.find(p);
        if (best <= radius*(1 - 1e-9))
        {
            ASSERT_GE(n.face, 0) << i;
            EXPECT_NEAR(n.distance, best, 1e-12) << i;
            // Outward normals: the side is where p is relative to the
            // sphere polyhedron.
            ++nFound;
        }
        else if (best > radius*(1 + 1e-9))
        {
            EXPECT_EQ(n.face, -1) << i;
        }
    }
    EXPECT_GT(nFound, 300);
}


TEST(surfaceFill, nearestPointOfLargeTiltedTriangles)
{
    // Two large triangles whose boxes are mostly empty (the grid skips the
    // cells they do not come near) against brute force.
    soup s;
    addTriangle(s, {0, 0, 0}, {1, 0.1, 1}, {0.2, 1, 0.9});
    addTriangle(s, {1, 1, 0}, {0, 0.9, 1}, {0.9, 0, 0.8});
    const triSurface surf(s, 0);
    const triSurfaceDistance near(surf, 0.02);
    std::mt19937_64 gen(3);
    std::uniform_real_distribution<scalar> u(-0.05, 1.05);
    int nFound = 0;
    for (int i = 0; i < 20000; ++i)
    {
        const vec3 p{u(gen), u(gen), u(gen)};
        scalar best = 1e300;
        for (int t = 0; t < 2; ++t)
        {
            best = std::min(best, mag(p - triSurfaceDistance::
                nearestOnTriangle(p, s[3*t], s[3*t + 1], s[3*t + 2])));
        }
        const triSurfaceDistance::nearest n = near.find(p);
        ASSERT_EQ(n.face >= 0, best <= 0.02) << i;
        if (n.face >= 0)
        {
            EXPECT_NEAR(n.distance, best, 1e-15);
            ++nFound;
        }
    }
    EXPECT_GT(nFound, 500);
}


TEST(surfaceFill, nearestOnTriangleRegions)
{
    const vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
    const auto near = [&](const vec3& p)
    {
        return triSurfaceDistance::nearestOnTriangle(p, a, b, c);
    };
    EXPECT_NEAR(mag(near({0.2, 0.2, 3}) - vec3{0.2, 0.2, 0}), 0, 1e-15);
    EXPECT_NEAR(mag(near({-1, -1, 1}) - a), 0, 1e-15);
    EXPECT_NEAR(mag(near({2, -1, 0}) - b), 0, 1e-15);
    EXPECT_NEAR(mag(near({1, 1, 0}) - vec3{0.5, 0.5, 0}), 0, 1e-15);
    EXPECT_NEAR(mag(near({0.5, -2, 1}) - vec3{0.5, 0, 0}), 0, 1e-15);
}


TEST(surfaceFill, sideOfAnOpenSurfaceFollowsTheNormals)
{
    const triSurface tank(openTank(), 1e-9);
    ASSERT_FALSE(tank.closed());
    const triSurfaceDistance near(tank, 0.3);
    // Inside the tank: against the outward normals; outside: with them,
    // also at the convex bottom edge and corner.
    EXPECT_EQ(near.find({0.1, 0.5, 0.5}).side, -1);
    EXPECT_EQ(near.find({-0.1, 0.5, 0.5}).side, 1);
    EXPECT_EQ(near.find({-0.1, 0.5, -0.1}).side, 1);
    EXPECT_EQ(near.find({-0.1, -0.1, -0.1}).side, 1);
    EXPECT_EQ(near.find({0.05, 0.05, 0.05}).side, -1);
    EXPECT_EQ(near.find({0.5, 0.5, 0.5}).face, -1);
}


// * * * * * * * * * * * * * * * Seed filling * * * * * * * * * * * * * * //

TEST(surfaceFill, seedFillsAnOpenTankUpToTheLevel)
{
    const surfaceCase c;
    c.add("tank.stl", openTank());
    // 20 nodes across; the nodes dp/2 off the walls stay: exactly
    // 20 x 20 x (0.3/0.05) nodes.
    const std::vector<vec3> nodes = c.fill("shape seedFill; file"
        " \"constant/geometry/tank.stl\"; seed (0.5 0.5 0.1); level 0.3;",
        0.05);
    EXPECT_EQ(nodes.size(), 20u*20u*6u);
    for (const vec3& p : nodes)
    {
        ASSERT_GT(p.z, 0);
        ASSERT_LT(p.z, 0.3);
    }

    // The same with a tilted "up" and a lattice shifted by a quarter dp:
    // within the tank and below the tilted plane.
    const std::vector<vec3> tilted = c.fill("shape seedFill; file"
        " \"constant/geometry/tank.stl\"; seed (0.5 0.5 0.1); level 0.3;"
        " up (0.2 0 1);", 0.05, {0.0125, 0.0125, 0.0125});
    const vec3 up = vec3{0.2, 0, 1}/mag(vec3{0.2, 0, 1});
    std::size_t expected = 0;
    for (int k = -1; k < 22; ++k)
    for (int j = -1; j < 22; ++j)
    for (int i = -1; i < 22; ++i)
    {
        const vec3 p{0.0125 + (i + 0.5)*0.05, 0.0125 + (j + 0.5)*0.05,
                     0.0125 + (k + 0.5)*0.05};
        bool in;
        const scalar d = boxDistance(p, {0, 0, 0}, {1, 1, 1}, in);
        expected += in && d >= 0.025 && dot(p, up) < 0.3;
    }
    EXPECT_EQ(tilted.size(), expected);
}


TEST(surfaceFill, seedFillsAClosedSphereAndOneOfTwoTanks)
{
    const surfaceCase c;
    c.add("ball.stl", icosphere({0.5, 0.5, 0.5}, 0.4, 4));
    const scalar dp = 0.02;
    const std::vector<vec3> ball = c.fill("shape seedFill; file"
        " \"constant/geometry/ball.stl\"; seed (0.5 0.5 0.5);", dp);
    // Closed: no level needed; the nodes at least dp/2 inside: a sphere of
    // radius r - dp/2.
    const scalar r = 0.4 - dp/2;
    const scalar error = ball.size()*dp*dp*dp/(4.0/3.0*pi*r*r*r) - 1;
    std::cout << "    seedFill sphere, 40 dp across: volume error "
              << 100*error << " % against r - dp/2\n";
    EXPECT_LT(std::abs(error), 0.01);

    // Two open tanks side by side: the seed fills its own only.
    soup two = openTank({0, 0, 0}, {1, 1, 1});
    const soup other = openTank({1.5, 0, 0}, {2.5, 1, 1});
    two.insert(two.end(), other.begin(), other.end());
    c.add("two.stl", two);
    const std::vector<vec3> one = c.fill("shape seedFill; file"
        " \"constant/geometry/two.stl\"; seed (2 0.5 0.1); level 0.5;", 0.1);
    EXPECT_EQ(one.size(), 10u*10u*5u);
    for (const vec3& p : one)
    {
        ASSERT_GT(p.x, 1.5);
    }
}


TEST(surfaceFill, seedOutsideOrALeakIsAnError)
{
    const surfaceCase c;
    c.add("tank.stl", openTank());
    soup leaky = openTank();
    leaky.erase(leaky.begin(), leaky.begin() + 3);   // a hole in the floor
    c.add("leaky.stl", leaky);

    const std::string tank = "shape seedFill; file"
        " \"constant/geometry/tank.stl\";";
    expectError(catchFatal([&]
    {
        c.New(tank + "\n seed (2 0.5 0.1); level 0.3;", 0.05);
    }), c.dictFile(), 2, {"Keyword 'seed'", "outside the bounding box",
                          "tank.stl"});

    // No level: an open tank spills.
    expectError(catchFatal([&]
    {
        c.New(tank + "\n seed (0.5 0.5 0.1);", 0.05);
    }), c.dictFile(), 2, {"Keyword 'seed'", "not inside a container",
                          "give a level"});

    // Level above the rim: spills too.
    expectError(catchFatal([&]
    {
        c.New(tank + "\n seed (0.5 0.5 0.1); level 1.5;", 0.05);
    }), c.dictFile(), 2, {"Keyword 'seed'", "leaks below level 1.5"});

    expectError(catchFatal([&]
    {
        c.New("shape seedFill; file \"constant/geometry/leaky.stl\";\n"
              "seed (0.5 0.5 0.1); level 0.3;", 0.05);
    }), c.dictFile(), 2, {"Keyword 'seed'", "leaky.stl"});

    expectError(catchFatal([&]
    {
        c.New(tank + "\n seed (0.5 0.5 0.5); level 0.3;", 0.05);
    }), c.dictFile(), 2, {"Keyword 'seed'", "is not below level 0.3"});

    expectError(catchFatal([&]
    {
        // The seed's node is 0.002 off the wall.
        c.New(tank + "\n seed (0.001 0.5 0.1); level 0.3;", 0.01,
              {-0.003, 0, 0});
    }), c.dictFile(), 2, {"Keyword 'seed'", "closer than dp/2"});

    expectError(catchFatal([&]
    {
        c.New("shape seedFill; file \"constant/geometry/none.stl\";"
              " seed (0 0 0);", 0.05);
    }), c.dictFile(), 1, {"Keyword 'file'", "none.stl does not exist"});
    expectError(catchFatal([&]
    {
        c.New("shape seedFill; file \"constant\"; seed (0 0 0);", 0.05);
    }), c.dictFile(), 1, {"Keyword 'file'", "is a directory, not a file"});

    expectError(catchFatal([&]
    {
        c.New(tank + " level 0.3;", 0.05);
    }), c.dictFile(), -1, {"seed"});
}


// * * * * * * * * * * * * * * * Wall layers * * * * * * * * * * * * * * * //

TEST(surfaceFill, layersOnAClosedBoxMatchExactDistances)
{
    const surfaceCase c;
    c.add("box.stl", flipped(cube({0, 0, 0}, {1, 1, 1})));
    const scalar dp = 0.1;
    for (const std::string side : {"outside", "inside", "both"})
    {
        const std::vector<vec3> nodes = c.fill("shape surfaceLayers; file"
            " \"constant/geometry/box.stl\"; layers 3; side " + side + ";",
            dp);
        std::size_t expected = 0;
        for (int k = -5; k < 15; ++k)
        for (int j = -5; j < 15; ++j)
        for (int i = -5; i < 15; ++i)
        {
            const vec3 p{(i + 0.5)*dp, (j + 0.5)*dp, (k + 0.5)*dp};
            bool in;
            const scalar d = boxDistance(p, {0, 0, 0}, {1, 1, 1}, in);
            const bool sideOk = side == "both" || (side == "inside") == in;
            expected += sideOk && d > 0 && d <= 3*dp*(1 + 1e-9);
        }
        EXPECT_EQ(nodes.size(), expected) << side;
    }
    // Inside: the 10^3 cube minus its 4^3 core.
    EXPECT_EQ(c.fill("shape surfaceLayers; file \"constant/geometry/box.stl\";"
                     " layers 3; side inside;", dp).size(), 1000u - 64u);
}


TEST(surfaceFill, layersOnAnOpenTankFollowTheNormals)
{
    const surfaceCase c;
    c.add("tank.stl", openTank());
    const scalar dp = 0.1;
    for (const std::string side : {"outside", "inside"})
    {
        const std::vector<vec3> nodes = c.fill("shape surfaceLayers; file"
            " \"constant/geometry/tank.stl\"; layers 2; side " + side + ";",
            dp);
        // Below the rim: exactly the nodes of that side within 2 dp of
        // the walls and floor; above it: within 2 dp of the rim.
        std::size_t expectedBelow = 0, below = 0;
        for (int k = -5; k < 10; ++k)
        for (int j = -5; j < 15; ++j)
        for (int i = -5; i < 15; ++i)
        {
            const vec3 p{(i + 0.5)*dp, (j + 0.5)*dp, (k + 0.5)*dp};
            bool in;
            const scalar d = boxDistance(p, {0, 0, 0}, {1, 1, 2}, in);
            expectedBelow += (side == "inside") == in && d <= 2*dp*1.000001;
        }
        for (const vec3& p : nodes)
        {
            if (p.z < 1)
            {
                ++below;
            }
            else
            {
                bool in;
                EXPECT_LE(boxDistance(p, {0, 0, 0}, {1, 1, 1}, in),
                          2*dp*1.000001);
                EXPECT_EQ(p.x > 0 && p.x < 1 && p.y > 0 && p.y < 1,
                          side == "inside") << p.x << ' ' << p.y;
            }
        }
        EXPECT_EQ(below, expectedBelow) << side;
    }

    expectError(catchFatal([&]
    {
        c.New("shape surfaceLayers; file \"constant/geometry/tank.stl\";\n"
              "layers 0; side inside;", dp);
    }), c.dictFile(), 2, {"Keyword 'layers'", "at least 1"});
    expectError(catchFatal([&]
    {
        c.New("shape surfaceLayers; file \"constant/geometry/tank.stl\";\n"
              "layers 2; side up;", dp);
    }), c.dictFile(), 2, {"'side'", "unknown value 'up'"});
}


TEST(surfaceFill, generatorFillsATankFromSTLWithWallsAndWater)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    const surfaceCase c;
    c.add("tank.stl", openTank());
    writeText(c.dir.path()/"system"/"generateParticlesDict",
        "nDimensions 3;\ndp 0.05;\nbodies\n{\n"
        "    walls { type wall; rho 1000; shapes { t { shape surfaceLayers;"
        " file \"constant/geometry/tank.stl\"; layers 3; side outside; } } }\n"
        "    water { type fluid; rho 1000; shapes { w { shape seedFill;"
        " file \"constant/geometry/tank.stl\"; seed (0.5 0.5 0.1);"
        " level 0.4; } } }\n}\n");
    particleGenerator gen(c.dir.path(), "system/generateParticlesDict");
    gen.generate();
    ASSERT_EQ(gen.summaries().size(), 2u);
    // The water is dp from the first wall layer: nothing dropped.
    EXPECT_EQ(gen.summaries()[1].name, "water");
    EXPECT_EQ(gen.summaries()[1].nParticles, 20*20*8);
    EXPECT_EQ(gen.summaries()[1].nDropped, 0);
    const scalar error = gen.summaries()[1].volume/0.4 - 1;
    std::cout << "    seedFill open tank, level 0.4: volume error "
              << 100*error << " %\n";
    EXPECT_NEAR(error, 0, 1e-12);
}


// * * * * * * * * * * * * * * * * * 2D * * * * * * * * * * * * * * * * * //

namespace
{

std::size_t count2D(const surfaceCase& c, const std::string& text, scalar dp,
                    scalar* area = nullptr)
{
    const dictionary d = dictionary::fromString("s {" + text + "}",
                                                c.dictFile());
    std::unique_ptr<shape> s =
        shape::New("s", d.subDict("s"), 2, dp, {}, c.dir.path());
    if (area)
    {
        *area = s->volume();
    }
    region r(2);
    r.add(std::move(s));
    return lattice({0, 0, 0}, dp, 2).fill(r).size();
}

} // End anonymous namespace


TEST(surfaceFill, polygonsFillByTheBoxRule)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    const surfaceCase c;
    scalar area = 0;
    // Both orientations, the boxes' rule on edges: exactly 10 x 10.
    EXPECT_EQ(count2D(c, "shape polygon; points ((0 0) (1 0) (1 1) (0 1));",
                      0.1, &area), 100u);
    EXPECT_DOUBLE_EQ(area, 1);
    EXPECT_EQ(count2D(c, "shape polygon; points ((0 0) (0 1) (1 1) (1 0));",
                      0.1), 100u);
    // Non-convex: an L of three unit squares.
    EXPECT_EQ(count2D(c, "shape polygon; points ((0 0) (2 0) (2 1) (1 1)"
                      " (1 2) (0 2));", 0.1, &area), 300u);
    EXPECT_DOUBLE_EQ(area, 3);

    // A 200-gon of radius 0.5 at 50 dp across.
    std::ostringstream pts;
    pts.precision(17);
    for (int i = 0; i < 200; ++i)
    {
        pts << " (" << 0.5*std::cos(2*pi*i/200) << ' '
            << 0.5*std::sin(2*pi*i/200) << ')';
    }
    const std::size_t n = count2D(c, "shape polygon; points (" + pts.str()
                                  + ");", 0.02, &area);
    EXPECT_NEAR(area, 0.5*200*0.25*std::sin(2*pi/200), 1e-12);
    const scalar error = n*0.02*0.02/area - 1;
    std::cout << "    polygon, circle 50 dp across: area error "
              << 100*error << " %\n";
    EXPECT_LT(std::abs(error), 0.01);

    expectError(catchFatal([&]
    {
        count2D(c, "shape polygon;\npoints ((0 0) (1 1));", 0.1);
    }), c.dictFile(), 2, {"Keyword 'points'", "at least 3"});
    expectError(catchFatal([&]
    {
        count2D(c, "shape polygon;\npoints ((0 0) (1 1) (2 2));", 0.1);
    }), c.dictFile(), 2, {"Keyword 'points'", "no area"});
    expectError(catchFatal([&]
    {
        c.New("shape polygon;\npoints ((0 0) (1 0) (1 1));", 0.1);
    }), c.dictFile(), 1, {"Shape 's'", "needs nDimensions 2"});
}


TEST(surfaceFill, stlCutByThePlaneZ0)
{
    const surfaceCase c;
    // A box across the plane: exactly the unit square's nodes.
    c.add("box.stl", cube({0, 0, -0.5}, {1, 1, 0.5}));
    scalar area = 0;
    EXPECT_EQ(count2D(c, "shape stl; file \"constant/geometry/box.stl\";",
                      0.1, &area), 100u);
    EXPECT_NEAR(area, 1, 1e-14);

    // A sphere (flipped triangles: orientation does not matter) and a
    // torus about z (an annulus: the even-odd rule makes the hole).
    c.add("ball.stl", flipped(icosphere({0.5, 0.5, 0}, 0.5, 4)));
    const std::size_t nBall = count2D(c, "shape stl; file"
        " \"constant/geometry/ball.stl\";", 0.02, &area);
    EXPECT_NEAR(area/(pi*0.25), 1, 0.01);
    const scalar ballError = nBall*0.02*0.02/area - 1;

    c.add("torus.stl", torus({0, 0, 0}, 0.35, 0.15, 96, 32));
    const std::size_t nTorus = count2D(c, "shape stl; file"
        " \"constant/geometry/torus.stl\"; rotate { axis (0 0 1); angle 10; }",
        0.006, &area);
    EXPECT_NEAR(area/(pi*(0.5*0.5 - 0.2*0.2)), 1, 0.01);
    const scalar torusError = nTorus*0.006*0.006/area - 1;
    std::cout << "    stl cut by z = 0, 50 dp across: area error circle "
              << 100*ballError << " %, annulus " << 100*torusError << " %\n";
    EXPECT_LT(std::abs(ballError), 0.01);
    EXPECT_LT(std::abs(torusError), 0.01);

    // An open surface, and one the plane misses.
    c.add("tank.stl", openTank({0, 0, -0.5}, {1, 1, 0.5}));
    const std::string tank = (c.dir.path()/"constant"/"geometry"
                              /"tank.stl").string();
    expectError(catchFatal([&]
    {
        count2D(c, "shape stl; file \"constant/geometry/tank.stl\";", 0.1);
    }), tank, 0, {"Shape 's'", "not closed", "checkClosed"});
    expectError(catchFatal([&]
    {
        count2D(c, "shape stl; file \"constant/geometry/box.stl\";"
                " translate (0 0 2);", 0.1);
    }), (c.dir.path()/"constant"/"geometry"/"box.stl").string(), 0,
        {"z = 0 does not cut", "translate"});
}


// * * * * * * * * * * * * seedFill and surfaceLayers in 2D * * * * * * * * //

namespace
{

// The box [lo, hi] across z = 0 without its face y = hi: cut by z = 0, an
// open 2D tank (a U), normals out.
soup openTank2D(const vec3& lo = {0, 0, -0.5}, const vec3& hi = {1, 1, 0.5})
{
    soup s = cube(lo, hi);
    s.erase(s.begin() + 18, s.begin() + 24);
    return s;
}

// Nodes of a 2D body whose shape is text, on the lattice of dp at origin.
std::vector<vec3> fill2D(const surfaceCase& c, const std::string& text,
                         scalar dp, const vec3& origin = {0, 0, 0})
{
    const dictionary d = dictionary::fromString("s {" + text + "}",
                                                c.dictFile());
    region r(2);
    r.add(shape::New("s", d.subDict("s"), 2, dp, {}, c.dir.path(), origin));
    return lattice(origin, dp, 2).fill(r);
}

// Distance from p to the polyline through pts (exact).
scalar polylineDistance(const vec3& p, const std::vector<vec3>& pts)
{
    scalar best = 1e300;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i)
    {
        best = std::min(best, mag(p - segmentDistance::nearestOnSegment
            (p, pts[i], pts[i + 1])));
    }
    return best;
}

} // End anonymous namespace


TEST(surfaceFill, segmentDistanceMatchesBruteForce)
{
    // The cut of a torus: two closed polygons, and points all around.
    const triSurface surf(torus({0, 0, 0}, 0.35, 0.15, 48, 16), 1e-9);
    const std::vector<planarRegion::segment> segs =
        stlSliceShape::cut(surf.points(), surf.faces());
    ASSERT_GT(segs.size(), 90u);
    const scalar radius = 0.05;
    const segmentDistance near(segs, radius);
    std::mt19937_64 gen(7);
    std::uniform_real_distribution<scalar> u(-0.6, 0.6);
    int nFound = 0;
    for (int i = 0; i < 5000; ++i)
    {
        const vec3 p{u(gen), u(gen), 0};
        scalar best = 1e300;
        int side = 0;
        for (const planarRegion::segment& s : segs)
        {
            const vec3 a{s.x0, s.y0, 0}, b{s.x1, s.y1, 0};
            const vec3 q = segmentDistance::nearestOnSegment(p, a, b);
            if (mag(p - q) < best)
            {
                best = mag(p - q);
                // Outward normals: the side is out of the annulus.
                const scalar r = mag(p);
                side = (r > 0.5 || r < 0.2) ? 1 : -1;
            }
        }
        const segmentDistance::nearest n = near.find(p);
        if (best <= radius*(1 - 1e-9))
        {
            ASSERT_GE(n.segment, 0) << i;
            EXPECT_NEAR(n.distance, best, 1e-14) << i;
            // Inside the annulus is against the (outward) normals.
            const scalar r = mag(p);
            if (std::abs(r - 0.5) > 0.01 && std::abs(r - 0.2) > 0.01)
            {
                EXPECT_EQ(n.side, side) << i;
            }
            ++nFound;
        }
        else if (best > radius*(1 + 1e-9))
        {
            EXPECT_EQ(n.segment, -1) << i;
        }
    }
    EXPECT_GT(nFound, 500);
}


TEST(surfaceFill, seedFills2DOpenTankUpToTheLevel)
{
    const surfaceCase c;
    c.add("tank.stl", openTank2D());
    // 20 nodes across, the ones dp/2 off the walls stay: 20 x 6, with the
    // seed given as (x y) or (x y 0); "up" is +y in 2D.
    const std::string tank = "shape seedFill; file"
        " \"constant/geometry/tank.stl\"; level 0.3;";
    const std::vector<vec3> nodes = fill2D(c, tank + " seed (0.5 0.1);",
                                           0.05);
    EXPECT_EQ(nodes.size(), 20u*6u);
    for (const vec3& p : nodes)
    {
        ASSERT_GT(p.y, 0);
        ASSERT_LT(p.y, 0.3);
        ASSERT_EQ(p.z, 0);
    }
    EXPECT_EQ(fill2D(c, tank + " seed (0.5 0.1 0);", 0.05).size(), 120u);

    // A tilted "up" and a lattice shifted by a quarter dp: the nodes in the
    // tank, at least dp/2 from its walls and below the tilted line.
    const std::vector<vec3> tilted = fill2D(c, tank + " seed (0.5 0.1);"
        " up (0.2 1);", 0.05, {0.0125, 0.0125, 0});
    const vec3 up = vec3{0.2, 1, 0}/mag(vec3{0.2, 1, 0});
    std::size_t expected = 0;
    for (int j = -1; j < 22; ++j)
    for (int i = -1; i < 22; ++i)
    {
        const vec3 p{0.0125 + (i + 0.5)*0.05, 0.0125 + (j + 0.5)*0.05, 0};
        const bool in = p.x > 0 && p.x < 1 && p.y > 0 && p.y < 1;
        const scalar d = std::min({p.x, 1 - p.x, p.y});
        expected += in && d >= 0.025 && dot(p, up) < 0.3;
    }
    EXPECT_EQ(tilted.size(), expected);
    EXPECT_GT(expected, 50u);

    // A closed cut needs no level: the square's 10 x 10, also with
    // flipped triangles.
    c.add("box.stl", flipped(cube({0, 0, -0.5}, {1, 1, 0.5})));
    EXPECT_EQ(fill2D(c, "shape seedFill; file \"constant/geometry/box.stl\";"
                     " seed (0.5 0.5);", 0.1).size(), 100u);
}


TEST(surfaceFill, seedOutsideOrALeakIsAnErrorIn2D)
{
    const surfaceCase c;
    c.add("tank.stl", openTank2D());
    const std::string tank = "shape seedFill; file"
        " \"constant/geometry/tank.stl\";";
    const auto fill = [&](const std::string& text, scalar dp = 0.05,
                          const vec3& origin = {0, 0, 0})
    {
        fill2D(c, tank + "\n" + text, dp, origin);
    };
    expectError(catchFatal([&] { fill("seed (2 0.5); level 0.3;"); }),
        c.dictFile(), 2, {"Keyword 'seed'", "outside the bounding box",
                          "cut of the surface by z = 0", "tank.stl"});
    expectError(catchFatal([&] { fill("seed (0.5 0.1);"); }),
        c.dictFile(), 2, {"Keyword 'seed'", "not inside a container",
                          "give a level"});
    expectError(catchFatal([&] { fill("seed (0.5 0.1); level 1.5;"); }),
        c.dictFile(), 2, {"Keyword 'seed'", "leaks below level 1.5"});
    expectError(catchFatal([&] { fill("seed (0.5 0.5); level 0.3;"); }),
        c.dictFile(), 2, {"Keyword 'seed'", "is not below level 0.3"});
    // The seed's node is 0.002 off the floor.
    expectError(catchFatal([&]
    {
        fill("seed (0.5 0.001); level 0.3;", 0.01, {0, -0.003, 0});
    }), c.dictFile(), 2, {"Keyword 'seed'", "closer than dp/2"});
    expectError(catchFatal([&] { fill("seed (0.5 0.1 0.2); level 0.3;"); }),
        c.dictFile(), 2, {"Keyword 'seed'", "give (x y)"});
    expectError(catchFatal([&] { fill("seed (0.5 0.1); level 0.3;"
                                      " up (0 0 1);"); }),
        c.dictFile(), 2, {"Keyword 'up'", "give (x y)"});

    // A tank the plane misses.
    expectError(catchFatal([&]
    {
        fill("seed (0.5 0.1); level 0.3; translate (0 0 2);");
    }), (c.dir.path()/"constant"/"geometry"/"tank.stl").string(), 0,
        {"Shape 's'", "z = 0 does not cut", "translate"});
}


TEST(surfaceFill, layersOn2DOpenTankMatchExactDistances)
{
    const surfaceCase c;
    c.add("tank.stl", openTank2D());
    const scalar dp = 0.1;
    // The U of the cut, and its outside: where the normals point.
    const std::vector<vec3> u{{0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    for (const std::string side : {"outside", "inside"})
    {
        const std::vector<vec3> nodes = fill2D(c, "shape surfaceLayers; file"
            " \"constant/geometry/tank.stl\"; layers 2; side " + side + ";",
            dp);
        // Within 2 dp of the U on that side; past the rim the layers round
        // its ends on that side (a quarter circle each).
        std::size_t expected = 0, above = 0;
        for (int j = -5; j < 15; ++j)
        for (int i = -5; i < 15; ++i)
        {
            const vec3 p{(i + 0.5)*dp, (j + 0.5)*dp, 0};
            const bool out = p.x < 0 || p.x > 1 || p.y < 0;
            const scalar d = polylineDistance(p, u);
            const bool here = (side == "outside") == out
                && d <= 2*dp*(1 + 1e-9);
            expected += here;
            above += here && p.y > 1;
        }
        EXPECT_EQ(nodes.size(), expected) << side;
        EXPECT_GT(above, 0u) << side;
        for (const vec3& p : nodes)
        {
            ASSERT_EQ(p.z, 0);
        }
    }
    // Inside, below the rim: 2 rows along the floor and 2 columns up the
    // walls; past the rim, the quarter circles of radius 2 dp hold 3 nodes
    // each ((0.05, 1.05), (0.15, 1.05), (0.05, 1.15)).
    EXPECT_EQ(fill2D(c, "shape surfaceLayers; file"
        " \"constant/geometry/tank.stl\"; layers 2; side inside;", dp).size(),
        10u*2u + 2u*2u*8u + 2u*3u);
}


TEST(surfaceFill, layersOn2DClosedCutBothSides)
{
    const surfaceCase c;
    // Flipped triangles: the sides of a closed cut come from the
    // even-odd rule, not the normals.
    c.add("box.stl", flipped(cube({0, 0, -0.5}, {1, 1, 0.5})));
    const scalar dp = 0.1;
    for (const std::string side : {"outside", "inside", "both"})
    {
        const std::vector<vec3> nodes = fill2D(c, "shape surfaceLayers; file"
            " \"constant/geometry/box.stl\"; layers 3; side " + side + ";",
            dp);
        std::size_t expected = 0;
        for (int j = -5; j < 15; ++j)
        for (int i = -5; i < 15; ++i)
        {
            const vec3 p{(i + 0.5)*dp, (j + 0.5)*dp, 0};
            bool in;
            const scalar d = boxDistance(p, {0, 0, -1}, {1, 1, 1}, in);
            const scalar d2 = in ? std::min({p.x, 1 - p.x, p.y, 1 - p.y})
                                 : d;
            const bool sideOk = side == "both" || (side == "inside") == in;
            expected += sideOk && d2 > 0 && d2 <= 3*dp*(1 + 1e-9);
        }
        EXPECT_EQ(nodes.size(), expected) << side;
    }
    // Inside: the 10 x 10 square less its 4 x 4 core.
    EXPECT_EQ(fill2D(c, "shape surfaceLayers; file"
        " \"constant/geometry/box.stl\"; layers 3; side inside;", dp).size(),
        100u - 16u);
}


TEST(surfaceFill, generatorFills2DTankFromSTLWithWallsAndWater)
{
    const surfaceCase c;
    c.add("tank.stl", openTank2D());
    writeText(c.dir.path()/"system"/"generateParticlesDict",
        "nDimensions 2;\ndp 0.05;\nbodies\n{\n"
        "    walls { type wall; rho 1000; shapes { t { shape surfaceLayers;"
        " file \"constant/geometry/tank.stl\"; layers 3; side outside; } } }\n"
        "    water { type fluid; rho 1000; shapes { w { shape seedFill;"
        " file \"constant/geometry/tank.stl\"; seed (0.5 0.1);"
        " level 0.4; } } }\n}\n");
    particleGenerator gen(c.dir.path(), "system/generateParticlesDict");
    gen.generate();
    ASSERT_EQ(gen.summaries().size(), 2u);
    EXPECT_EQ(gen.summaries()[1].name, "water");
    EXPECT_EQ(gen.summaries()[1].nParticles, 20*8);
    EXPECT_EQ(gen.summaries()[1].nDropped, 0);
    // Walls: the nodes outside the U within 3 dp of it, rounding its ends.
    const std::vector<vec3> u{{0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    std::int64_t expected = 0;
    for (int j = -10; j < 30; ++j)
    for (int i = -10; i < 30; ++i)
    {
        const vec3 p{(i + 0.5)*0.05, (j + 0.5)*0.05, 0};
        const bool out = p.x < 0 || p.x > 1 || p.y < 0;
        expected += out && polylineDistance(p, u) <= 0.15*(1 + 1e-9);
    }
    EXPECT_EQ(gen.summaries()[0].nParticles, expected);
}
