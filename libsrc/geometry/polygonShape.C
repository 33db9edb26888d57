/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// 2D shapes from polygons and from the cut of an STL surface.

#include "polygonShape.H"
#include "error.H"
#include "stlShape.H"
#include "triSurface.H"

#include <cmath>
#include <utility>
#include <sstream>

namespace sphvcpm
{

namespace
{

planarRegion polygonFromDict
(
    const std::string& name,
    const dictionary& dict,
    int nDimensions
)
{
    if (nDimensions != 2)
    {
        dict.fatalAt("shape", "Shape '" + name + "': shape polygon is a 2D"
            " shape (x-y plane) and needs nDimensions 2");
    }
    const std::vector<vec3> pts = dict.get<std::vector<vec3>>("points");
    if (pts.size() < 3)
    {
        dict.fatalAt("points", "Keyword 'points': polygon '" + name
            + "' needs at least 3 points (x y), found "
            + std::to_string(pts.size()));
    }
    std::vector<planarRegion::segment> segs;
    for (std::size_t i = 0; i < pts.size(); ++i)
    {
        const vec3& a = pts[i];
        const vec3& b = pts[(i + 1) % pts.size()];
        if (!std::isfinite(mag(a)))
        {
            dict.fatalAt("points", "Keyword 'points': point "
                + std::to_string(i) + " of polygon '" + name
                + "' is not finite");
        }
        if (a.z != 0)
        {
            dict.fatalAt("points", "Keyword 'points': point "
                + std::to_string(i) + " of polygon '" + name + "' has a z"
                  " component; give (x y)");
        }
        segs.push_back({a.x, a.y, b.x, b.y});
    }
    planarRegion r(std::move(segs));
    if (!(r.area() > 0))
    {
        dict.fatalAt("points", "Keyword 'points': polygon '" + name
            + "' encloses no area (its points are on one line)");
    }
    return r;
}

} // End anonymous namespace


polygonShape::polygonShape
(
    std::string name,
    int nDimensions,
    planarRegion region
)
:
    shape(std::move(name), nDimensions),
    region_(std::move(region)),
    area_(region_.area())
{}


polygonShape::polygonShape
(
    std::string name,
    const dictionary& dict,
    int nDimensions
)
:
    polygonShape(name, nDimensions, polygonFromDict(name, dict, nDimensions))
{}


std::vector<planarRegion::segment> stlSliceShape::cut
(
    const std::vector<vec3>& points,
    const std::vector<std::array<label, 3>>& faces
)
{
    // Where edge (a, b) meets z = 0, from its lexicographically smaller
    // end so that both triangles of the edge agree to the bit.
    const auto meet = [&](label a, label b)
    {
        const vec3& p = points[a];
        const vec3& q = points[b];
        const bool swap = q.x < p.x || (q.x == p.x && (q.y < p.y
            || (q.y == p.y && q.z < p.z)));
        const vec3& s = swap ? q : p;
        const vec3& e = swap ? p : q;
        const scalar t = s.z/(s.z - e.z);
        return vec3{s.x + t*(e.x - s.x), s.y + t*(e.y - s.y), 0};
    };

    std::vector<planarRegion::segment> segs;
    for (const auto& f : faces)
    {
        bool above[3];
        int nAbove = 0;
        for (int i = 0; i < 3; ++i)
        {
            above[i] = points[f[i]].z >= 0;
            nAbove += above[i];
        }
        if (nAbove == 0 || nAbove == 3)
        {
            continue;
        }
        // The vertex alone on its side, and its two edges.
        int lone = 0;
        for (int i = 0; i < 3; ++i)
        {
            if ((nAbove == 1) == above[i])
            {
                lone = i;
            }
        }
        vec3 a = meet(f[lone], f[(lone + 1) % 3]);
        vec3 b = meet(f[lone], f[(lone + 2) % 3]);
        if (a.x == b.x && a.y == b.y)
        {
            continue;
        }
        // Run along z x n, so that the segment's right-hand normal is the
        // triangle's normal projected onto the plane.
        const vec3 n = cross(points[f[1]] - points[f[0]],
                             points[f[2]] - points[f[0]]);
        if ((b.x - a.x)*(-n.y) + (b.y - a.y)*n.x < 0)
        {
            std::swap(a, b);
        }
        segs.push_back({a.x, a.y, b.x, b.y});
    }
    return segs;
}


planarRegion stlSliceShape::cutRegion
(
    const triSurface& surf,
    const std::string& name,
    const std::string& source
)
{
    planarRegion r(cut(surf.points(), surf.faces()));
    if (r.empty())
    {
        const boundBox b = surf.bounds();
        std::ostringstream os;
        os << "Shape '" << name << "': the plane z = 0 does not cut the"
           << " surface (its z from " << b.min.z << " to " << b.max.z
           << "; a surface that only touches the plane is not cut):"
           << " move it with translate";
        fatalIOError(source, 0, os.str());
    }
    return r;
}


namespace
{

planarRegion sliceFromDict
(
    const std::string& name,
    const dictionary& dict,
    const std::filesystem::path& caseDir
)
{
    try
    {
        stlDetail::surfaceInput in =
            stlDetail::readSurface(name, dict, caseDir);
        const scalar merge = in.mergeDistance < 0
            ? stlDetail::defaultMergeDistance(in.soup) : in.mergeDistance;
        const triSurface surf(in.soup, merge);
        stlDetail::checkRepairs(surf, name, in.source, merge);
        if (!surf.closed() && in.checkClosed)
        {
            std::ostringstream os;
            os << "Shape '" << name << "': the surface is not closed: "
               << surf.openEdges().size() << " open edges (edges used by an"
               << " odd number of triangles), so its cut by z = 0 need not"
               << " be closed either\nClose the surface (in the CAD tool),"
               << " raise mergeDistance (now " << merge << " m) if the gaps"
               << " are tiny, or set checkClosed no to fill it anyway";
            fatalIOError(in.source, 0, os.str(), "checkClosed");
        }
        return stlSliceShape::cutRegion(surf, name, in.source);
    }
    catch (const FatalError& err)
    {
        stlDetail::rethrowForShape(err, name, dict);
    }
}

} // End anonymous namespace


stlSliceShape::stlSliceShape
(
    std::string name,
    const dictionary& dict,
    int nDimensions,
    const std::filesystem::path& caseDir
)
:
    polygonShape(name, nDimensions, sliceFromDict(name, dict, caseDir))
{}

} // End namespace sphvcpm
