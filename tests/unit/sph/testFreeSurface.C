/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The fluid's free surface (libsrc/sph/freeSurface): blocks, a disc and a
// ball of particles on a lattice, whose edges are known. Checked: where
// the surface lies, the area or volume it encloses, that it is closed and
// consistently oriented (each edge of a triangle met once the other way
// round by one other triangle; each point of an outline the end of one
// segment and the start of one), the normals, and the fields on it.

#include "freeSurface.H"
#include "../testPrecision.H"
#include "../testTools.H"

#include <cmath>
#include <map>
#include <utility>

using namespace sphvcpm;

namespace
{

using test::catchFatal;
using test::expectMessage;
using test::tol;

// Rounding bounds of sums over particles in the build's precision.
const double roundRel = tol(1e-12, 1e-6);

constexpr scalar rho0 = 1000;

// Particles at cell centres of a lattice of spacing dp, filling inside(x),
// in a fluid body at rest with p = 2 + x and U = (1, -2, 3) (z 0 in 2D).
template<class Inside>
particleBody lattice(const std::string& name, int nDim, scalar dp,
                     const vec3& lo, const vec3& hi, const Inside& inside)
{
    particleBody body(name, bodyType::fluid, nDim, dp);
    auto& mass = body.addScalarField("mass");
    auto& rho = body.addScalarField("rho");
    auto& p = body.addScalarField("p");
    auto& U = body.addVectorField("U");
    const int nz = nDim == 3 ? int(std::round((hi.z - lo.z)/dp)) : 1;
    const int ny = int(std::round((hi.y - lo.y)/dp));
    const int nx = int(std::round((hi.x - lo.x)/dp));
    for (int k = 0; k < nz; ++k)
    {
        for (int j = 0; j < ny; ++j)
        {
            for (int i = 0; i < nx; ++i)
            {
                const point x{lo.x + (i + 0.5)*dp, lo.y + (j + 0.5)*dp,
                              nDim == 3 ? lo.z + (k + 0.5)*dp : 0};
                if (!inside(x)) continue;
                const label n = body.append(x);
                mass[n] = rho0*std::pow(dp, nDim);
                rho[n] = rho0;
                p[n] = 2 + x.x;
                U[n] = {1, -2, nDim == 3 ? scalar(3) : scalar(0)};
            }
        }
    }
    return body;
}

freeSurface surfaceOf(const std::vector<const particleBody*>& bodies,
                      const freeSurfaceSettings& settings = {})
{
    const scalar dp = bodies.front()->dp();
    return fluidFreeSurface(bodies, kernelType::wendlandC2, 1.5*dp,
                            settings);
}

const std::vector<vec3>& vectorField(const vtpMesh& m, const std::string& n)
{
    for (const auto& [name, values] : m.vectorFields)
    {
        if (name == n) return values;
    }
    throw std::runtime_error("no field " + n);
}

const std::vector<scalar>& scalarField(const vtpMesh& m, const std::string& n)
{
    for (const auto& [name, values] : m.scalarFields)
    {
        if (name == n) return values;
    }
    throw std::runtime_error("no field " + n);
}

// Closed and consistently oriented: every directed edge (a, b) of a cell
// is met exactly once, and (b, a) exactly once by another cell.
void expectClosed(const vtpMesh& m)
{
    std::map<std::pair<std::int64_t, std::int64_t>, int> directed;
    const int k = m.nodesPerCell;
    ASSERT_GT(m.nCells(), 0u);
    for (std::size_t c = 0; c < m.nCells(); ++c)
    {
        const std::int64_t* v = &m.connectivity[c*k];
        if (k == 2)
        {
            ++directed[{v[0], 1}];      // starts of segments
            ++directed[{v[1], 0}];      // ends
            continue;
        }
        for (int e = 0; e < 3; ++e)
        {
            ++directed[{v[e], v[(e + 1) % 3]}];
        }
    }
    std::size_t bad = 0;
    for (const auto& [edge, count] : directed)
    {
        if (k == 2)
        {
            bad += count != 1;
            continue;
        }
        const auto back = directed.find({edge.second, edge.first});
        bad += count != 1 || back == directed.end() || back->second != 1;
    }
    EXPECT_EQ(bad, 0u) << "edges not met once each way";
}

// Round about the origin (a disc or a ball): every point within half a
// particle of the radius R of the particles' own disc or ball, 0.1 dp on
// average, its normal of unit length and pointing outwards.
void expectRound(const vtpMesh& m, const scalar R, const scalar dp)
{
    const auto& n = vectorField(m, "Normals");
    double meanR = 0;
    for (std::size_t v = 0; v < m.points.size(); ++v)
    {
        const point& x = m.points[v];
        EXPECT_NEAR(mag(x), R, 0.5*dp);
        EXPECT_GT(dot(n[v], toVec3(x))/mag(x), 0.9);
        EXPECT_NEAR(mag(n[v]), 1, 10*roundRel);
        meanR += mag(x)/m.points.size();
    }
    EXPECT_NEAR(meanR, R, 0.1*dp);
}

} // End anonymous namespace


