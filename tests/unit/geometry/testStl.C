/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// STL surfaces: reading (ASCII with several solids, binary, gzip), repairs
// and their report, open-surface and malformed-file errors, the three-ray
// inside test (flipped triangles, rays through edges, non-convex shapes,
// tiny gaps), volumes, transforms and the stl shape in generateParticles.

#include "lattice.H"
#include "../testPrecision.H"
#include "particleGenerator.H"
#include "stlReader.H"
#include "stlShape.H"
#include "testGeometryTools.H"
#include "testStlSurfaces.H"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>

using namespace sphvcpm;
using namespace sphvcpm::test;
namespace fs = std::filesystem;

namespace
{

const scalar pi = M_PI;

std::unique_ptr<shape> stlFromText(const std::string& text,
                                   const fs::path& caseDir, int nDim = 3)
{
    const dictionary d = dictionary::fromString("s {" + text + "}",
        (caseDir/"system"/"generateParticlesDict").string());
    return shape::New("s", d.subDict("s"), nDim, 0.01, {}, caseDir);
}

// Lattice nodes of spacing dp inside s.
std::size_t fillCount(std::unique_ptr<shape> s, scalar dp,
                      const vec3& origin = {0, 0, 0})
{
    region r(3);
    r.add(std::move(s));
    return lattice(origin, dp, 3).fill(r).size();
}

// Random points of box b, classified by s and by exact(p), skipping the
// points within band of the surface (where a polyhedron and the exact
// shape differ): the number that disagree.
template<class Exact>
int disagreements(const shape& s, const boundBox& b, Exact exact,
                  int n = 20000)
{
    std::mt19937_64 gen(11);
    std::uniform_real_distribution<scalar> u(0, 1);
    int bad = 0;
    for (int i = 0; i < n; ++i)
    {
        vec3 p;
        for (int d = 0; d < 3; ++d)
        {
            p[d] = b.min[d] + u(gen)*(b.max[d] - b.min[d]);
        }
        const int e = exact(p);     // 1 in, 0 out, -1 too close to tell
        if (e >= 0 && int(s.inside(p, 0)) != e)
        {
            ++bad;
        }
    }
    return bad;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Reading * * * * * * * * * * * * * * * * //

TEST(stl, asciiBinaryAndGzipGiveTheSameTriangles)
{
    const scratchDir dir("stl");
    const soup s = asFloat(icosphere({0.1, 0.2, 0.3}, 0.5, 2));
    writeFile(dir.path()/"a.stl", asciiSTL(s, 3));
    // A binary header that starts with "solid", as some exporters write.
    writeFile(dir.path()/"b.stl", binarySTL(s, "solid exported by CAD"));
    writeGz(dir.path()/"c.stl.gz", asciiSTL(s));
    writeGz(dir.path()/"d.stl.gz", binarySTL(s));

    const stlData a = readSTL(dir.path()/"a.stl");
    EXPECT_FALSE(a.binary);
    EXPECT_FALSE(a.compressed);
    EXPECT_EQ(a.solids,
              (std::vector<std::string>{"part0", "part1", "part2"}));
    EXPECT_EQ(a.nTriangles(), s.size()/3);
    EXPECT_EQ(a.vertices, s);

    const stlData b = readSTL(dir.path()/"b.stl");
    EXPECT_TRUE(b.binary);
    EXPECT_EQ(b.vertices, s);

    const stlData c = readSTL(dir.path()/"c.stl.gz");
    EXPECT_TRUE(c.compressed);
    EXPECT_FALSE(c.binary);
    EXPECT_EQ(c.vertices, s);

    const stlData d = readSTL(dir.path()/"d.stl.gz");
    EXPECT_TRUE(d.compressed);
    EXPECT_TRUE(d.binary);
    EXPECT_EQ(d.vertices, s);
}


TEST(stl, asciiIsLenient)
{
    // Upper case keywords, CRLF line ends, no names, an empty solid.
    const std::string text =
        "SOLID\r\nendsolid\r\nsolid\r\n FACET NORMAL 0 0 nan\r\n OUTER LOOP\r\n"
        "  VERTEX 0 0 0\r\n  VERTEX 1 0 0\r\n  VERTEX 0 1 0\r\n ENDLOOP\r\n"
        " ENDFACET\r\nENDSOLID\r\n";
    const stlData d = parseSTL(text.data(), text.size(), "t.stl");
    EXPECT_EQ(d.solids.size(), 2u);
    ASSERT_EQ(d.nTriangles(), 1u);
    EXPECT_EQ(d.vertices[1], (vec3{1, 0, 0}));
}


// * * * * * * * * * * * * * * * Bad files * * * * * * * * * * * * * * * * //

TEST(stl, malformedFilesAreClearErrors)
{
    const auto parse = [](const std::string& text)
    {
        return catchFatal([&]()
        {
            parseSTL(text.data(), text.size(), "x.stl");
        });
    };
    const std::string good = asciiSTL(cube({0, 0, 0}, {1, 1, 1}));

    expectError(parse(""), "x.stl", 0, {"empty"});
    expectError(parse("  \n\t\n"), "x.stl", 0, {"empty"});

    // Truncated in a facet, and at the end of a solid.
    expectError(parse(good.substr(0, good.size()/2)), "x.stl", -1,
                {"truncated"});
    expectError(parse(good.substr(0, good.rfind("endsolid"))), "x.stl", -1,
                {"without 'endsolid'", "truncated"});

    // A non-finite and a malformed coordinate, at their lines.
    std::string bad = good;
    bad.replace(bad.find("vertex 0 0 0"), 12, "vertex 0 nan 0");
    expectError(parse(bad), "x.stl", lineOf(bad, "nan"), {"not a finite"});
    bad = good;
    bad.replace(bad.find("vertex 0 0 0"), 12, "vertex 0 1e999 0");
    expectError(parse(bad), "x.stl", lineOf(bad, "1e999"), {"not a finite"});
    bad = good;
    bad.replace(bad.find("vertex 0 0 0"), 12, "vertex 0 0,5 0");
    expectError(parse(bad), "x.stl", lineOf(bad, "0,5"),
                {"expected a number", "0,5"});

    // Four vertices in a loop.
    bad = good;
    const std::size_t at = bad.find("endloop");
    bad.insert(at, "vertex 1 1 1\n      ");
    expectError(parse(bad), "x.stl", -1, {"expected 'endloop'", "vertex"});

    // No triangles.
    expectError(parse("solid empty\nendsolid empty\n"), "x.stl", 0,
                {"no triangles"});

    // Binary: count against size, too short, non-finite, no triangles.
    std::string bin = binarySTL(cube({0, 0, 0}, {1, 1, 1}), "CAD export");
    expectError(parse(bin.substr(0, bin.size() - 7)), "x.stl", 0,
                {"header counts 12 triangles", "684 bytes", "677 bytes",
                 "truncated"});
    expectError(parse(bin.substr(0, 50)), "x.stl", 0, {"fewer than the"});
    bin = binarySTL(cube({0, 0, 0}, {1, 1, 1}));
    const float inf = std::numeric_limits<float>::infinity();
    std::memcpy(&bin[84 + 50*5 + 12 + 4], &inf, 4);
    expectError(parse(bin), "x.stl", 0, {"triangle 5", "non-finite"});
    expectError(parse(binarySTL({})), "x.stl", 0, {"no triangles"});

    // A huge count in the header is not allocated.
    bin = binarySTL(cube({0, 0, 0}, {1, 1, 1}));
    const std::uint32_t huge = 0xFFFFFFFFu;
    std::memcpy(&bin[80], &huge, 4);
    expectError(parse(bin), "x.stl", 0, {"4294967295 triangles"});
}


TEST(stl, badFilesThroughTheShape)
{
    const scratchDir dir("stl");
    const fs::path dict = dir.path()/"system"/"generateParticlesDict";

    // Missing file: the dictionary's keyword.
    FatalError err = catchFatal([&]()
    {
        stlFromText("shape stl; file \"constant/geometry/none.stl\";",
                    dir.path());
    });
    expectError(err, dict.string(), 1, {"none.stl", "case directory"});

    // A truncated gzip file.
    const std::string bytes = asciiSTL(cube({0, 0, 0}, {1, 1, 1}));
    writeGz(dir.path()/"full.stl.gz", bytes);
    std::ifstream in(dir.path()/"full.stl.gz", std::ios::binary);
    std::string gz((std::istreambuf_iterator<char>(in)),
                   std::istreambuf_iterator<char>());
    writeFile(dir.path()/"cut.stl.gz", gz.substr(0, gz.size()/2));
    err = catchFatal([&]()
    {
        stlFromText("shape stl; file cut.stl.gz;", dir.path());
    });
    expectError(err, (dir.path()/"cut.stl.gz").string(), 0,
                {"Shape 's'", "gzip"});

    // An open surface, named with where the shape was asked for.
    soup open = cube({0, 0, 0}, {1, 1, 1});
    open.resize(open.size() - 3);
    writeFile(dir.path()/"open.stl", asciiSTL(open));
    err = catchFatal([&]()
    {
        stlFromText("shape stl; file open.stl;", dir.path());
    });
    expectError(err, (dir.path()/"open.stl").string(), 0,
                {"Shape 's' (" + dict.string() + " line 1): the surface is"
                 " not closed: 3 open edges"});

    // An empty file, named with where the shape was asked for.
    writeFile(dir.path()/"empty.stl", "");
    err = catchFatal([&]()
    {
        stlFromText("shape stl; file empty.stl;", dir.path());
    });
    expectError(err, (dir.path()/"empty.stl").string(), 0,
                {"Shape 's'", dict.string(), "empty"});

    // 2D, a bad keyword, a zero scale, a zero axis.
    writeFile(dir.path()/"cube.stl", bytes);
    err = catchFatal([&]()
    {
        stlFromText("shape stl; file cube.stl; translate (0 0 1);",
                    dir.path(), 2);
    });
    expectError(err, (dir.path()/"cube.stl").string(), 0,
                {"Shape 's'", dict.string(), "z = 0 does not cut"});
    err = catchFatal([&]()
    {
        stlFromText("shape stl; file cube.stl; scal 2;", dir.path());
    });
    expectError(err, dict.string(), 1, {"scal"});
    err = catchFatal([&]()
    {
        stlFromText("shape stl; file cube.stl;\n scale 0;", dir.path());
    });
    expectError(err, dict.string(), 2, {"scale", "non-zero"});
    err = catchFatal([&]()
    {
        stlFromText("shape stl; file cube.stl;\n"
                    "rotate { axis (0 0 0); angle 3; }", dir.path());
    });
    expectError(err, dict.string(), 2, {"axis", "non-zero"});
    err = catchFatal([&]()
    {
        stlFromText("shape stl; file cube.stl;\n mergeDistance -1;",
                    dir.path());
    });
    expectError(err, dict.string(), 2, {"mergeDistance"});
}


TEST(stl, openSurfaceIsAnErrorNamingItsEdges)
{
    soup s = cube({0, 0, 0}, {1, 1, 1});
    s.resize(s.size() - 3);     // one triangle of the +x face missing
    const FatalError err = catchFatal([&]()
    {
        stlShape("lid", s, "open.stl");
    });
    expectError(err, "open.stl", 0,
                {"Shape 'lid'", "not closed", "3 open edges",
                 "within (1 0 0) to (1 1 1)", "checkClosed no"});

    // Filled anyway on request: the vote closes the hole; no volume.
    const stlShape lenient("lid", s, "open.stl", -1, false);
    EXPECT_FALSE(lenient.surface().closed());
    EXPECT_LT(lenient.volume(), 0);
    EXPECT_TRUE(lenient.inside({0.5, 0.5, 0.5}, 0));
    // Its +x ray leaves through the hole; the two others outvote it.
    EXPECT_TRUE(lenient.inside({0.9, 0.3, 0.6}, 0));
    EXPECT_FALSE(lenient.inside({1.1, 0.3, 0.6}, 0));
}


TEST(stl, degenerateAndDuplicateTrianglesAreDropped)
{
    soup s = cube({0, 0, 0}, {1, 1, 1});
    addTriangle(s, {0, 0, 0}, {0, 0, 0}, {1, 0, 0});        // two equal
    addTriangle(s, {0, 0, 0}, {0.5, 0, 0}, {1, 0, 0});      // collinear
    addTriangle(s, {0, 0, 0}, {1e-12, 0, 0}, {0, 1, 0});    // merged
    for (int i = 0; i < 2; ++i)     // a coincident pair cancels
    {
        addTriangle(s, {0, 0, 0}, {1, 1, 1}, {0, 1, 0});
    }
    const stlShape c("c", s, "c.stl");
    EXPECT_EQ(c.surface().size(), 12u);
    EXPECT_EQ(c.surface().repaired().nDegenerate, 3u);
    EXPECT_EQ(c.surface().repaired().nDuplicate, 2u);
    EXPECT_EQ(c.surface().repaired().nMergedPoints, 1u);
    EXPECT_TRUE(c.surface().closed());
    EXPECT_NEAR(c.volume(), 1, 1e-12);

    // Nothing left: an error, not an empty shape.
    soup none;
    addTriangle(none, {0, 0, 0}, {1, 0, 0}, {2, 0, 0});
    expectError(catchFatal([&]() { stlShape("n", none, "n.stl"); }),
                "n.stl", 0, {"no triangle", "1 degenerate"});
}


// * * * * * * * * * * * * * * Inside and volume * * * * * * * * * * * * * //

TEST(stl, cubeInsideEveryRayThroughEdgesAndVertices)
{
    const soup s = cube({0, 0, 0}, {1, 1, 1});
    const triSurface surf(s, 0);
    const triSurfaceInside test(surf);

    // Rays from these points run exactly along the face diagonals (shared
    // edges) and through vertices of the triangulation: each single ray
    // must count right, without the vote.
    const std::vector<vec3> in =
        {{0.5, 0.5, 0.5}, {0.25, 0.25, 0.25}, {0.5, 0.25, 0.25},
         {1e-9, 0.5, 0.5}, {0.3, 0.3, 0.7}};
    for (const vec3& p : in)
    {
        for (int axis = 0; axis < 3; ++axis)
        {
            EXPECT_EQ(test.parity(p, axis), 1) << p.x << ' ' << p.y << ' '
                << p.z << " axis " << axis;
        }
    }
    // Outside, with rays through vertices and along the cube's edges.
    const std::vector<vec3> out =
        {{-0.5, 0, 0}, {-0.5, 1, 1}, {-0.5, 0.5, 0.5}, {0.5, -0.5, 1},
         {2, 2, 2}, {0.5, 0.5, -1e-9}};
    for (const vec3& p : out)
    {
        for (int axis = 0; axis < 3; ++axis)
        {
            EXPECT_EQ(test.parity(p, axis), 0) << p.x << ' ' << p.y << ' '
                << p.z << " axis " << axis;
        }
    }

    // Lattices lined up with the faces' diagonals: exactly 10^3 nodes.
    EXPECT_EQ(fillCount(std::make_unique<stlShape>("c", s, "c"), 0.1), 1000u);
    EXPECT_NEAR(stlShape("c", s, "c").volume(), 1, 1e-12);
}


TEST(stl, sphereVolumeErrorBelowOnePercentAt50Across)
{
    const scalar r = 0.5;
    const vec3 c{0.013, -0.021, 0.007};   // off the lattice's symmetry
    auto s = std::make_unique<stlShape>("ball", icosphere(c, r, 5), "ball");
    const scalar exact = 4.0/3.0*pi*r*r*r;
    // The polyhedron is a little smaller than the sphere.
    EXPECT_LT(s->volume(), exact);
    EXPECT_NEAR(s->volume()/exact, 1, 1e-3);

    const scalar dp = 2*r/50;
    const std::size_t n = fillCount(std::move(s), dp);
    const scalar err = std::abs(n*dp*dp*dp - exact)/exact;
    EXPECT_LT(err, 0.01) << n << " particles";
}


TEST(stl, flippedTrianglesDoNotMatter)
{
    const soup s = icosphere({0, 0, 0}, 1, 3);
    const stlShape ok("ok", s, "ok");
    const stlShape half("half", flipped(s, 2), "half");
    const stlShape some("some", flipped(s, 7), "some");
    EXPECT_NEAR(half.volume(), ok.volume(), 1e-12);
    EXPECT_NEAR(some.volume(), ok.volume(), 1e-12);
    EXPECT_GT(ok.volume(), 4.0);

    // Inside out entirely: still the same body.
    const stlShape inverted("inv", flipped(s, 1), "inv");
    EXPECT_NEAR(inverted.volume(), ok.volume(), 1e-12);

    EXPECT_EQ(fillCount(std::make_unique<stlShape>("h", flipped(s, 3), "h"),
                        0.05),
              fillCount(std::make_unique<stlShape>("o", s, "o"), 0.05));
}


TEST(stl, nonConvexTorus)
{
    const scalar R = 1, a = 0.3;
    const stlShape t("torus", torus({0, 0, 0}, R, a, 128, 64), "torus");
    // Volume 2 pi^2 R a^2, less the polyhedron's chords.
    EXPECT_NEAR(t.volume()/(2*pi*pi*R*a*a), 1, 3e-3);

    const auto exact = [&](const vec3& p)
    {
        const scalar q = std::hypot(p.x, p.y) - R;
        const scalar d = std::hypot(q, p.z) - a;
        return std::abs(d) < 2e-3 ? -1 : int(d < 0);
    };
    EXPECT_EQ(disagreements(t, {{-1.5, -1.5, -0.5}, {1.5, 1.5, 0.5}}, exact),
              0);
    EXPECT_FALSE(t.inside({0, 0, 0}, 0));      // the hole
    EXPECT_TRUE(t.inside({R, 0, 0}, 0));
}


TEST(stl, cavityAndTouchingBodies)
{
    // A hollow cube: the inner surface (either orientation) subtracts.
    soup hollow = cube({0, 0, 0}, {3, 3, 3});
    const soup inner = cube({1, 1, 1}, {2, 2, 2});
    hollow.insert(hollow.end(), inner.begin(), inner.end());
    const stlShape h("h", hollow, "h");
    EXPECT_EQ(h.surface().nShells(), 2u);
    EXPECT_NEAR(h.volume(), 26, 1e-12);
    EXPECT_FALSE(h.inside({1.5, 1.5, 1.5}, 0));
    EXPECT_TRUE(h.inside({0.5, 1.5, 1.5}, 0));
    EXPECT_NEAR(stlShape("h", flipped(hollow, 1), "h").volume(), 26, 1e-12);

    // Two cubes sharing a face, written as two solids: their union (the
    // shared face cancels in pairs).
    soup two = cube({0, 0, 0}, {1, 1, 1});
    const soup next = cube({1, 0, 0}, {2, 1, 1});
    two.insert(two.end(), next.begin(), next.end());
    const stlShape u("u", two, "u");
    EXPECT_EQ(u.surface().repaired().nDuplicate, 4u);
    EXPECT_TRUE(u.surface().closed());
    EXPECT_NEAR(u.volume(), 2, 1e-12);
    EXPECT_EQ(fillCount(std::make_unique<stlShape>("u", two, "u"), 0.1),
              2000u);
}


TEST(stl, nestedShellsAndManyShells)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    // A ball in a hollow ball: the volumes alternate in sign whatever the
    // orientation of each shell.
    soup nested = icosphere({0, 0, 0}, 1, 3);
    const soup middle = flipped(icosphere({0, 0, 0}, 0.7, 3), 1);
    const soup inner = icosphere({0.05, 0, 0}, 0.3, 3);
    nested.insert(nested.end(), middle.begin(), middle.end());
    nested.insert(nested.end(), inner.begin(), inner.end());
    const stlShape n("n", flipped(nested, 5), "n");
    const scalar v1 = stlShape("a", icosphere({0, 0, 0}, 1, 3), "a").volume();
    const scalar v2 =
        stlShape("b", icosphere({0, 0, 0}, 0.7, 3), "b").volume();
    const scalar v3 =
        stlShape("c", icosphere({0.05, 0, 0}, 0.3, 3), "c").volume();
    EXPECT_EQ(n.surface().nShells(), 3u);
    EXPECT_NEAR(n.volume(), v1 - v2 + v3, 1e-12);
    EXPECT_TRUE(n.inside({0.85, 0, 0}, 0));
    EXPECT_FALSE(n.inside({0.5, 0, 0}, 0));
    EXPECT_TRUE(n.inside({0.1, 0, 0}, 0));

    // 4,000 separate cubes (48,000 triangles): a few inside queries per
    // shell orient them, not a pass over all triangles per shell.
    soup many;
    for (int i = 0; i < 4000; ++i)
    {
        const vec3 lo{scalar(i % 20), scalar((i/20) % 20), scalar(i/400)};
        const soup c = i % 2 ? flipped(cube(lo, lo + vec3{0.5, 0.5, 0.5}), 1)
                             : cube(lo, lo + vec3{0.5, 0.5, 0.5});
        many.insert(many.end(), c.begin(), c.end());
    }
    const stlShape m("m", many, "m");
    EXPECT_EQ(m.surface().nShells(), 4000u);
    EXPECT_NEAR(m.volume(), 4000*0.125, 1e-9);
}


TEST(stl, tinyGapsAreMergedOrOutvoted)
{
    const soup s = icosphere({0, 0, 0}, 1, 3);
    const std::size_t closedCount =
        fillCount(std::make_unique<stlShape>("s", s, "s"), 0.04);

    // Every soup vertex moved by up to 1e-9 (float round-off of an
    // export): the copies of a vertex no longer coincide but merge.
    soup jittered = s;
    std::mt19937_64 gen(3);
    std::uniform_real_distribution<scalar> u(-1e-9, 1e-9);
    for (vec3& p : jittered)
    {
        p += vec3{u(gen), u(gen), u(gen)};
    }
    const stlShape j("j", jittered, "j");
    EXPECT_TRUE(j.surface().closed());
    EXPECT_GT(j.surface().repaired().nMergedPoints, 0u);
    EXPECT_NEAR(j.volume(), stlShape("s", s, "s").volume(), 1e-7);

    // Merging off: the gaps are open edges...
    expectError(catchFatal([&]() { stlShape("j", jittered, "j", 0); }),
                "j", 0, {"not closed"});
    // ... and filling anyway, each single-ray error is outvoted.
    EXPECT_EQ(fillCount(std::make_unique<stlShape>("j", jittered, "j", 0,
                                                   false), 0.04),
              closedCount);

    // A real hole (one triangle missing): a handful of nodes at most.
    soup holed = s;
    holed.erase(holed.begin() + 300, holed.begin() + 303);
    const std::size_t holedCount = fillCount(
        std::make_unique<stlShape>("h", holed, "h", -1, false), 0.04);
    EXPECT_LE(std::abs(long(holedCount) - long(closedCount)), 2)
        << holedCount << " against " << closedCount;
}


TEST(stl, overflowingCoordinatesDoNotCrash)
{
    // Found with the fuzz target: a cube of +-1e308 overflows every area
    // and extent to inf or NaN. Answers are meaningless, but no crash.
    // (+-3e38 in single precision, near the largest float.)
    const scalar huge = scalar(sizeof(scalar) == 8 ? 1e308 : 3e38);
    const stlData d = [&]()
    {
        const std::string text = asciiSTL(cube({-huge, -huge, -huge},
                                               {huge, huge, huge}));
        return parseSTL(text.data(), text.size(), "huge.stl");
    }();
    for (const scalar merge : {scalar(0), scalar(1e-6), vGreat})
    {
        const triSurface surf(d.vertices, merge);
        const triSurfaceInside test(surf);
        (void)surf.volume();
        (void)test.inside({0, 0, 0});
        (void)test.inside({huge, 0, -huge});
    }
}


// * * * * * * * * * * * * * * * Transforms * * * * * * * * * * * * * * * * //

TEST(stl, scaleRotateTranslate)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    const scratchDir dir("stl");
    // A 2 x 1 x 1 box in mm.
    writeFile(dir.path()/"constant"/"geometry"/"box.stl",
              binarySTL(cube({0, 0, 0}, {2000, 1000, 1000})));
    const std::unique_ptr<shape> s = stlFromText(
        "shape stl; file \"constant/geometry/box.stl\"; scale 0.001;"
        " rotate { axis (0 0 2); angle 90; } translate (1 2 3);", dir.path());
    EXPECT_EQ(s->type(), "stl");
    EXPECT_NEAR(s->volume(), 2, 1e-9);
    // x' = Rz(90) (0.001 x) + (1 2 3): the box spans x 0..1, y 2..4, z 3..4.
    const boundBox b = s->bounds();
    const vec3 lo{0, 2, 3}, hi{1, 4, 4};
    for (int d = 0; d < 3; ++d)
    {
        EXPECT_NEAR(b.min[d], lo[d], 1e-9) << d;
        EXPECT_NEAR(b.max[d], hi[d], 1e-9) << d;
    }
    EXPECT_TRUE(s->inside({0.5, 3.9, 3.5}, 0));
    EXPECT_FALSE(s->inside({1.5, 2.5, 3.5}, 0));

