/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Nearest point of plane segments within a radius over a uniform grid.

#include "segmentDistance.H"
#include "binLists.H"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sphvcpm
{

namespace
{

// Cells in all, at most (as for triSurfaceDistance).
constexpr scalar maxCells = 8e6;

} // End anonymous namespace


vec3 segmentDistance::nearestOnSegment
(
    const vec3& p,
    const vec3& a,
    const vec3& b
)
{
    const vec3 ab = b - a;
    const scalar len2 = dot(ab, ab);
    const scalar t = len2 > 0
        ? std::clamp(dot(p - a, ab)/len2, scalar(0), scalar(1))
        : scalar(0);
    return a + t*ab;
}


segmentDistance::segmentDistance
(
    const std::vector<planarRegion::segment>& segments,
    scalar radius
)
:
    radius_(radius)
{
    boundBox b = boundBox::invalid();
    for (const planarRegion::segment& s : segments)
    {
        a_.push_back({s.x0, s.y0, 0});
        b_.push_back({s.x1, s.y1, 0});
        const vec3 n{s.y1 - s.y0, s.x0 - s.x1, 0};
        const scalar len = mag(n);
        normals_.push_back(len > 0 ? n/len : vec3{0, 0, 0});
        b.add(a_.back());
        b.add(b_.back());
    }
    if (!b.valid() || !(radius_ >= 0) || !std::isfinite(radius_))
    {
        start_.assign(2, 0);
        return;
    }
    const vec3 grow{radius_, radius_, 0};
    origin_ = b.min - grow;
    const vec3 span = b.max + grow - origin_;

    // Cells of the radius (a query reads one cell), larger when there
    // would be too many.
    scalar h = std::max(radius_, vSmall);
    h = std::max(h, std::sqrt(std::max(span.x, h)*std::max(span.y, h)
                              /maxCells));
    if (!std::isfinite(h) || !std::isfinite(mag(span)))
    {
        h = std::numeric_limits<scalar>::max();
    }
    invCell_ = 1/h;
    for (int d = 0; d < 2; ++d)
    {
        const scalar n = std::ceil(span[d]*invCell_);
        n_[d] = std::isfinite(n)
            ? std::clamp<std::int64_t>(std::int64_t(std::min(n, scalar(1e7))), 1,
                                       10000000)
            : 1;
    }

    // A cell of the segment's box that the segment does not come near is
    // skipped: no point of the cell is within radius when its centre is
    // farther than radius plus half the cell's diagonal.
    const scalar reach = radius_ + 0.5*std::sqrt(scalar(2))*h;
    buildBinLists(n_[0]*n_[1], a_.size(),
        [&](const std::size_t si, const auto& visit)
        {
            std::int64_t lo[2], hi[2];
            for (int d = 0; d < 2; ++d)
            {
                const scalar x0 = std::min(a_[si][d], b_[si][d]) - radius_;
                const scalar x1 = std::max(a_[si][d], b_[si][d]) + radius_;
                lo[d] = std::clamp<std::int64_t>(cell(x0, d), 0, n_[d] - 1);
                hi[d] = std::clamp<std::int64_t>(cell(x1, d), 0, n_[d] - 1);
            }
            for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
            {
                for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
                {
                    const vec3 c = origin_ + h*vec3{scalar(i + 0.5), scalar(j + 0.5), 0};
                    const scalar d2 =
                        magSqr(c - nearestOnSegment(c, a_[si], b_[si]));
                    if (!(d2 > reach*reach))    // NaN (overflow): keep it
                    {
                        visit(j*n_[0] + i);
                    }
                }
            }
        },
        start_, items_);
}


std::int64_t segmentDistance::cell(scalar x, int d) const
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


segmentDistance::nearest segmentDistance::find(const vec3& p3) const
{
    nearest best;
    const vec3 p{p3.x, p3.y, 0};
    std::int64_t c[2];
    for (int d = 0; d < 2; ++d)
    {
        c[d] = cell(p[d], d);
        if (c[d] < 0 || c[d] >= n_[d])
        {
            return best;
        }
    }
    const std::int64_t id = c[1]*n_[0] + c[0];

    // Ties within a relative 1e-9 of the radius are the same distance:
    // the segment the point faces most squarely breaks them.
    const scalar tie = 1e-9*radius_;
    scalar bestFacing = -1;
    for (std::int64_t k = start_[id]; k < start_[id + 1]; ++k)
    {
        const label si = items_[k];
        const vec3 q = nearestOnSegment(p, a_[si], b_[si]);
        const scalar dist = mag(p - q);
        if (dist > radius_)
        {
            continue;
        }
        const scalar s = dot(p - q, normals_[si]);
        const scalar facing = std::abs(s);
        if
        (
            best.segment < 0 || dist < best.distance - tie
         || (dist <= best.distance + tie && facing > bestFacing)
        )
        {
            best.segment = si;
            best.distance = dist;
            best.point = q;
            best.side = s > 0 ? 1 : (s < 0 ? -1 : 0);
            bestFacing = facing;
        }
    }
    return best;
}

} // End namespace sphvcpm