// A 2D block at rest: its outline is the block's edge, dp/2 beyond the
// outer particles, and encloses its area.
TEST(freeSurface, block2D)
{
    const scalar dp = 0.01;
    const particleBody water = lattice("water", 2, dp, {0, 0, 0},
        {0.4, 0.3, 0}, [](const point&) { return true; });
    const freeSurface fs = surfaceOf({&water});
    const vtpMesh& m = fs.mesh;
    EXPECT_EQ(m.nodesPerCell, 2);
    EXPECT_NEAR(fs.particleVolume, 0.12, 0.12*roundRel);
    EXPECT_NEAR(fs.enclosed, 0.12, 0.002*0.12);
    expectClosed(m);

    // Away from the corners the points lie on the block's sides.
    std::size_t onTop = 0;
    for (std::size_t v = 0; v < m.points.size(); ++v)
    {
        const point& x = m.points[v];
        EXPECT_EQ(x.z, 0);
        if (x.x > 3*dp && x.x < 0.4 - 3*dp && x.y > 0.15)
        {
            EXPECT_NEAR(x.y, 0.3, 0.03*dp) << "point " << v;
            const vec3& n = vectorField(m, "Normals")[v];
            EXPECT_NEAR(n.y, 1, tol(1e-6, 1e-5));
            ++onTop;
        }
    }
    EXPECT_GT(onTop, 50u);

    // Fields: uniform U exactly; p = 2 + x to within the lattice's
    // smoothing error.
    const auto& U = vectorField(m, "U");
    const auto& p = scalarField(m, "p");
    for (std::size_t v = 0; v < m.points.size(); ++v)
    {
        EXPECT_NEAR(U[v].x, 1, 10*roundRel);
        EXPECT_NEAR(U[v].y, -2, 10*roundRel);
        EXPECT_NEAR(U[v].z, 0, 10*roundRel);
        EXPECT_NEAR(scalarField(m, "rho")[v], rho0, 10*rho0*roundRel);
        if (m.points[v].x > 3*dp && m.points[v].x < 0.4 - 3*dp)
        {
            EXPECT_NEAR(p[v], 2 + m.points[v].x, 0.01*dp);
        }
    }
}

// A disc: the outline runs anticlockwise, normals point out, and the
// points lie on the edge of the lattice's disc to within half a particle
// (its edge is a staircase of particles), on average to 0.1 dp.
TEST(freeSurface, disc2D)
{
    const scalar dp = 0.01, R = 0.2;
    const particleBody water = lattice("water", 2, dp, {-R, -R, 0},
        {R, R, 0}, [&](const point& x) { return mag(x) < R; });
    const freeSurface fs = surfaceOf({&water});
    expectClosed(fs.mesh);
    EXPECT_NEAR(fs.enclosed, fs.particleVolume, 0.005*fs.particleVolume);
    // The radius of a disc of the particles' area.
    expectRound(fs.mesh, std::sqrt(fs.particleVolume/M_PI), dp);
    // Each segment's outward normal (q - p) x z points away from the
    // centre.
    for (std::size_t c = 0; c < fs.mesh.nCells(); ++c)
    {
        const point& a = fs.mesh.points[fs.mesh.connectivity[2*c]];
        const point& b = fs.mesh.points[fs.mesh.connectivity[2*c + 1]];
        const vec3 out{scalar(b.y - a.y), scalar(a.x - b.x), 0};
        EXPECT_GT(dot(out, toVec3(0.5*(a + b))), 0);
    }
}

