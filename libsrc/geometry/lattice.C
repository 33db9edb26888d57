/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Lattice nodes and filling a region with them.

#include "lattice.H"
#include "error.H"

#include <algorithm>
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
    // Computed in double, rounded once in a single-precision build.
    return
    {
        scalar(origin_.x + (scalar(i) + 0.5)*dp_),
        scalar(origin_.y + (scalar(j) + 0.5)*dp_),
        nDimensions_ == 2
      ? scalar(0) : scalar(origin_.z + (scalar(k) + 0.5)*dp_)
    };
}


void lattice::tooManyNodes(const region& reg, const std::string& what,
                           const std::size_t maxNodes) const
{
    const boundBox bb = reg.bounds();
    std::ostringstream os;
    os << what << " holds more than " << maxNodes << " particles at dp "
       << dp_ << " (its bounds (" << bb.min.x << ' ' << bb.min.y << ' '
       << bb.min.z << ") to (" << bb.max.x << ' ' << bb.max.y << ' '
       << bb.max.z << ")), more than the memory this machine has free can"
       << " take: lengths are in metres (sizes written in millimetres give "
       << (nDimensions_ == 2 ? "10^6" : "10^9") << " times the particles)."
       << " Check the sizes (an STL's scale) and dp";
    fatalError(os.str());
}


std::vector<vec3> lattice::fill(const region& reg, const std::string& what,
                                const std::size_t maxNodes) const
{
    std::vector<vec3> nodes;
    const boundBox bb = reg.bounds();
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
    // Said before the fill where the shapes' volume is known (a fill of
    // 10^9 nodes takes minutes), else during it.
    const scalar volume = reg.volume();
    if (volume > 0
     && volume/std::pow(dp_, nDimensions_) > 1.01*scalar(maxNodes))
    {
        tooManyNodes(reg, what, maxNodes);
    }

    // Rows along x tested in parallel (an STL inside test costs far more
    // than a box's), a block of rows at a time so that the flags stay
    // small; the nodes are appended in the serial order.
    const scalar tol = tolerance();
    const std::int64_t nx = hi[0] - lo[0] + 1;
    const std::int64_t ny = hi[1] - lo[1] + 1;
    const std::int64_t nRows = ny*(hi[2] - lo[2] + 1);
    const std::int64_t rowsPerBlock =
        std::max<std::int64_t>(1, (std::int64_t(1) << 22)/nx);
    std::vector<unsigned char> in;
    for (std::int64_t row0 = 0; row0 < nRows; row0 += rowsPerBlock)
    {
        const std::int64_t n = std::min(rowsPerBlock, nRows - row0);
        in.assign(std::size_t(n*nx), 0);

        #pragma omp parallel for schedule(dynamic, 4)
        for (std::int64_t r = 0; r < n; ++r)
        {
            const std::int64_t j = lo[1] + (row0 + r) % ny;
            const std::int64_t k = lo[2] + (row0 + r)/ny;
            for (std::int64_t i = 0; i < nx; ++i)
            {
                in[r*nx + i] = reg.inside(node(lo[0] + i, j, k), tol);
            }
        }

        for (std::int64_t r = 0; r < n; ++r)
        {
            const std::int64_t j = lo[1] + (row0 + r) % ny;
            const std::int64_t k = lo[2] + (row0 + r)/ny;
            for (std::int64_t i = 0; i < nx; ++i)
            {
                if (in[r*nx + i])
                {
                    nodes.push_back(node(lo[0] + i, j, k));
                }
            }
        }
        if (nodes.size() > maxNodes)
        {
            tooManyNodes(reg, what, maxNodes);
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