    // A mirror (negative scale) is the same body, mirrored.
    const std::unique_ptr<shape> m = stlFromText(
        "shape stl; file \"constant/geometry/box.stl\"; scale -0.001;",
        dir.path());
    EXPECT_NEAR(m->volume(), 2, 1e-9);
    EXPECT_TRUE(m->inside({-1.5, -0.5, -0.5}, 0));
}


// * * * * * * * * * * * * * * generateParticles * * * * * * * * * * * * * //

TEST(stl, generatorFillsAndReportsTheVolumeError)
{
    const scratchDir dir("stl");
    writeGz(dir.path()/"constant"/"geometry"/"ball.stl.gz",
            binarySTL(icosphere({0.5, 0.5, 0.5}, 0.25, 4)));
    writeText(dir.path()/"system"/"generateParticlesDict",
        "nDimensions 3;\ndp 0.02;\nbodies\n{\n"
        "    ball { type solid; rho 2700; shapes { s { shape stl;"
        " file \"constant/geometry/ball.stl.gz\"; } } }\n"
        "    water { type fluid; rho 1000; shapes {\n"
        "        tank { shape box; min (0 0 0); max (1 1 1); }\n"
        "        hole { shape stl; file \"constant/geometry/ball.stl.gz\";"
        " scale 1.2; translate (-0.1 -0.1 -0.1); operation subtract; }\n"
        "    } }\n}\n");

    particleGenerator gen(dir.path(), "system/generateParticlesDict");
    gen.generate();
    std::ostringstream os;
    gen.printSummary(os);
    const std::string log = os.str();

    const scalar exact = 4.0/3.0*pi*0.25*0.25*0.25;
    ASSERT_EQ(gen.summaries().size(), 2u);
    const auto& ball = gen.summaries()[0];
    EXPECT_EQ(ball.name, "ball");
    EXPECT_NEAR(ball.shapeVolume/exact, 1, 3e-3);
    EXPECT_NEAR(ball.volume/ball.shapeVolume, 1, 0.02);
    EXPECT_NE(log.find("ball (solid): " + std::to_string(ball.nParticles)
                       + " particles"), std::string::npos) << log;
    EXPECT_NE(log.find(" %)"), std::string::npos) << log;
    EXPECT_NE(log.find(", error "), std::string::npos) << log;

    // The water fills the box outside the larger ball, away from the
    // solid (its 0.3 radius sphere leaves room for the clearance).
    const auto& water = gen.summaries()[1];
    EXPECT_EQ(water.nDropped, 0);
    EXPECT_NEAR(water.volume, 1 - 1.728*exact, 0.01);
}