// A 3D block and two fluid bodies side by side: one closed surface round
// both, its faces on the block's faces (to 0.05 dp). The kernel sum rounds
// the block's edges (at an edge only a quarter of the support holds
// fluid): the volume lost is at most that of edges rounded to the
// support's radius 2h, (1 - pi/4) (2h)^2 a unit length.
TEST(freeSurface, blocks3D)
{
    const scalar dp = 0.02;
    const particleBody left = lattice("left", 3, dp, {0, 0, 0},
        {0.2, 0.2, 0.3}, [](const point&) { return true; });
    const particleBody right = lattice("right", 3, dp, {0.2, 0, 0},
        {0.4, 0.2, 0.3}, [](const point&) { return true; });
    const freeSurface fs = surfaceOf({&left, &right});
    const vtpMesh& m = fs.mesh;
    EXPECT_EQ(m.nodesPerCell, 3);
    EXPECT_NEAR(fs.particleVolume, 0.4*0.2*0.3, 0.024*roundRel);
    const double edges = 4*(0.4 + 0.2 + 0.3), h = 1.5*dp;
    const double rounded = (1 - M_PI/4)*(4*h*h)*edges;
    EXPECT_LT(fs.enclosed, fs.particleVolume);
    EXPECT_GT(fs.enclosed, fs.particleVolume - rounded);
    expectClosed(m);
    std::size_t onTop = 0;
    for (const point& x : m.points)
    {
        if (x.z > 0.2 && x.x > 3*dp && x.x < 0.4 - 3*dp && x.y > 3*dp
         && x.y < 0.2 - 3*dp)
        {
            EXPECT_NEAR(x.z, 0.3, 0.05*dp);
            ++onTop;
        }
        // Nothing beyond the fluid's reach.
        EXPECT_GT(x.x, -dp);
        EXPECT_LT(x.z, 0.3 + dp);
    }
    EXPECT_GT(onTop, 50u);
    // Finer grid: the same volume, more triangles.
    freeSurfaceSettings fine;
    fine.refine = 2;
    const freeSurface fsFine = surfaceOf({&left, &right}, fine);
    EXPECT_NEAR(fsFine.enclosed, fs.enclosed, 0.005*fs.enclosed);
    EXPECT_GT(fsFine.mesh.nCells(), 3*m.nCells());
}

// A ball: normals and triangles face out, the points within half a
// particle of the lattice ball's edge (0.1 dp on average); a lower level
// encloses more.
TEST(freeSurface, ball3D)
{
    const scalar dp = 0.02, R = 0.2;
    const particleBody water = lattice("water", 3, dp, {-R, -R, -R},
        {R, R, R}, [&](const point& x) { return mag(x) < R; });
    const freeSurface fs = surfaceOf({&water});
    expectClosed(fs.mesh);
    expectRound(fs.mesh, std::cbrt(3*fs.particleVolume/(4*M_PI)), dp);
    const auto& c = fs.mesh.connectivity;
    std::size_t outward = 0;
    for (std::size_t t = 0; t < fs.mesh.nCells(); ++t)
    {
        const point& a = fs.mesh.points[c[3*t]];
        const point& b = fs.mesh.points[c[3*t + 1]];
        const point& d = fs.mesh.points[c[3*t + 2]];
        outward += dot(cross(b - a, d - a), (a + b + d)/3.0) > 0;
    }
    EXPECT_EQ(outward, fs.mesh.nCells());

    freeSurfaceSettings low;
    low.level = 0.2;
    EXPECT_GT(surfaceOf({&water}, low).enclosed, 1.05*fs.enclosed);
}

TEST(freeSurface, noFluidAndBadSettings)
{
    const freeSurface none = fluidFreeSurface({}, kernelType::wendlandC2,
                                              0.015, {});
    EXPECT_EQ(none.mesh.nCells(), 0u);
    EXPECT_EQ(none.mesh.points.size(), 0u);

    const particleBody water = lattice("water", 2, 0.01, {0, 0, 0},
        {0.1, 0.1, 0}, [](const point&) { return true; });
    for (const scalar level : {0.0, 1.0, -0.5, std::nan("")})
    {
        freeSurfaceSettings s;
        s.level = level;
        expectMessage(catchFatal([&] { surfaceOf({&water}, s); }),
                      {"level", "is not in (0, 1)"});
    }
    // A particle flung far away would make a huge grid: an error naming
    // it, not gigabytes; no coarser grid would do (1e12 nodes).
    particleBody far = water;
    far.append({1e6, 1e6, 0});
    far.scalarField("mass").back() = 0.1;
    far.scalarField("rho").back() = rho0;
    const FatalError err = catchFatal([&] { surfaceOf({&far}); });
    expectMessage(err, {"grid would have", "farthest from its median point",
                        "are at (1000000 1000000 0) (90 % lie within",
                        "look for particles far from the rest."});
    EXPECT_EQ(err.message().find("-surfaceRefine"), std::string::npos);
    // One 1 m away, over a grid of at most 20,000 nodes: at dp/2 it would
    // have about 45,000, at dp about 11,000, so the coarser grid is named.
    particleBody near = water;
    near.append({1, 1, 0});
    near.scalarField("mass").back() = 0.1;
    near.scalarField("rho").back() = rho0;
    freeSurfaceSettings small;
    small.maxNodes = 20000;
    expectMessage(catchFatal([&] { surfaceOf({&near}, small); }),
                  {"are at (1 1 0) (90 % lie within", "or use a coarser grid"
                   " (-surfaceRefine 1)."});
    small.refine = 1;
    EXPECT_GT(surfaceOf({&near}, small).mesh.nCells(), 0u);
    // No volume: named.
    particleBody empty = water;
    empty.scalarField("rho")[3] = 0;
    expectMessage(catchFatal([&] { surfaceOf({&empty}); }),
                  {"Fluid body 'water'", "no volume"});
}
