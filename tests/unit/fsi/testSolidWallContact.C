/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The solid-wall contact (solidWallContact.H, docs/fsi.md): the half-space
// profile of the walls' volume fraction against its definition and against
// lattice sums over a flat wall; the contact plane of single solid
// particles, among them one on the outer wall row between two wall
// particles, where a pairwise contact's pushes cancel; the sub-step's stop
// at a plane.

#include "cellList.H"
#include "parallel.H"
#include "solidWallContact.H"
#include "sphKernels.H"
#include "../testPrecision.H"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

using namespace sphvcpm;

namespace
{

// The walls' volume fraction at height s above the outer row (y = 0) of
// a flat wall of spacing 1 whose rows go down past the support, with the
// point shifted by `along` from a column of wall particles.
template<class Kernel>
scalar flatWallFraction(const Kernel& k, const int nDim, const scalar s,
                        const scalar along)
{
    const int reach = int(std::ceil(k.support())) + 1;
    scalar phi = 0;
    for (int row = 0; row <= reach; ++row)
    {
        for (int a = -reach; a <= reach; ++a)
        {
            for (int b = (nDim == 3 ? -reach : 0);
                 b <= (nDim == 3 ? reach : 0); ++b)
            {
                const scalar x = a - along, z = b - (nDim == 3 ? along : 0);
                phi += k.W(std::sqrt(x*x + z*z + (s + row)*(s + row)));
            }
        }
    }
    return phi;
}

template<class Kernel>
void checkProfile(const std::string& name)
{
    for (const int nDim : {2, 3})
    {
        for (const scalar hOverDp : {1.3, 1.5, 2.0})
        {
            SCOPED_TRACE(name + " " + std::to_string(nDim) + "D, h/dp "
                         + std::to_string(hOverDp));
            const Kernel k(hOverDp, nDim);
            const wallContactProfile p = makeWallContactProfile(k, nDim, 1);
            // h deep in the wall the fraction is nearly the lattice sum of
            // the kernel, 1; on its surface one half; h outside it little.
            EXPECT_NEAR(p.fraction(-hOverDp), 1.0, 0.06);
            EXPECT_NEAR(p.fraction(0), 0.5, 0.01);
            EXPECT_LT(p.fraction(hOverDp), 0.1);
            for (int i = 0; i < wallContactProfile::n; ++i)
            {
                EXPECT_GT(p.phi[i], p.phi[i + 1]) << "entry " << i;
            }
            for (const scalar g : {-0.9, -0.2, 0.0, 0.15, 0.4, 0.95})
            {
                EXPECT_NEAR(p.gap(p.fraction(g*hOverDp)), g*hOverDp,
                            test::tol(1e-9, 1e-5));
            }
            // Over a lattice wall, the gap to its surface (half a spacing
            // beyond the outer row) is read from the fraction to within a
            // few hundredths of a spacing, wherever the point lies along
            // the rows: the contact surface is flat.
            for (const scalar s : {0.0, 0.25, 0.5, 0.625, 0.75, 1.0})
            {
                for (const scalar along : {0.0, 0.25, 0.5})
                {
                    const scalar gap =
                        p.gap(flatWallFraction(k, nDim, s, along));
                    EXPECT_NEAR(gap, s - 0.5, 0.03)
                        << "s = " << s << ", along = " << along;
                }
            }
        }
    }
}


// Three rows of wall particles (2D, spacing dp) below y = 0 and one solid
// particle of spacing dp/4 at x; returns its contact plane.
contactPlane planeAt(const vec3 x)
{
    const scalar dp = 0.01, dpSolid = dp/4, rho0 = 1000;
    const wendlandC2Kernel k(1.5*dp, 2);
    particleFields f;
    const int nx = 20, rows = 3;
    const label n = nx*rows + 1;
    f.resize(n, false, false);
    f.link.assign(n, 0);              // the solid particle is the only one
    for (label m = 0; m < n; ++m)
    {
        const bool solid = m == n - 1;
        f.position[m] = solid ? x : vec3{(m % nx - nx/2)*dp, -(m/nx)*dp, 0};
        f.velocity[m] = {0, 0, 0};
        f.mass[m] = solid ? rho0*dpSolid*dpSolid : rho0*dp*dp;
        f.rho[m] = rho0;
        f.kind[m] = solid ? solidKind : wallKind;
        f.body[m] = solid ? 1 : 0;
        f.id[m] = m;
    }
    const cellGrid grid = makeCellGrid({-(nx/2 + 1)*dp, -(rows + 1)*dp, 0},
        {(nx/2 + 1)*dp, 4*dp, 0}, k.support(), 1, 2);
    cellList list;
    buildCellList(openmpExec{}, grid, f.position.data(), n, list);
    EXPECT_EQ(list.nInside, n);
    f.reorder(list.order, list.nInside, false, false);
    contactPlane plane{{-1, -1, -1}, {-1, -1, -1}};
    parallelFor(openmpExec{}, n, wallContactPlaneOp<wendlandC2Kernel>{k,
        grid, list.cellStart.data(), f.view(), makeWallContactProfile(k, 2, dp),
        rho0, scalar(0.5), k.support()*k.support(), &plane});
    return plane;
}

// One sub-step of a free particle with the given contact plane, from x
// at velocity u with no force; returns its position and velocity.
std::pair<vec3, vec3> stepAgainst(const contactPlane& plane, vec3 x, vec3 u,
                                  const scalar dt)
{
    const vec3 force{0, 0, 0}, clampVelocity{0, 0, 0};
    const std::uint8_t clamped = 0;
    kickDriftOp{dt, 1, 0, &force, &clamped, &clampVelocity, &x, &u,
                bodyMove::none(), &plane}(0);
    return {x, u};
}

} // End anonymous namespace


