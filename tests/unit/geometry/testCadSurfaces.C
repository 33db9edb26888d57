/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// STL surfaces exported by other tools (tests/data/geometry/cad, see its
// README.md): OpenSCAD (ASCII), gmsh, FreeCAD and VTK (binary, each with
// its own header). Each is read, must be closed, and is filled as shape stl
// fills it, at about 50 dp across its smallest relevant extent; the
// particles' volume N dp^3 is compared with
//   (a) the enclosed volume of the tessellated surface (triSurface::volume,
//       the "shapes" volume of the generator's report): within 1 %;
//   (b) the volume of the exact CAD solid: within 1 % plus what the
//       tessellation itself takes away or adds (below).
// The tessellation tolerance: a triangle whose vertices lie on a curved
// surface departs from it by its chord sag, largest near the triangle's
// middle, so sum(area x |distance of the centroid to the exact surface|)
// bounds the volume between the surface and its tessellation (the
// tessellated volume is checked against it too). For prismatic holes the
// tessellated volume is known in closed form (n-gon areas). One surface is
// also cut by z = 0 (shape stl in 2D) and its area compared the same way.

#include "lattice.H"
#include "../testPrecision.H"
#include "polygonShape.H"
#include "stlReader.H"
#include "stlShape.H"
#include "testGeometryTools.H"
#include "triSurface.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>

using namespace sphvcpm;
using namespace sphvcpm::test;

namespace
{

const scalar pi = M_PI;

std::string cadFile(const std::string& name)
{
    return std::string(SPHVCPM_TEST_DATA) + "/geometry/cad/" + name;
}

// The shape that text describes, as generateParticles builds it.
std::unique_ptr<shape> newShape(const std::string& text, int nDimensions,
                                scalar dp)
{
    const dictionary d = dictionary::fromString("s {" + text + "}",
                                                "generateParticlesDict");
    return shape::New("s", d.subDict("s"), nDimensions, dp);
}

// Number of lattice nodes (origin 0) inside the shape.
std::size_t fillCount(const std::string& text, int nDimensions, scalar dp,
                      scalar& shapeVolume)
{
    std::unique_ptr<shape> s = newShape(text, nDimensions, dp);
    shapeVolume = s->volume();
    region r(nDimensions);
    r.add(std::move(s));
    return lattice({0, 0, 0}, dp, nDimensions).fill(r).size();
}

// sum(area |distance(centroid)|) over the triangles of surf, scaled by
// scale^3: the volume between the tessellation and the exact surface whose
// unsigned distance is distance(p) (in the file's units).
scalar sagVolume
(
    const triSurface& surf,
    const std::function<scalar(const vec3&)>& distance,
    scalar scale = 1
)
{
    scalar v = 0;
    for (const triSurface::face& f : surf.faces())
    {
        const vec3& a = surf.points()[f[0]];
        const vec3& b = surf.points()[f[1]];
        const vec3& c = surf.points()[f[2]];
        v += 0.5*mag(cross(b - a, c - a))*distance((a + b + c)/scalar(3));
    }
    return v*scale*scale*scale;
}

// What each file must give.
struct cadCase
{
    std::string file;
    std::string keywords;       // extra keywords of the shape (scale)
    scalar scale;               // file units to m
    bool binary;
    std::size_t nTriangles;
    scalar exactVolume;         // of the CAD solid [m^3]
    scalar tessellation;        // relative tolerance from the tessellation
    scalar dp;
};

struct measured
{
    scalar surfaceError;        // N dp^3 against the tessellated volume
    scalar exactError;          // N dp^3 against the CAD volume
    scalar tessellatedError;    // tessellated against CAD volume
};

measured check(const cadCase& c)
{
    const std::string path = cadFile(c.file);
    const stlData stl = readSTL(path);
    EXPECT_EQ(stl.binary, c.binary) << c.file;
    EXPECT_EQ(stl.nTriangles(), c.nTriangles) << c.file;

    std::vector<vec3> soup = stl.vertices;
    for (vec3& p : soup)
    {
        p = c.scale*p;
    }
    const triSurface surf(soup, 1e-6*c.scale);
    EXPECT_TRUE(surf.closed()) << c.file << ": " << surf.openEdges().size()
        << " open edges";
    EXPECT_EQ(surf.repaired().nDegenerate, 0u) << c.file;
    EXPECT_EQ(surf.repaired().nDuplicate, 0u) << c.file;

    scalar shapeVolume = 0;
    const std::size_t n = fillCount("shape stl; file \"" + path + "\";"
        + c.keywords, 3, c.dp, shapeVolume);
    const scalar particles = scalar(n)*c.dp*c.dp*c.dp;

    // The shape's volume (the report's) is the tessellated surface's.
    EXPECT_NEAR(shapeVolume/std::abs(surf.volume()), 1, 1e-12) << c.file;
    const measured m
    {
        particles/shapeVolume - 1,
        particles/c.exactVolume - 1,
        shapeVolume/c.exactVolume - 1
    };
    std::cout << "    " << c.file << ": " << stl.nTriangles()
        << " triangles, " << n << " particles; volume error "
        << 100*m.surfaceError << " % against the tessellated surface, "
        << 100*m.exactError << " % against the CAD solid (tessellation "
        << 100*m.tessellatedError << " %, tolerance "
        << 100*c.tessellation << " %)\n";
    EXPECT_LT(std::abs(m.surfaceError), 0.01) << c.file;
    EXPECT_LE(std::abs(m.tessellatedError), c.tessellation) << c.file;
    EXPECT_LT(std::abs(m.exactError), 0.01 + c.tessellation) << c.file;
    return m;
}

// Area of the regular n-gon inscribed in a circle of radius r.
scalar nGonArea(int n, scalar r)
{
    return 0.5*n*r*r*std::sin(2*pi/n);
}

} // End anonymous namespace


