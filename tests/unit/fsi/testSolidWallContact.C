/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The solid-wall contact (solidWallContact.H, docs/fsi.md): the contact
// plane of single solid particles over a flat wall, also on the outer wall
// row between two wall particles, where a pairwise contact's pushes cancel,
// and next to a side wall in an inner corner, where the floor must not
// count; the sub-step's stop at a plane.

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

// Three rows of floor particles (2D, spacing dp) below y = 0, from x =
// -0.13 to 0.09; with a side wall, three columns of it at x = -0.11 to
// -0.13 up to y = 0.05 (its surface at x = -0.105). One solid particle of
// spacing dp/4 at x; returns its contact plane.
contactPlane planeAt(const point x, const bool sideWall = false)
{
    const scalar dp = 0.01, dpSolid = dp/4, rho0 = 1000;
    const wendlandC2Kernel k(1.5*dp, 2);
    std::vector<point> walls;
    for (int row = 0; row < 3; ++row)
    {
        for (int col = -13; col < 10; ++col)
        {
            walls.push_back({col*dp, -row*dp, 0});
        }
    }
    for (int col = 11; sideWall && col <= 13; ++col)
    {
        for (int row = 1; row <= 5; ++row)
        {
            walls.push_back({-col*dp, row*dp, 0});
        }
    }
    particleFields f;
    const label n = label(walls.size()) + 1;
    f.resize(n, false, false);
    f.link.assign(n, 0);              // the solid particle is the only one
    for (label m = 0; m < n; ++m)
    {
        const bool solid = m == n - 1;
        f.position[m] = solid ? x : walls[m];
        f.velocity[m] = {0, 0, 0};
        f.mass[m] = solid ? rho0*dpSolid*dpSolid : rho0*dp*dp;
        f.rho[m] = rho0;
        f.kind[m] = solid ? solidKind : wallKind;
        f.body[m] = solid ? 1 : 0;
        f.id[m] = m;
    }
    const cellGrid grid = makeCellGrid({-0.15, -0.04, 0}, {0.11, 0.08, 0},
                                       k.support(), 1, 2);
    cellList list;
    buildCellList(openmpExec{}, grid, f.position.data(), f.kind.data(), n,
                  list);
    EXPECT_EQ(list.nInside, n);
    f.reorder(list.order, list.nInside, false, false);
    contactPlane plane{{-1, -1, -1}, {-1, -1, -1}};
    parallelFor(openmpExec{}, n, wallContactPlaneOp<wendlandC2Kernel>{k,
        grid, list.cellStart.data(), list.kindEnd.data(), f.view(), rho0, scalar(0.5),
        k.support()*k.support(), &plane});
    return plane;
}

// One sub-step of a free particle with the given contact plane, from x
// at velocity u with no force; returns its position and velocity.
std::pair<point, vec3> stepAgainst(const contactPlane& plane, point x,
                                   vec3 u, const scalar dt)
{
    const vec3 force{0, 0, 0}, clampVelocity{0, 0, 0};
    const std::uint8_t clamped = 0;
    kickDriftOp{dt, 1, 0, &force, &clamped, &clampVelocity, &x, &u,
                bodyMove::none(), &plane}(0);
    return {x, u};
}

} // End anonymous namespace


TEST(solidWallContact, planeOfTheSmoothedWallEverywhere)
{
    SPHVCPM_DOUBLE_ONLY();   // positions to 1e-12
    // The wall's surface is y = dp/2 = 0.005 above the outer row; the
    // contact surface is dp_s/2 = 0.00125 further, y = 0.00625, above a
    // wall particle, and dips to y = sqrt(0.00625^2 - 0.005^2) = 0.00375
    // midway between two (contact with the nearest wall particle).
    EXPECT_EQ(mag(planeAt({0, 0.009, 0}).normal), 0);
    EXPECT_NEAR(planeAt({0, 0.007, 0}).planePoint.y, 0.00625, 1e-9);
    for (const scalar x : {0.0, 0.0025, 0.005})      // on, off, between rows
    {
        SCOPED_TRACE("x = " + std::to_string(x));
        // Near contact and on the outer row, also between two wall
        // particles (x = 0.005), where pairwise pushes along the rows
        // cancel: the normal within 3 degrees of the wall's (the rows'
        // ripple tilts the gradient off the symmetric points), the plane
        // below the contact surface's top and, on the outer row, well
        // ahead of the particle.
        for (const scalar y : {0.005, 0.0})
        {
            const contactPlane c = planeAt({x, y, 0});
            EXPECT_NEAR(mag(c.normal), 1, 1e-12) << "y = " << y;
            EXPECT_GT(c.normal.y, std::cos(3*M_PI/180)) << "y = " << y;
            if (y == 0) EXPECT_GT(c.planePoint.y, 0.001) << "pushed out";
            EXPECT_LT(c.planePoint.y, 0.00625 + 1e-9) << "y = " << y;
        }
    }
    EXPECT_NEAR(planeAt({0.005, 0.005, 0}).planePoint.y,
                0.005 - (std::sqrt(0.005*0.005 + 0.005*0.005) - 0.00625),
                1e-6);
}


TEST(solidWallContact, innerCornerCountsTheNearWallOnly)
{
    // A solid particle at contact with a side wall (surface x = -0.105,
    // contact x = -0.10375) 0.4 and 1.5 spacings above the floor's
    // surface: its plane faces the side wall and lies at the particle, not
    // ahead of it (a gap read from the summed volume fraction would see
    // the floor too and push the particle off the side wall).
    for (const scalar y : {0.009, 0.02})
    {
        SCOPED_TRACE("y = " + std::to_string(y));
        const point x{-0.10375, y, 0};
        const contactPlane c = planeAt(x, true);
        ASSERT_NEAR(mag(c.normal), 1, 1e-12);
        EXPECT_GT(c.normal.x, std::cos(M_PI/4));
        EXPECT_GT(dot(toVec3(x - c.planePoint), c.normal), -0.0003);
        EXPECT_LT(dot(toVec3(x - c.planePoint), c.normal), 0.0015);
    }
}


TEST(solidWallContact, subStepsStopAtThePlane)
{
    SPHVCPM_DOUBLE_ONLY();   // positions to 1e-12
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
