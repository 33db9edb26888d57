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

// Whether the horizontal line at y crosses s, and where.
inline bool crossing(const planarRegion::segment& s, scalar y, scalar& x)
{
    if ((s.y0 <= y) == (s.y1 <= y))
    {
        return false;
    }
    const scalar t = (y - s.y0)/(s.y1 - s.y0);
    x = s.x0 + t*(s.x1 - s.x0);
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
    if (segments_.empty() || !std::isfinite(bounds_.max.y - bounds_.min.y))
    {
        start_.assign(2, 0);
        items_.resize(segments_.size());
        for (std::size_t i = 0; i < items_.size(); ++i)
        {
            items_[i] = i;
        }
        start_[1] = std::int64_t(items_.size());
        return;
    }

    // About one segment per row.
    const scalar h = bounds_.max.y - bounds_.min.y;
    nRows_ = std::clamp<std::int64_t>(std::int64_t(segments_.size()), 1,
                                      1 << 20);
    y0_ = bounds_.min.y;
    invDy_ = h > 0 ? scalar(nRows_)/h : 0;
    const auto row = [&](scalar y)
    {
        const scalar r = std::floor((y - y0_)*invDy_);
        return std::clamp<std::int64_t>(r >= 0 ? std::int64_t(std::min(
            r, scalar(nRows_))) : 0, 0, nRows_ - 1);
    };
    buildBinLists(nRows_, segments_.size(),
        [&](const std::size_t i, const auto& visit)
        {
            const segment& s = segments_[i];
            const std::int64_t a = row(std::min(s.y0, s.y1));
            const std::int64_t b = row(std::max(s.y0, s.y1));
            for (std::int64_t r = a; r <= b; ++r)
            {
                visit(r);
            }
        },
        start_, items_);
}


void planarRegion::crossings(scalar y, std::vector<scalar>& xs) const
{
    xs.clear();
    std::int64_t r = 0;
    if (nRows_ > 1)
    {
        const scalar f = std::floor((y - y0_)*invDy_);
        if (!(f >= 0 && f < scalar(nRows_)))
        {
            return;
        }
        r = std::int64_t(f);
    }
    for (std::int64_t k = start_[r]; k < start_[r + 1]; ++k)
    {
        scalar x;
        if (crossing(segments_[items_[k]], y, x))
        {
            xs.push_back(x);
        }
    }
}


bool planarRegion::inside(scalar x, scalar y) const
{
    if (!(y >= bounds_.min.y && y <= bounds_.max.y))
    {
        return false;
    }
    std::int64_t r = 0;
    if (nRows_ > 1)
    {
        r = std::clamp<std::int64_t>
        (
            std::int64_t(std::floor((y - y0_)*invDy_)), 0, nRows_ - 1
        );
    }
    int n = 0;
    for (std::int64_t k = start_[r]; k < start_[r + 1]; ++k)
    {
        scalar xc;
        n += crossing(segments_[items_[k]], y, xc) && xc > x;
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