// OpenSCAD 2021.01, ASCII "solid OpenSCAD_Model", in mm: an L-bracket
// (union of two boxes) with a 48-gon hole through each leg.
TEST(cadSurfaces, openscadBracket)
{
    // Exact double values or digits of geometry (single: float rounding).
    SPHVCPM_DOUBLE_ONLY();
    const scalar mm = 1e-3;
    const scalar exact = (60*40*10 + 10*40*40 - pi*64*10 - pi*36*10)
        *mm*mm*mm;
    // The holes are 48-gon prisms: the tessellated volume is exact to the
    // float coordinates.
    const scalar tessellated = (60*40*10 + 10*40*40 - nGonArea(48, 8)*10
        - nGonArea(48, 6)*10)*mm*mm*mm;
    const stlData stl = readSTL(cadFile("bracket.stl"));
    ASSERT_EQ(stl.solids.size(), 1u);
    EXPECT_EQ(stl.solids[0], "OpenSCAD_Model");

    // 50 dp across the 10 mm plates (their faces on lattice faces).
    const measured m = check({"bracket.stl", " scale 0.001;", mm, false, 412,
        exact, std::abs(tessellated/exact - 1)*(1 + 1e-5), 0.2*mm});
    EXPECT_NEAR(m.tessellatedError, tessellated/exact - 1, 1e-6);

    // Cut by z = 5 mm (2D): the base, 60 x 40 mm less the 48-gon, exactly.
    scalar cutArea = 0;
    const scalar dp = 0.2*mm;
    const std::size_t n = fillCount("shape stl; file \"" + cadFile("bracket.stl")
        + "\"; scale 0.001; translate (0 0 -0.005);", 2, dp, cutArea);
    const scalar exactArea = (60*40 - pi*64)*mm*mm;
    EXPECT_NEAR(cutArea/((60*40 - nGonArea(48, 8))*mm*mm), 1, 1e-6);
    const scalar areaError = n*dp*dp/exactArea - 1;
    std::cout << "    bracket.stl cut by z = 5 mm: " << n << " particles;"
        << " area error " << 100*(n*dp*dp/cutArea - 1) << " % against the"
        << " cut, " << 100*areaError << " % against the CAD section\n";
    EXPECT_LT(std::abs(areaError), 0.01);
}


