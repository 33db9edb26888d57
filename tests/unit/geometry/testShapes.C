/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Shapes: inside tests with the boundary rule (min faces in, max faces out,
// curved surfaces in), 2D cuts, bounds that hold every inside point,
// closed-form volumes, and the errors of their dictionaries.

#include "boxShape.H"
#include "../testPrecision.H"
#include "containerShape.H"
#include "cylinderShape.H"
#include "sphereShape.H"
#include "testGeometryTools.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace sphvcpm;
using test::catchFatal;
using test::expectError;
using test::expectMessage;

namespace
{

const scalar tol = 1e-12;

// Every point of a random sample that is inside lies within the bounds.
void expectBoundsHold(const shape& s, const boundBox& around)
{
    std::mt19937_64 gen(7);
    std::uniform_real_distribution<scalar> u(0, 1);
    const boundBox b = s.bounds();
    int nInside = 0;
    for (int n = 0; n < 200000; ++n)
    {
        vec3 p;
        for (int d = 0; d < 3; ++d)
        {
            p[d] = around.min[d] + u(gen)*(around.max[d] - around.min[d]);
        }
        if (s.nDimensions() == 2)
        {
            p.z = 0;
        }
        if (s.inside(p, 0))
        {
            ++nInside;
            for (int d = 0; d < s.nDimensions(); ++d)
            {
                ASSERT_GE(p[d], b.min[d]) << s.name() << " axis " << d;
                ASSERT_LE(p[d], b.max[d]) << s.name() << " axis " << d;
            }
        }
    }
    EXPECT_GT(nInside, 100) << s.name();
}

std::unique_ptr<shape> fromText(const std::string& text, int nDim,
                                scalar dp = 0.01)
{
    const dictionary d =
        dictionary::fromString("s {" + text + "}", "/case/system/dict");
    return shape::New("s", d.subDict("s"), nDim, dp);
}

} // End anonymous namespace


TEST(shapes, boxInsideAndFaces)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    const boxShape b3("b", {0, 0, 0}, {1, 2, 3}, 3);
    EXPECT_TRUE(b3.inside({0.5, 1, 1.5}, tol));
    EXPECT_TRUE(b3.inside({0, 0, 0}, tol));         // min corner: in
    EXPECT_FALSE(b3.inside({1, 1, 1}, tol));        // max x face: out
    EXPECT_FALSE(b3.inside({0.5, 2, 1}, tol));      // max y face: out
    EXPECT_FALSE(b3.inside({0.5, 1, 3}, tol));      // max z face: out
    EXPECT_FALSE(b3.inside({-1e-9, 1, 1}, tol));
    EXPECT_TRUE(b3.inside({1 - 1e-9, 1, 1}, tol));
    // Within the tolerance counts as on the face.
    EXPECT_TRUE(b3.inside({-1e-13, 1, 1}, tol));
    EXPECT_FALSE(b3.inside({1 - 1e-13, 1, 1}, tol));
    EXPECT_DOUBLE_EQ(b3.volume(), 6);

    // 2D: z is ignored, so a box may be flat in z.
    const boxShape b2("b", {0, 0, 0}, {0.4, 0.3, 0}, 2);
    EXPECT_TRUE(b2.inside({0.1, 0.1, 0}, tol));
    EXPECT_TRUE(b2.inside({0.1, 0.1, 5}, tol));
    EXPECT_FALSE(b2.inside({0.4, 0.1, 0}, tol));
    EXPECT_DOUBLE_EQ(b2.volume(), 0.4*0.3);
}


TEST(shapes, sphereAndCircle)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    const sphereShape s("s", {1, 2, 3}, 0.5, 3);
    EXPECT_TRUE(s.inside({1, 2, 3}, tol));
    EXPECT_TRUE(s.inside({1.5, 2, 3}, tol));        // on the surface: in
    EXPECT_FALSE(s.inside({1.5 + 1e-9, 2, 3}, tol));
    EXPECT_FALSE(s.inside({1.4, 2.4, 3}, tol));
    EXPECT_NEAR(s.volume(), 4.0/3.0*M_PI*0.125, 1e-15);
    expectBoundsHold(s, {{0, 1, 2}, {2, 3, 4}});

    // 2D: a circle in the x-y plane whatever the centre's z.
    const sphereShape c("c", {1, 2, 7}, 0.5, 2);
    EXPECT_TRUE(c.inside({1.3, 2.3, 0}, tol));
    EXPECT_FALSE(c.inside({1.4, 2.4, 0}, tol));
    EXPECT_NEAR(c.volume(), M_PI*0.25, 1e-15);
}