TEST(solidWallContact, profileMatchesFlatLatticeWalls)
{
    checkProfile<wendlandC2Kernel>("wendlandC2");
    checkProfile<cubicSplineKernel>("cubicSpline");
}


TEST(solidWallContact, planeOfTheSmoothedWallEverywhere)
{
    // The wall's surface is y = dp/2 = 0.005 above the outer row; the
    // contact surface is dp_s/2 = 0.00125 further, y = 0.00625; planes are
    // set within dp_s/2 more, below y = 0.0075.
    for (const scalar x : {0.0, 0.0025, 0.005})      // on, off, between rows
    {
        SCOPED_TRACE("x = " + std::to_string(x));
        EXPECT_EQ(mag(planeAt({x, 0.008, 0}).normal), 0);
        // Near contact, on the outer row, and between two wall particles
        // (x = 0.005), where pairwise pushes along the rows cancel: the
        // plane is the contact surface to within 0.03 dp, its normal
        // within 3 degrees of the wall's (the rows' ripple tilts the
        // gradient off the symmetric points).
        for (const scalar y : {0.007, 0.005, 0.0})
        {
            const contactPlane c = planeAt({x, y, 0});
            EXPECT_NEAR(mag(c.normal), 1, 1e-12) << "y = " << y;
            EXPECT_GT(c.normal.y, std::cos(3*M_PI/180)) << "y = " << y;
            EXPECT_NEAR(c.point.y, 0.00625, 0.0003) << "y = " << y;
        }
    }
}


TEST(solidWallContact, subStepsStopAtThePlane)
{
    const contactPlane floor{{0, 0.00625, 0}, {0, 1, 0}};
    // Moving into it: put back on it, the approach speed gone, the
    // sliding speed kept.
    auto [x, u] = stepAgainst(floor, {0.1, 0.0063, 0}, {0.3, -1, 0}, 1e-3);
    EXPECT_DOUBLE_EQ(x.y, 0.00625);
    EXPECT_NEAR(x.x, 0.1003, 1e-12);
    EXPECT_EQ(u.y, 0);
    EXPECT_EQ(u.x, 0.3);
    // Moving away, or not reaching it: free.
    std::tie(x, u) = stepAgainst(floor, {0.1, 0.0063, 0}, {0, 1, 0}, 1e-3);
    EXPECT_NEAR(x.y, 0.0073, 1e-12);
    std::tie(x, u) = stepAgainst(floor, {0.1, 0.008, 0}, {0, -1, 0}, 1e-3);
    EXPECT_NEAR(x.y, 0.007, 1e-12);
    EXPECT_EQ(u.y, -1);
    // No plane (zero normal): free.
    std::tie(x, u) = stepAgainst({{0, 0.00625, 0}, {0, 0, 0}},
                                 {0.1, 0.0063, 0}, {0, -1, 0}, 1e-3);
    EXPECT_NEAR(x.y, 0.0053, 1e-12);
}