// gmsh 4.8.4 (OpenCASCADE kernel), binary with header "Created by Gmsh":
// a torus (genus one, non-convex) of radii 0.3 and 0.1 about z.
TEST(cadSurfaces, gmshTorus)
{
    const scalar R = 0.3, r = 0.1;
    const std::string path = cadFile("torus.stl");
    const triSurface surf(readSTL(path).vertices, 1e-7);
    const scalar exact = 2*pi*pi*R*r*r;
    const scalar sag = sagVolume(surf, [&](const vec3& p)
    {
        const scalar rho = std::hypot(p.x, p.y) - R;
        return std::abs(std::hypot(rho, p.z) - r);
    });
    // 50 dp across the tube.
    check({"torus.stl", "", 1, true, 5630, exact, sag/exact, 0.004});

    // Its cut by z = 0 (many vertices lie on the plane): the annulus
    // 0.2 < r < 0.4, whose inscribed polygons the cut gives.
    scalar cutArea = 0;
    const scalar dp = 0.004;
    const std::size_t n = fillCount("shape stl; file \"" + path + "\";", 2,
                                    dp, cutArea);
    const scalar exactArea = pi*((R + r)*(R + r) - (R - r)*(R - r));
    const scalar areaError = n*dp*dp/cutArea - 1;
    const scalar exactAreaError = n*dp*dp/exactArea - 1;
    // The cut's polygons approximate the two circles: their distance to
    // them bounds the area lost or gained.
    const std::unique_ptr<shape> cut =
        newShape("shape stl; file \"" + path + "\";", 2, dp);
    scalar sagArea = 0;
    for (const planarRegion::segment& s : stlSliceShape::cut(surf.points(),
                                                             surf.faces()))
    {
        // The area between a segment and the arc it stands for is within
        // its length times the largest distance of its ends and middle to
        // the circle (its ends are on chords of the triangles, not on the
        // circle, when they do not lie on the plane).
        const auto off = [&](scalar x, scalar y)
        {
            const scalar rho = std::hypot(x, y);
            return std::abs(rho - (rho > R ? R + r : R - r));
        };
        const scalar len = std::hypot(s.x1 - s.x0, s.y1 - s.y0);
        sagArea += len*std::max({off(s.x0, s.y0), off(s.x1, s.y1),
            off(0.5*(s.x0 + s.x1), 0.5*(s.y0 + s.y1))});
    }
    std::cout << "    torus.stl cut by z = 0: " << n << " particles; area"
        << " error " << 100*areaError << " % against the cut, "
        << 100*exactAreaError << " % against the annulus (cut "
        << 100*(cutArea/exactArea - 1) << " %, tolerance "
        << 100*sagArea/exactArea << " %)\n";
    EXPECT_NEAR(cut->volume(), cutArea, 1e-15);
    EXPECT_LT(std::abs(areaError), 0.01);
    EXPECT_LE(std::abs(cutArea/exactArea - 1), sagArea/exactArea);
    EXPECT_LT(std::abs(exactAreaError), 0.01 + sagArea/exactArea);
}


// FreeCAD 0.20.2, Part box cut by a sphere and meshed by MeshPart (0.05 mm
// deflection), binary with header "MESH-MESH-...", in mm: a bowl.
TEST(cadSurfaces, freecadBowl)
{
    const scalar mm = 1e-3;
    const scalar exact = (40*40*20 - 2.0/3.0*pi*15*15*15)*mm*mm*mm;
    const vec3 centre{20, 20, 20};
    const triSurface surf(readSTL(cadFile("bowl.stl")).vertices, 1e-6);
    // The sagging triangles are those of the sphere (all three vertices
    // on it); the box's are flat.
    const scalar sag = sagVolume(surf, [&](const vec3& p)
    {
        const scalar d = std::abs(mag(p - centre) - 15);
        return d < 0.1 ? d : 0;
    }, mm);
    // 50 dp across the 20 mm height.
    check({"bowl.stl", " scale 0.001;", mm, true, 1588, exact, sag/exact,
           0.4*mm});
}


// VTK 9.2 (ParaView 5.11) vtkSTLWriter, binary with header "Visualization
// Toolkit generated SLA File": a hollow sphere, two latitude-longitude
// spheres of radii 0.5 and 0.3 whose triangles all face out (the inner
// one is a cavity all the same).
TEST(cadSurfaces, vtkHollowSphere)
{
    const scalar rOut = 0.5, rIn = 0.3;
    const triSurface surf(readSTL(cadFile("hollowSphere.stl")).vertices,
                          1e-7);
    EXPECT_EQ(surf.nShells(), 2u);
    const scalar exact = 4.0/3.0*pi*(rOut*rOut*rOut - rIn*rIn*rIn);
    const scalar sag = sagVolume(surf, [&](const vec3& p)
    {
        const scalar d = mag(p);
        return std::min(std::abs(d - rOut), std::abs(d - rIn));
    });
    // 40 dp across the 0.2 m shell (50 would hold 6.4 million particles).
    check({"hollowSphere.stl", "", 1, true, 4224, exact, sag/exact, 0.005});
}