TEST(shapes, cylinderAnyAxis)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    // Along z, caps at z = 0 (in) and z = 2 (out).
    const cylinderShape z("z", {0, 0, 0}, {0, 0, 2}, 1, 3);
    EXPECT_TRUE(z.inside({0.5, 0.5, 1}, tol));
    EXPECT_TRUE(z.inside({0.5, 0, 0}, tol));
    EXPECT_FALSE(z.inside({0.5, 0, 2}, tol));
    EXPECT_TRUE(z.inside({1, 0, 1}, tol));          // on the mantle: in
    EXPECT_FALSE(z.inside({0.8, 0.8, 1}, tol));
    EXPECT_NEAR(z.volume(), 2*M_PI, 1e-14);

    // Oblique: points at a known distance from the axis.
    const vec3 p1{1, 1, 1}, p2{2, 3, 4};
    const cylinderShape o("o", p1, p2, 0.25, 3);
    const vec3 a = (p2 - p1)/mag(p2 - p1);
    const vec3 n = cross(a, vec3{0, 0, 1})/mag(cross(a, vec3{0, 0, 1}));
    const vec3 mid = 0.5*(p1 + p2);
    EXPECT_TRUE(o.inside(mid + 0.24*n, tol));
    EXPECT_FALSE(o.inside(mid + 0.26*n, tol));
    EXPECT_TRUE(o.inside(p1 + 0.1*n, tol));         // point1 cap: in
    EXPECT_FALSE(o.inside(p2 + 0.1*n, tol));        // point2 cap: out
    EXPECT_FALSE(o.inside(p1 - 0.01*a, tol));
    EXPECT_NEAR(o.volume(), M_PI*0.0625*mag(p2 - p1), 1e-14);
    expectBoundsHold(o, {{0, 0, 0}, {3, 4, 5}});

    // 2D cuts by z = 0: axis along z is a disc, axis in the plane a
    // rectangle (half-width sqrt(r^2 - h^2) at height h), oblique unknown.
    const cylinderShape disc("d", {1, 1, -1}, {1, 1, 1}, 0.5, 2);
    EXPECT_TRUE(disc.inside({1.4, 1, 0}, tol));
    EXPECT_FALSE(disc.inside({1.4, 1.4, 0}, tol));
    EXPECT_NEAR(disc.volume(), M_PI*0.25, 1e-15);
    const cylinderShape above("a", {1, 1, 0.5}, {1, 1, 1}, 0.5, 2);
    EXPECT_EQ(above.volume(), 0);

    const cylinderShape bar("b", {0, 0, 0.3}, {2, 0, 0.3}, 0.5, 2);
    EXPECT_TRUE(bar.inside({1, 0.39, 0}, tol));
    EXPECT_FALSE(bar.inside({1, 0.41, 0}, tol));
    EXPECT_NEAR(bar.volume(), 2*0.4*2, 1e-14);
    expectBoundsHold(bar, {{-1, -1, 0}, {3, 1, 0}});

    const cylinderShape tilted("t", {0, 0, -1}, {1, 0, 1}, 0.5, 2);
    EXPECT_LT(tilted.volume(), 0);
}


