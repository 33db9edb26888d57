/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Ray parity along the three axes over per-axis 2D bins of triangles.

#include "triSurfaceInside.H"
#include "binLists.H"

#include <algorithm>
#include <cmath>

namespace sphvcpm
{

namespace
{

// Twice the signed area of (a, b, q), always computed from the
// lexicographically smaller end of the edge so that the two triangles that
// share an edge get exactly opposite values. positive: q is on the left;
// a point on the line counts as on the left of the edge's lexicographic
// direction, which is moving q by (-e^2, e) for an infinitesimal e: every
// tie is then decided as for a point in general position.
inline scalar edgeFunction
(
    scalar au, scalar av, scalar bu, scalar bv, scalar qu, scalar qv,
    bool& positive
)
{
    const bool forward = au < bu || (au == bu && av < bv);
    const scalar e = forward
        ? (bu - au)*(qv - av) - (bv - av)*(qu - au)
        : -((au - bu)*(qv - bv) - (av - bv)*(qu - bu));
    positive = e > 0 || (e == 0 && forward);
    return e;
}


// Bin of a coordinate already scaled to bin units, clamped to [0, n) and
// safe for NaN and overflow (a cast of those would be undefined).
inline std::int64_t clampedBin(scalar x, std::int64_t n)
{
    if (!(x >= 0))
    {
        return 0;
    }
    if (!(x < scalar(n)))
    {
        return n - 1;
    }
    return std::int64_t(x);
}

} // End anonymous namespace


triSurfaceInside::triSurfaceInside(const triSurface& surf)
:
    bounds_(surf.bounds())
{
    for (int axis = 0; axis < 3; ++axis)
    {
        build(surf, axis);
    }
}


void triSurfaceInside::build(const triSurface& surf, int axis)
{
    axisGrid& g = grids_[axis];
    g.u = (axis + 1) % 3;
    g.v = (axis + 2) % 3;

    g.triangles.clear();
    g.triangles.reserve(surf.size());
    for (const triSurface::face& f : surf.faces())
    {
        projected t;
        for (int i = 0; i < 3; ++i)
        {
            const vec3& p = surf.points()[f[i]];
            t.u[i] = p[g.u];
            t.v[i] = p[g.v];
            t.w[i] = p[axis];
        }
        const scalar area2 = (t.u[1] - t.u[0])*(t.v[2] - t.v[0])
                           - (t.v[1] - t.v[0])*(t.u[2] - t.u[0]);
        // Seen edge-on: no ray along this axis crosses it (its neighbours
        // count the crossing).
        if (area2 == 0)
        {
            continue;
        }
        if (area2 < 0)
        {
            std::swap(t.u[1], t.u[2]);
            std::swap(t.v[1], t.v[2]);
            std::swap(t.w[1], t.w[2]);
        }
        g.triangles.push_back(t);
    }

    if (!bounds_.valid())
    {
        g.start.assign(2, 0);
        return;
    }

    // Bins over the projected bounds, padded so that a point outside the
    // bins lies outside every triangle's projection.
    const scalar eu0 = bounds_.max[g.u] - bounds_.min[g.u];
    const scalar ev0 = bounds_.max[g.v] - bounds_.min[g.v];
    const scalar pad = 1e-6*std::max(std::hypot(eu0, ev0), vSmall);
    g.u0 = bounds_.min[g.u] - pad;
    g.v0 = bounds_.min[g.v] - pad;
    const scalar eu = eu0 + 2*pad;
    const scalar ev = ev0 + 2*pad;

    // About one triangle per bin, fewer bins when long triangles would
    // make the bin lists much longer than the triangle list.
    // (A degenerate or overflowing extent gets one bin.)
    const scalar nTarget = std::max<scalar>(1, scalar(g.triangles.size()));
    const scalar cell = std::sqrt(eu/nTarget)*std::sqrt(ev);
    const bool usable = std::isfinite(eu) && std::isfinite(ev)
        && std::isfinite(cell) && cell > 0;
    g.nu = usable ? 1 + clampedBin(eu/cell, 4096) : 1;
    g.nv = usable ? 1 + clampedBin(ev/cell, 4096) : 1;

    const auto binRange = [&](const projected& t, std::int64_t lo[2],
                              std::int64_t hi[2])
    {
        const scalar uMin = std::min({t.u[0], t.u[1], t.u[2]});
        const scalar uMax = std::max({t.u[0], t.u[1], t.u[2]});
        const scalar vMin = std::min({t.v[0], t.v[1], t.v[2]});
        const scalar vMax = std::max({t.v[0], t.v[1], t.v[2]});
        lo[0] = clampedBin((uMin - g.u0)*g.invDu, g.nu);
        hi[0] = clampedBin((uMax - g.u0)*g.invDu, g.nu);
        lo[1] = clampedBin((vMin - g.v0)*g.invDv, g.nv);
        hi[1] = clampedBin((vMax - g.v0)*g.invDv, g.nv);
    };

    const std::int64_t maxItems =
        16*std::int64_t(g.triangles.size()) + 1000000;
    while (true)
    {
        g.invDu = usable ? scalar(g.nu)/eu : 0;
        g.invDv = usable ? scalar(g.nv)/ev : 0;
        std::int64_t nItems = 0;
        for (const projected& t : g.triangles)
        {
            std::int64_t lo[2], hi[2];
            binRange(t, lo, hi);
            nItems += (hi[0] - lo[0] + 1)*(hi[1] - lo[1] + 1);
        }
        if (nItems <= maxItems || (g.nu == 1 && g.nv == 1))
        {
            break;
        }
        g.nu = std::max<std::int64_t>(1, g.nu/2);
        g.nv = std::max<std::int64_t>(1, g.nv/2);
    }

    // Bin lists (compressed rows).
    buildBinLists(g.nu*g.nv, g.triangles.size(),
        [&](const std::size_t ti, const auto& visit)
        {
            std::int64_t lo[2], hi[2];
            binRange(g.triangles[ti], lo, hi);
            for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
            {
                for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
                {
                    visit(j*g.nu + i);
                }
            }
        },
        g.start, g.items);
}


int triSurfaceInside::parity(const vec3& p, int axis) const
{
    const axisGrid& g = grids_[axis];
    const scalar qu = p[g.u];
    const scalar qv = p[g.v];
    const scalar bu = std::floor((qu - g.u0)*g.invDu);
    const scalar bv = std::floor((qv - g.v0)*g.invDv);
    if (!(bu >= 0 && bu < scalar(g.nu) && bv >= 0 && bv < scalar(g.nv)))
    {
        return 0;
    }
    const std::int64_t b = std::int64_t(bv)*g.nu + std::int64_t(bu);

    int n = 0;
    for (std::int64_t k = g.start[b]; k < g.start[b + 1]; ++k)
    {
        const projected& t = g.triangles[g.items[k]];
        bool in0, in1, in2;
        const scalar e0 =
            edgeFunction(t.u[1], t.v[1], t.u[2], t.v[2], qu, qv, in0);
        if (!in0)
        {
            continue;
        }
        const scalar e1 =
            edgeFunction(t.u[2], t.v[2], t.u[0], t.v[0], qu, qv, in1);
        if (!in1)
        {
            continue;
        }
        const scalar e2 =
            edgeFunction(t.u[0], t.v[0], t.u[1], t.v[1], qu, qv, in2);
        if (!in2)
        {
            continue;
        }
        // Where the ray meets the triangle (barycentric weights are the
        // edge functions; a tie's zero weight is exact).
        const scalar a0 = std::max<scalar>(e0, 0);
        const scalar a1 = std::max<scalar>(e1, 0);
        const scalar a2 = std::max<scalar>(e2, 0);
        const scalar sum = a0 + a1 + a2;
        const scalar w = sum > 0
            ? (a0*t.w[0] + a1*t.w[1] + a2*t.w[2])/sum
            : t.w[0];
        n += w > p[axis];
    }
    return n & 1;
}


bool triSurfaceInside::inside(const vec3& p) const
{
    for (int d = 0; d < 3; ++d)
    {
        if (!(p[d] >= bounds_.min[d] && p[d] <= bounds_.max[d]))
        {
            return false;
        }
    }
    const int x = parity(p, 0);
    const int y = parity(p, 1);
    if (x == y)
    {
        return x;
    }
    return parity(p, 2);
}

} // End namespace sphvcpm
