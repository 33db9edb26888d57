/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Flood fill of lattice nodes from a seed point inside a surface.

#include "seedFillShape.H"
#include "error.H"
#include "polygonShape.H"
#include "segmentDistance.H"
#include "stlShape.H"
#include "triSurfaceDistance.H"

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <sstream>

namespace sphvcpm
{

seedFillShape::seedFillShape
(
    std::string name,
    const dictionary& dict,
    int nDimensions,
    scalar dp,
    const vec3& latticeOrigin,
    const std::filesystem::path& caseDir
)
:
    shape(std::move(name), nDimensions),
    origin_(latticeOrigin),
    dp_(dp),
    bounds_(boundBox::invalid())
{
    try
    {
        fill(dict, caseDir);
    }
    catch (const FatalError& err)
    {
        stlDetail::rethrowForShape(err, name_, dict);
    }
}


void seedFillShape::fill
(
    const dictionary& dict,
    const std::filesystem::path& caseDir
)
{
    using shapeDetail::str;

    // Read everything first, so that a bad keyword is named before the
    // surface is built.
    stlDetail::surfaceInput in = stlDetail::readSurface(name_, dict, caseDir);
    const int nDim = nDimensions_;
    const vec3 seed = dict.get<vec3>("seed");
    if (!std::isfinite(mag(seed)))
    {
        dict.fatalAt("seed", "Keyword 'seed': expected a finite point");
    }
    if (nDim == 2 && seed.z != 0)
    {
        dict.fatalAt("seed", "Keyword 'seed': in 2D the seed is a point of"
            " the plane z = 0: give (x y)");
    }
    // -g: up the y axis in 2D, the z axis in 3D.
    vec3 up = dict.getOrDefault<vec3>("up",
        nDim == 2 ? vec3{0, 1, 0} : vec3{0, 0, 1});
    if (!(mag(unitVector(up)) > 0))
    {
        dict.fatalAt("up", "Keyword 'up': expected a finite, non-zero"
            " vector (the direction opposite to gravity), e.g. "
          + std::string(nDim == 2 ? "(0 1)" : "(0 0 1)"));
    }
    if (nDim == 2 && up.z != 0)
    {
        dict.fatalAt("up", "Keyword 'up': in 2D the direction opposite to"
            " gravity lies in the plane z = 0: give (x y)");
    }
    up = unitVector(up);
    const bool hasLevel = dict.found("level");
    const scalar level = dict.getOrDefault<scalar>("level", 0);
    if (!std::isfinite(level))
    {
        dict.fatalAt("level", "Keyword 'level': expected a finite height");
    }

    const scalar merge = in.mergeDistance < 0
        ? stlDetail::defaultMergeDistance(in.soup) : in.mergeDistance;
    const triSurface surf(in.soup, merge);
    stlDetail::checkRepairs(surf, name_, in.source, merge);

    // What the fill asks of the container: whether a step along an axis
    // crosses it (the ray parities at its two ends differ), and the
    // distance to it within dp/2. In 3D the surface; in 2D its cut by
    // z = 0, as for shape stl.
    std::function<bool(const vec3&, int)> parity;
    std::function<bool(const vec3&)> nearSurface;
    std::unique_ptr<triSurfaceInside> rays;
    std::unique_ptr<triSurfaceDistance> near;
    std::unique_ptr<planarRegion> cut;
    std::unique_ptr<segmentDistance> nearCut;
    // Closer than dp/2 (up to round-off: a node dp/2 off a wall on a
    // lattice face stays).
    const scalar close = 0.5*dp_*(1 - 1e-6);
    boundBox bb;
    if (nDim == 3)
    {
        rays = std::make_unique<triSurfaceInside>(surf);
        near = std::make_unique<triSurfaceDistance>(surf, dp_/2);
        parity = [&](const vec3& p, int axis)
        {
            return rays->parity(p, axis);
        };
        nearSurface = [&](const vec3& p)
        {
            const triSurfaceDistance::nearest n = near->find(p);
            return n.face >= 0 && n.distance < close;
        };
        bb = surf.bounds();
    }
    else
    {
        cut = std::make_unique<planarRegion>
        (
            stlSliceShape::cutRegion(surf, name_, in.source)
        );
        nearCut = std::make_unique<segmentDistance>(cut->segments(), dp_/2);
        parity = [&](const vec3& p, int axis)
        {
            return cut->parity(p.x, p.y, axis);
        };
        nearSurface = [&](const vec3& p)
        {
            const segmentDistance::nearest n = nearCut->find(p);
            return n.segment >= 0 && n.distance < close;
        };
        bb = cut->bounds();
    }
    const std::string surface = nDim == 3 ? "the surface"
        : "the cut of the surface by z = 0";

    // Nodes of the surface's bounding box: a step out of it has escaped.
    // In 2D one layer of nodes, on z = 0.
    lo_[2] = 0;
    n_[2] = 1;
    scalar nTotal = 1;
    for (int d = 0; d < nDim; ++d)
    {
        lo_[d] = std::int64_t(std::ceil((bb.min[d] - origin_[d])/dp_ - 0.5));
        const std::int64_t hi =
            std::int64_t(std::floor((bb.max[d] - origin_[d])/dp_ - 0.5));
        n_[d] = std::max<std::int64_t>(0, hi - lo_[d] + 1);
        nTotal *= scalar(n_[d]);
    }
    if (nTotal > 2147483647.0)
    {
        dict.fatalAt("file", "Shape '" + name_ + "': the bounding box of "
          + surface + " spans more than 2^31 lattice nodes at dp " + str(dp_)
          + ": check scale and dp");
    }
    filled_.assign(std::size_t(nTotal), 0);

    // In 2D the third index stays 0 and nodes lie on z = 0.
    const auto node = [&](const std::int64_t ijk[3])
    {
        return vec3
        {
            scalar(origin_.x + (scalar(ijk[0]) + 0.5)*dp_),
            scalar(origin_.y + (scalar(ijk[1]) + 0.5)*dp_),
            nDim == 2
          ? scalar(0) : scalar(origin_.z + (scalar(ijk[2]) + 0.5)*dp_)
        };
    };
    const scalar tol = 1e-9*dp_;
    const auto belowLevel = [&](const vec3& p)
    {
        return !hasLevel || dot(p, up) < level - tol;
    };
    const auto index = [&](const std::int64_t ijk[3])
    {
        return ((ijk[2] - lo_[2])*n_[1] + (ijk[1] - lo_[1]))*n_[0]
             + (ijk[0] - lo_[0]);
    };

    // The seed's node.
    std::int64_t s[3] = {0, 0, 0};
    for (int d = 0; d < nDim; ++d)
    {
        s[d] = std::int64_t(std::floor((seed[d] - origin_[d])/dp_));
    }
    const vec3 sNode = node(s);
    for (int d = 0; d < nDim; ++d)
    {
        if (s[d] < lo_[d] || s[d] >= lo_[d] + n_[d])
        {
            dict.fatalAt("seed", "Keyword 'seed': the seed "
              + str(seed, nDim) + " of shape '" + name_ + "' is outside the"
                " bounding box of " + surface + ", " + str(bb.min, nDim)
              + " to " + str(bb.max, nDim)
              + " (" + in.source + "): it must lie in the fluid, inside the"
                " container");
        }
    }
    if (!belowLevel(sNode))
    {
        dict.fatalAt("seed", "Keyword 'seed': the seed " + str(seed, nDim)
          + " of shape '" + name_ + "' (its lattice node " + str(sNode, nDim)
          + ") is not below level " + str(level) + ": it must lie in the"
            " fluid");
    }
    if (nearSurface(sNode))
    {
        dict.fatalAt("seed", "Keyword 'seed': the lattice node "
          + str(sNode, nDim) + " of the seed " + str(seed, nDim)
          + " of shape '" + name_ + "' is closer than dp/2 to " + surface
          + ": move the seed into the fluid");
    }

    // Breadth-first over the nodes; 1 filled, 2 too close to the surface.
    std::vector<std::array<std::int64_t, 3>> at{{s[0], s[1], s[2]}};
    filled_[index(s)] = 1;
    for (std::size_t q = 0; q < at.size(); ++q)
    {
        const std::int64_t a[3] = {at[q][0], at[q][1], at[q][2]};
        const vec3 pa = node(a);
        ++nFilled_;
        const vec3 half{dp_/2, dp_/2, nDim == 2 ? scalar(0) : dp_/2};
        bounds_.add(pa - half);
        bounds_.add(pa + half);
        for (int axis = 0; axis < nDim; ++axis)
        {
            for (const int step : {-1, 1})
            {
                std::int64_t b[3] = {a[0], a[1], a[2]};
                b[axis] += step;
                const vec3 pb = node(b);
                if (!belowLevel(pb))
                {
                    continue;
                }
                const bool inBox = b[axis] >= lo_[axis]
                    && b[axis] < lo_[axis] + n_[axis];
                if (inBox && filled_[index(b)])
                {
                    continue;
                }
                // Odd crossings between the two ends: the step leaves.
                if (parity(pa, axis) != parity(pb, axis))
                {
                    continue;
                }
                const bool close = nearSurface(pb);
                if (!inBox && !close)
                {
                    std::ostringstream os;
                    os << "Keyword 'seed': the fill of shape '" << name_
                       << "' from the seed " << str(seed, nDim) << " reached "
                       << str(pb, nDim) << ", outside the bounding box of "
                       << surface << " (" << in.source << "), after "
                       << nFilled_ << " nodes: the seed is not inside a"
                       << " container, or the container is open or leaks "
                       << (hasLevel ? "below level " + str(level)
                                    : std::string("(give a level for an"
                                      " open tank)"));
                    dict.fatalAt("seed", os.str());
                }
                if (!inBox)
                {
                    continue;
                }
                filled_[index(b)] = close ? 2 : 1;
                if (!close)
                {
                    at.push_back({b[0], b[1], b[2]});
                }
            }
        }
    }
    // 2 marked nodes too close; only 1 is filled.
    for (unsigned char& f : filled_)
    {
        f = f == 1;
    }
}


bool seedFillShape::inside(const vec3& p, scalar) const
{
    std::int64_t idx = 0;
    for (int d = nDimensions_; d-- > 0;)
    {
        const scalar c = std::floor((p[d] - origin_[d])/dp_) - scalar(lo_[d]);
        if (!(c >= 0 && c < scalar(n_[d])))
        {
            return false;
        }
        idx = idx*n_[d] + std::int64_t(c);
    }
    return filled_[std::size_t(idx)];
}

} // End namespace sphvcpm
