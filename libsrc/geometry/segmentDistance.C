/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Nearest point of plane segments within a radius, on a radiusGrid.

#include "segmentDistance.H"

#include <algorithm>

namespace sphvcpm
{

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


std::vector<segmentDistance::line> segmentDistance::linesOf
(
    const std::vector<planarRegion::segment>& segments
)
{
    std::vector<line> lines;
    lines.reserve(segments.size());
    for (const planarRegion::segment& s : segments)
    {
        const vec3 n{s.y1 - s.y0, s.x0 - s.x1, 0};
        const scalar len = mag(n);
        lines.push_back
        (
            {{s.x0, s.y0, 0}, {s.x1, s.y1, 0},
             len > 0 ? n/len : vec3{0, 0, 0}}
        );
    }
    return lines;
}


segmentDistance::segmentDistance
(
    const std::vector<planarRegion::segment>& segments,
    scalar radius
)
:
    lines_(linesOf(segments)),
    grid_
    (
        [&]
        {
            boundBox b = boundBox::invalid();
            for (const line& l : lines_)
            {
                b.add(l.a);
                b.add(l.b);
            }
            return b;
        }(),
        radius, lines_.size(),
        [&](const std::size_t i)
        {
            boundBox b = boundBox::invalid();
            b.add(lines_[i].a);
            b.add(lines_[i].b);
            return b;
        },
        [&](const std::size_t i, const vec3& p)
        {
            return nearestOnSegment(p, lines_[i].a, lines_[i].b);
        }
    )
{}


segmentDistance::nearest segmentDistance::find(const vec3& p) const
{
    const auto n = grid_.find
    (
        {p.x, p.y, 0},
        [&](const label i, const vec3& q)
        {
            return nearestOnSegment(q, lines_[i].a, lines_[i].b);
        },
        [&](const label i) { return lines_[i].normal; }
    );
    return {n.item, n.distance, n.point, n.side};
}

} // End namespace sphvcpm