TEST(shapes, containerLayers)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    // 2D, 2 layers of 0.1 around [0, 1) x [0, 1).
    const containerShape c("c", {0, 0, 0}, {1, 1, 0}, 2, false, 2, 0.1);
    EXPECT_FALSE(c.inside({0.5, 0.5, 0}, tol));
    EXPECT_TRUE(c.inside({-0.05, 0.5, 0}, tol));
    EXPECT_TRUE(c.inside({-0.2, -0.2, 0}, tol));    // outer min corner: in
    EXPECT_FALSE(c.inside({-0.21, 0.5, 0}, tol));
    EXPECT_TRUE(c.inside({1.15, 1.15, 0}, tol));    // corner block
    EXPECT_FALSE(c.inside({1.2, 0.5, 0}, tol));     // outer max face: out
    EXPECT_TRUE(c.inside({1, 0.5, 0}, tol));        // inner max face: wall
    EXPECT_FALSE(c.inside({0, 0.5, 0}, tol));       // inner min face: inside
    EXPECT_NEAR(c.volume(), 1.4*1.4 - 1, 1e-14);

    // Open top: nothing above the top of the box.
    const containerShape open("o", {0, 0, 0}, {1, 1, 0}, 2, true, 2, 0.1);
    EXPECT_TRUE(open.inside({-0.1, 0.99, 0}, tol));
    EXPECT_FALSE(open.inside({-0.1, 1.0, 0}, tol));
    EXPECT_FALSE(open.inside({0.5, 1.1, 0}, tol));
    EXPECT_NEAR(open.volume(), 1.4*1.2 - 1, 1e-14);

    // 3D: the top is z.
    const containerShape c3("c", {0, 0, 0}, {1, 1, 1}, 1, true, 3, 0.1);
    EXPECT_TRUE(c3.inside({0.5, 1.05, 0.5}, tol));
    EXPECT_TRUE(c3.inside({0.5, 0.5, -0.05}, tol));
    EXPECT_FALSE(c3.inside({0.5, 0.5, 1.05}, tol));
    EXPECT_NEAR(c3.volume(), 1.2*1.2*1.1 - 1, 1e-14);
}


TEST(shapes, selectedByDictionary)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    EXPECT_EQ(fromText("shape box; min (0 0 0); max (1 1 1);", 3)->type(),
              "box");
    EXPECT_EQ(fromText("shape sphere; centre (0 0); radius 1;", 2)->type(),
              "sphere");
    EXPECT_EQ(fromText("shape cylinder; point1 (0 0 0); point2 (0 0 1);"
                       " radius 1;", 3)->type(), "cylinder");
    const auto c = fromText("shape container; min (0 0 0); max (1 1 0);"
                            " layers 3; openTop yes;", 2, 0.01);
    ASSERT_EQ(c->type(), "container");
    EXPECT_TRUE(dynamic_cast<const containerShape&>(*c).openTop());
    EXPECT_EQ(dynamic_cast<const containerShape&>(*c).layers(), 3);
    EXPECT_NEAR(c->bounds().min.x, -0.03, 1e-15);
}


TEST(shapes, dictionaryErrors)
{
    const std::string file = "/case/system/dict";

    expectError(catchFatal([&]
    {
        fromText("\nshape cube; min (0 0 0); max (1 1 1);", 3);
    }), file, 2, {"'shape'", "unknown value 'cube'",
                  "box container cylinder polygon seedFill sphere stl"
                  " surfaceLayers"});

    expectError(catchFatal([&]
    {
        fromText("shape box;\nmin (0 0 0);\nmax (1 0 1);", 3);
    }), file, 3, {"max (1 0 1) is not above min (0 0 0) in y"});

    // 2D: only x and y count, and the message says so.
    expectError(catchFatal([&]
    {
        fromText("shape box; min (0 0 0);\nmax (-1 1 0);", 2);
    }), file, 2, {"max (-1 1) is not above min (0 0) in x", "2D"});

    expectError(catchFatal([&]
    {
        fromText("shape sphere; centre (0 0 0);\nradius 0;", 3);
    }), file, 2, {"'radius'", "expected a positive number", "found 0"});

    expectError(catchFatal([&]
    {
        fromText("shape cylinder; point1 (1 2 3);\npoint2 (1 2 3);"
                 " radius 1;", 3);
    }), file, 2, {"point1 == point2", "no direction"});

    expectError(catchFatal([&]
    {
        fromText("shape container; min (0 0 0); max (1 1 1);\nlayers 0;",
                 3);
    }), file, 2, {"at least one layer", "found 0"});

    // A misspelt keyword is named, with a suggestion and the valid ones.
    expectError(catchFatal([&]
    {
        fromText("shape sphere; centre (0 0 0);\nradus 1;", 3);
    }), file, 2, {"Unknown keyword 'radus'", "Did you mean 'radius'?",
                  "centre", "shape"});

    // Direct construction checks too.
    expectMessage(catchFatal([]
    {
        boxShape("b", {0, 0, 0}, {1, 1, 0}, 3);
    }), {"Box 'b'", "not above"});
    expectMessage(catchFatal([]
    {
        sphereShape("s", {0, 0, 0}, -1, 3);
    }), {"radius must be positive"});
    expectMessage(catchFatal([]
    {
        cylinderShape("c", {0, 0, 0}, {0, 0, 0}, 1, 3);
    }), {"point1 == point2"});
}
