/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Nearest surface point within a radius over a uniform grid of triangles.

#include "triSurfaceDistance.H"
#include "binLists.H"
#include "segmentDistance.H"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sphvcpm
{

namespace
{

// Cells in all, at most: the grid's memory stays below about 64 MB.
constexpr scalar maxCells = 8e6;

} // End anonymous namespace


vec3 triSurfaceDistance::nearestOnTriangle
(
    const vec3& p,
    const vec3& a,
    const vec3& b,
    const vec3& c
)
{
    // The projection onto the plane when it falls inside the triangle
    // (all three sub-triangles turn the same way as the triangle),
    // otherwise the nearest point of the nearest edge.
    const vec3 n = cross(b - a, c - a);
    const scalar n2 = dot(n, n);
    if (n2 > 0)
    {
        const vec3 q = p - (dot(p - a, n)/n2)*n;
        if
        (
            dot(cross(b - a, q - a), n) >= 0
         && dot(cross(c - b, q - b), n) >= 0
         && dot(cross(a - c, q - c), n) >= 0
        )
        {
            return q;
        }
    }
    // The edges, as segmentDistance measures them.
    const vec3 ab = segmentDistance::nearestOnSegment(p, a, b);
    const vec3 bc = segmentDistance::nearestOnSegment(p, b, c);
    const vec3 ca = segmentDistance::nearestOnSegment(p, c, a);
    const scalar dab = magSqr(p - ab);
    const scalar dbc = magSqr(p - bc);
    const scalar dca = magSqr(p - ca);
    if (dab <= dbc && dab <= dca)
    {
        return ab;
    }
    return dbc <= dca ? bc : ca;
}


triSurfaceDistance::triSurfaceDistance(const triSurface& surf, scalar radius)
:
    radius_(radius),
    points_(surf.points()),
    faces_(surf.faces())
{
    normals_.reserve(faces_.size());
    for (const triSurface::face& f : faces_)
    {
        const vec3 n = cross(points_[f[1]] - points_[f[0]],
                             points_[f[2]] - points_[f[0]]);
        const scalar len = mag(n);
        normals_.push_back(len > 0 ? n/len : vec3{0, 0, 0});
    }

    boundBox b = surf.bounds();
    if (!b.valid() || !(radius_ >= 0) || !std::isfinite(radius_))
    {
        start_.assign(2, 0);
        return;
    }
    const vec3 grow{radius_, radius_, radius_};
    origin_ = b.min - grow;
    const vec3 span = b.max + grow - origin_;

    // Cells of the radius (a query reads one cell), larger when there
    // would be too many, and never far smaller than the triangles.
    scalar h = std::max(radius_, vSmall);
    const scalar volume = std::max(span.x, h)*std::max(span.y, h)
                         *std::max(span.z, h);
    h = std::max(h, std::cbrt(volume/maxCells));
    if (!std::isfinite(h) || !std::isfinite(mag(span)))
    {
        h = std::numeric_limits<scalar>::max();
    }
    invCell_ = 1/h;
    for (int d = 0; d < 3; ++d)
    {
        const scalar n = std::ceil(span[d]*invCell_);
        n_[d] = std::isfinite(n)
            ? std::clamp<std::int64_t>(std::int64_t(std::min(n, scalar(1e6))), 1,
                                       1000000)
            : 1;
    }

    const auto range = [&](const triSurface::face& f, std::int64_t lo[3],
                           std::int64_t hi[3])
    {
        for (int d = 0; d < 3; ++d)
        {
            const scalar a = std::min({points_[f[0]][d], points_[f[1]][d],
                                       points_[f[2]][d]}) - radius_;
            const scalar z = std::max({points_[f[0]][d], points_[f[1]][d],
                                       points_[f[2]][d]}) + radius_;
            lo[d] = std::clamp<std::int64_t>(cell(a, d), 0, n_[d] - 1);
            hi[d] = std::clamp<std::int64_t>(cell(z, d), 0, n_[d] - 1);
        }
    };

    // A cell of the triangle's box that the triangle does not come near
    // is skipped (a tilted triangle's box is mostly empty): no point of
    // the cell is within radius when its centre is farther than radius
    // plus half the cell's diagonal.
    const scalar reach = radius_ + 0.5*std::sqrt(scalar(3))*h;
    const auto near = [&](const triSurface::face& f, std::int64_t i,
                          std::int64_t j, std::int64_t k)
    {
        const vec3 c = origin_ + h*vec3{scalar(i + 0.5), scalar(j + 0.5), scalar(k + 0.5)};
        const scalar d2 = magSqr(c - nearestOnTriangle(c, points_[f[0]],
                                               points_[f[1]], points_[f[2]]));
        return !(d2 > reach*reach);     // NaN (overflow): keep it
    };

    buildBinLists(n_[0]*n_[1]*n_[2], faces_.size(),
        [&](const std::size_t fi, const auto& visit)
        {
            std::int64_t lo[3], hi[3];
            range(faces_[fi], lo, hi);
            for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
            {
                for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
                {
                    for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
                    {
                        if (near(faces_[fi], i, j, k))
                        {
                            visit((k*n_[1] + j)*n_[0] + i);
                        }
                    }
                }
            }
        },
        start_, items_);
}


std::int64_t triSurfaceDistance::cell(scalar x, int d) const
{
    const scalar c = std::floor((x - origin_[d])*invCell_);
    if (!(c >= 0))
    {
        return -1;
    }
    if (!(c < scalar(n_[d])))
    {
        return n_[d];
    }
    return std::int64_t(c);
}


triSurfaceDistance::nearest triSurfaceDistance::find(const vec3& p) const
{
    nearest best;
    std::int64_t c[3];
    for (int d = 0; d < 3; ++d)
    {
        c[d] = cell(p[d], d);
        if (c[d] < 0 || c[d] >= n_[d])
        {
            return best;
        }
    }
    const std::int64_t id = (c[2]*n_[1] + c[1])*n_[0] + c[0];

    // Ties within a relative 1e-9 of the radius are the same distance:
    // the triangle the point faces most squarely breaks them.
    const scalar tie = 1e-9*radius_;
    scalar bestFacing = -1;
    for (std::int64_t k = start_[id]; k < start_[id + 1]; ++k)
    {
        const label fi = items_[k];
        const triSurface::face& f = faces_[fi];
        const vec3 q = nearestOnTriangle(p, points_[f[0]], points_[f[1]],
                                         points_[f[2]]);
        const scalar dist = mag(p - q);
        if (dist > radius_)
        {
            continue;
        }
        const scalar facing = std::abs(dot(p - q, normals_[fi]));
        if
        (
            best.face < 0 || dist < best.distance - tie
         || (dist <= best.distance + tie && facing > bestFacing)
        )
        {
            const scalar s = dot(p - q, normals_[fi]);
            best.face = fi;
            best.distance = dist;
            best.point = q;
            best.side = s > 0 ? 1 : (s < 0 ? -1 : 0);
            bestFacing = facing;
        }
    }
    return best;
}

} // End namespace sphvcpm
