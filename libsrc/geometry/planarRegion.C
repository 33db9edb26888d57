/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Even-odd region of line segments in the x-y plane.

#include "planarRegion.H"
#include "binLists.H"

#include <algorithm>
#include <cmath>
#include <map>

namespace sphvcpm
{

namespace
{

// Whether the line along axis through v (the other coordinate) crosses s,
// and where along the axis.
inline bool crossing
(
    const planarRegion::segment& s,
    int axis,
    scalar v,
    scalar& u
)
{
    const scalar u0 = axis == 0 ? s.x0 : s.y0;
    const scalar u1 = axis == 0 ? s.x1 : s.y1;
    const scalar v0 = axis == 0 ? s.y0 : s.x0;
    const scalar v1 = axis == 0 ? s.y1 : s.x1;
    if ((v0 <= v) == (v1 <= v))
    {
        return false;
    }
    const scalar t = (v - v0)/(v1 - v0);
    u = u0 + t*(u1 - u0);
    return true;
}

} // End anonymous namespace


planarRegion::planarRegion(std::vector<segment> segments)
:
    segments_(std::move(segments)),
    bounds_(boundBox::invalid())
{
    for (const segment& s : segments_)
    {
        bounds_.add(vec3{s.x0, s.y0, 0});
        bounds_.add(vec3{s.x1, s.y1, 0});
    }
    binSegments(0);
    binSegments(1);
}


void planarRegion::binSegments(int axis)
{
    bins& b = bins_[axis];
    const int across = 1 - axis;
    if
    (
        segments_.empty()
     || !std::isfinite(bounds_.max[across] - bounds_.min[across])
    )
    {
        b.n = 1;
        b.start.assign(2, 0);
        b.items.resize(segments_.size());
        for (std::size_t i = 0; i < b.items.size(); ++i)
        {
            b.items[i] = i;
        }
        b.start[1] = std::int64_t(b.items.size());
        return;
    }

    // About one segment per bin.
    const scalar h = bounds_.max[across] - bounds_.min[across];
    b.n = std::clamp<std::int64_t>(std::int64_t(segments_.size()), 1,
                                   1 << 20);
    b.lo = bounds_.min[across];
    b.invH = h > 0 ? scalar(b.n)/h : 0;
    const auto clamped = [&](scalar v)
    {
        const scalar r = std::floor((v - b.lo)*b.invH);
        return std::clamp<std::int64_t>(r >= 0 ? std::int64_t(std::min(
            r, scalar(b.n))) : 0, 0, b.n - 1);
    };
    buildBinLists(b.n, segments_.size(),
        [&](const std::size_t i, const auto& visit)
        {
            const segment& s = segments_[i];
            const scalar v0 = across == 1 ? s.y0 : s.x0;
            const scalar v1 = across == 1 ? s.y1 : s.x1;
            const std::int64_t lo = clamped(std::min(v0, v1));
            const std::int64_t hi = clamped(std::max(v0, v1));
            for (std::int64_t r = lo; r <= hi; ++r)
            {
                visit(r);
            }
        },
        b.start, b.items);
}


std::int64_t planarRegion::bins::of(scalar v) const
{
    if (n == 1)
    {
        return 0;
    }
    const scalar f = std::floor((v - lo)*invH);
    if (!(f >= 0 && f < scalar(n)))
    {
        return -1;
    }
    return std::int64_t(f);
}


void planarRegion::crossings(scalar y, std::vector<scalar>& xs) const
{
    xs.clear();
    const bins& b = bins_[0];
    const std::int64_t r = b.of(y);
    if (r < 0)
    {
        return;
    }
    for (std::int64_t k = b.start[r]; k < b.start[r + 1]; ++k)
    {
        scalar x;
        if (crossing(segments_[b.items[k]], 0, y, x))
        {
            xs.push_back(x);
        }
    }
}


bool planarRegion::parity(scalar x, scalar y, int axis) const
{
    const scalar u = axis == 0 ? x : y;
    const scalar v = axis == 0 ? y : x;
    const int across = 1 - axis;
    if (!(v >= bounds_.min[across] && v <= bounds_.max[across]))
    {
        return false;
    }
    const bins& b = bins_[axis];
    const std::int64_t r = b.n > 1
        ? std::clamp<std::int64_t>
          (
              std::int64_t(std::floor((v - b.lo)*b.invH)), 0, b.n - 1
          )
        : 0;
    int n = 0;
    for (std::int64_t k = b.start[r]; k < b.start[r + 1]; ++k)
    {
        scalar uc;
        n += crossing(segments_[b.items[k]], axis, v, uc) && uc > u;
    }
    return n & 1;
}


scalar planarRegion::area() const
{
    std::vector<scalar> ys;
    ys.reserve(2*segments_.size());
    for (const segment& s : segments_)
    {
        ys.push_back(s.y0);
        ys.push_back(s.y1);
    }
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());

    scalar a = 0;
    std::vector<scalar> xs;
    for (std::size_t i = 0; i + 1 < ys.size(); ++i)
    {
        const scalar y = 0.5*(ys[i] + ys[i + 1]);
        crossings(y, xs);
        std::sort(xs.begin(), xs.end());
        scalar width = 0;
        for (std::size_t k = 0; k + 1 < xs.size(); k += 2)
        {
            width += xs[k + 1] - xs[k];
        }
        a += width*(ys[i + 1] - ys[i]);
    }
    return a;
}


std::size_t planarRegion::nOpenEnds() const
{
    std::map<std::array<scalar, 2>, int> ends;
    for (const segment& s : segments_)
    {
        ++ends[{s.x0, s.y0}];
        ++ends[{s.x1, s.y1}];
    }
    std::size_t n = 0;
    for (const auto& e : ends)
    {
        n += e.second & 1;
    }
    return n;
}

} // End namespace sphvcpm
