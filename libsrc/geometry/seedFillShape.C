/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Flood fill of lattice nodes from a seed point inside a surface.

#include "seedFillShape.H"
#include "error.H"
#include "stlShape.H"
#include "triSurfaceDistance.H"

#include <array>
#include <cmath>
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
    if (nDimensions != 3)
    {
        dict.fatalAt("shape", "Shape '" + name_ + "': shape seedFill needs"
            " nDimensions 3 (fill a 2D body with shape stl or polygon)");
    }
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
    const vec3 seed = dict.get<vec3>("seed");
    if (!std::isfinite(mag(seed)))
    {
        dict.fatalAt("seed", "Keyword 'seed': expected a finite point");
    }
    vec3 up = dict.getOrDefault<vec3>("up", {0, 0, 1});
    if (!(mag(up) > 0) || !std::isfinite(mag(up)))
    {
        dict.fatalAt("up", "Keyword 'up': expected a finite, non-zero"
            " vector (the direction opposite to gravity), e.g. (0 0 1)");
    }
    up = up/mag(up);
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
    const triSurfaceInside rays(surf);
    const triSurfaceDistance near(surf, dp_/2);

    // Nodes of the surface's bounding box: a step out of it has escaped.
    const boundBox bb = surf.bounds();
    scalar nTotal = 1;
    for (int d = 0; d < 3; ++d)
    {
        lo_[d] = std::int64_t(std::ceil((bb.min[d] - origin_[d])/dp_ - 0.5));
        const std::int64_t hi =
            std::int64_t(std::floor((bb.max[d] - origin_[d])/dp_ - 0.5));
        n_[d] = std::max<std::int64_t>(0, hi - lo_[d] + 1);
        nTotal *= scalar(n_[d]);
    }
    if (nTotal > 2147483647.0)
    {
        dict.fatalAt("file", "Shape '" + name_ + "': the bounding box of the"
            " surface spans more than 2^31 lattice nodes at dp " + str(dp_)
          + ": check scale and dp");
    }
    filled_.assign(std::size_t(nTotal), 0);

    const auto node = [&](const std::int64_t ijk[3])
    {
        return vec3
        {
            origin_.x + (scalar(ijk[0]) + 0.5)*dp_,
            origin_.y + (scalar(ijk[1]) + 0.5)*dp_,
            origin_.z + (scalar(ijk[2]) + 0.5)*dp_
        };
    };
    const scalar tol = 1e-9*dp_;
    const auto belowLevel = [&](const vec3& p)
    {
        return !hasLevel || dot(p, up) < level - tol;
    };
    // Closer than dp/2 (up to round-off: a node dp/2 off a wall on a
    // lattice face stays).
    const auto tooClose = [&](const vec3& p)
    {
        const triSurfaceDistance::nearest n = near.find(p);
        return n.face >= 0 && n.distance < 0.5*dp_*(1 - 1e-6);
    };
    const auto index = [&](const std::int64_t ijk[3])
    {
        return ((ijk[2] - lo_[2])*n_[1] + (ijk[1] - lo_[1]))*n_[0]
             + (ijk[0] - lo_[0]);
    };

    // The seed's node.
    std::int64_t s[3];
    for (int d = 0; d < 3; ++d)
    {
        s[d] = std::int64_t(std::floor((seed[d] - origin_[d])/dp_));
    }
    const vec3 sNode = node(s);
    for (int d = 0; d < 3; ++d)
    {
        if (s[d] < lo_[d] || s[d] >= lo_[d] + n_[d])
        {
            dict.fatalAt("seed", "Keyword 'seed': the seed " + str(seed, 3)
              + " of shape '" + name_ + "' is outside the bounding box of the"
                " surface, " + str(bb.min, 3) + " to " + str(bb.max, 3)
              + " (" + in.source + "): it must lie in the fluid, inside the"
                " container");
        }
    }
    if (!belowLevel(sNode))
    {
        dict.fatalAt("seed", "Keyword 'seed': the seed " + str(seed, 3)
          + " of shape '" + name_ + "' (its lattice node " + str(sNode, 3)
          + ") is not below level " + str(level) + ": it must lie in the"
            " fluid");
    }
    if (tooClose(sNode))
    {
        dict.fatalAt("seed", "Keyword 'seed': the lattice node "
          + str(sNode, 3) + " of the seed " + str(seed, 3) + " of shape '"
          + name_ + "' is closer than dp/2 to the surface: move the seed"
            " into the fluid");
    }

    // Breadth-first over the nodes; 1 filled, 2 too close to the surface.
    std::vector<std::array<std::int64_t, 3>> at{{s[0], s[1], s[2]}};
    filled_[index(s)] = 1;
    for (std::size_t q = 0; q < at.size(); ++q)
    {
        const std::int64_t a[3] = {at[q][0], at[q][1], at[q][2]};
        const vec3 pa = node(a);
        ++nFilled_;
        bounds_.add(pa - vec3{dp_/2, dp_/2, dp_/2});
        bounds_.add(pa + vec3{dp_/2, dp_/2, dp_/2});
        for (int axis = 0; axis < 3; ++axis)
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
                if (rays.parity(pa, axis) != rays.parity(pb, axis))
                {
                    continue;
                }
                const bool close = tooClose(pb);
                if (!inBox && !close)
                {
                    std::ostringstream os;
                    os << "Keyword 'seed': the fill of shape '" << name_
                       << "' from the seed " << str(seed, 3) << " reached "
                       << str(pb, 3) << ", outside the bounding box of the"
                       << " surface (" << in.source << "), after "
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
    for (int d = 3; d-- > 0;)
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
