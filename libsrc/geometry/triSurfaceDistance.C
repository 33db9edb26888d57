/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Nearest surface point within a radius, on a radiusGrid of triangles.

#include "triSurfaceDistance.H"
#include "segmentDistance.H"

namespace sphvcpm
{

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


std::vector<vec3> triSurfaceDistance::normalsOf(const triSurface& surf)
{
    std::vector<vec3> normals;
    normals.reserve(surf.faces().size());
    for (const triSurface::face& f : surf.faces())
    {
        const vec3& a = surf.points()[f[0]];
        const vec3 n = cross(surf.points()[f[1]] - a, surf.points()[f[2]] - a);
        const scalar len = mag(n);
        normals.push_back(len > 0 ? n/len : vec3{0, 0, 0});
    }
    return normals;
}


triSurfaceDistance::triSurfaceDistance(const triSurface& surf, scalar radius)
:
    points_(surf.points()),
    faces_(surf.faces()),
    normals_(normalsOf(surf)),
    grid_
    (
        surf.bounds(), radius, faces_.size(),
        [&](const std::size_t i)
        {
            boundBox b = boundBox::invalid();
            for (int v = 0; v < 3; ++v)
            {
                b.add(points_[faces_[i][v]]);
            }
            return b;
        },
        [&](const std::size_t i, const vec3& p) { return nearestOf(i, p); }
    )
{}


vec3 triSurfaceDistance::nearestOf(const std::size_t i, const vec3& p) const
{
    const triSurface::face& f = faces_[i];
    return nearestOnTriangle(p, points_[f[0]], points_[f[1]], points_[f[2]]);
}


triSurfaceDistance::nearest triSurfaceDistance::find(const vec3& p) const
{
    const auto n = grid_.find
    (
        p,
        [&](const label i, const vec3& q) { return nearestOf(i, q); },
        [&](const label i) { return normals_[i]; }
    );
    return {n.item, n.distance, n.point, n.side};
}

} // End namespace sphvcpm
