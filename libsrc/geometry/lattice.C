/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Lattice nodes and filling a region with them.

#include "lattice.H"
#include "error.H"

#include <cmath>
#include <limits>
#include <sstream>

namespace sphvcpm
{

lattice::lattice(const vec3& origin, scalar dp, int nDimensions)
:
    origin_(origin),
    dp_(dp),
    nDimensions_(nDimensions)
{
    if (!(dp_ > 0) || !std::isfinite(dp_))
    {
        fatalError("Lattice spacing dp must be positive, found "
            + shapeDetail::str(dp_));
    }
    if (nDimensions_ != 2 && nDimensions_ != 3)
    {
        fatalError("Lattice nDimensions must be 2 or 3, found "
            + std::to_string(nDimensions_));
    }
    if (nDimensions_ == 2)
    {
        origin_.z = 0;
    }
}


vec3 lattice::node(std::int64_t i, std::int64_t j, std::int64_t k) const
{
    return
    {
        origin_.x + (scalar(i) + 0.5)*dp_,
        origin_.y + (scalar(j) + 0.5)*dp_,
        nDimensions_ == 2 ? scalar(0) : origin_.z + (scalar(k) + 0.5)*dp_
    };
}


std::vector<vec3> lattice::fill(const region& r, const std::string& what)
    const
{
    std::vector<vec3> nodes;
    const boundBox bb = r.bounds();
    if (!bb.valid())
    {
        return nodes;
    }

    // Index range of the nodes within the bounds, one node wider on each
    // side so that rounding never loses a node on a face.
    std::int64_t lo[3] = {0, 0, 0};
    std::int64_t hi[3] = {0, 0, 0};
    scalar nTotal = 1;
    for (int d = 0; d < nDimensions_; ++d)
    {
        const scalar a = (bb.min[d] - origin_[d])/dp_ - 0.5;
        const scalar b = (bb.max[d] - origin_[d])/dp_ - 0.5;
        nTotal *= b - a + 3;
        if (!std::isfinite(nTotal) || nTotal > 2147483647.0)
        {
            std::ostringstream os;
            os << "The bounds of " << what << ", (" << bb.min.x << ' '
               << bb.min.y << ' ' << bb.min.z << ") to (" << bb.max.x << ' '
               << bb.max.y << ' ' << bb.max.z << "), span more than 2^31"
               << " lattice nodes at dp " << dp_ << ": check the sizes and"
               << " dp";
            fatalError(os.str());
        }
        lo[d] = std::int64_t(std::floor(a)) - 1;
        hi[d] = std::int64_t(std::ceil(b)) + 1;
    }

    const scalar tol = tolerance();
    for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
    {
        for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
        {
            for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
            {
                const vec3 p = node(i, j, k);
                if (r.inside(p, tol))
                {
                    nodes.push_back(p);
                }
            }
        }
    }

    if (nodes.size() > std::size_t(std::numeric_limits<label>::max()))
    {
        fatalError(what + " holds " + std::to_string(nodes.size())
            + " particles, more than a label can count");
    }
    return nodes;
}

} // End namespace sphvcpm
