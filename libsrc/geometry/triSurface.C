/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Merging, repairs, edge analysis, orientation and volume of a triangulated
// surface.

#include "triSurface.H"
#include "triSurfaceInside.H"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace sphvcpm
{

namespace
{

struct cellKey
{
    std::int64_t i, j, k;
    bool operator==(const cellKey& o) const
    {
        return i == o.i && j == o.j && k == o.k;
    }
};

struct cellHash
{
    std::size_t operator()(const cellKey& c) const
    {
        std::uint64_t h = std::uint64_t(c.i)*0x9E3779B97F4A7C15ull;
        h ^= std::uint64_t(c.j) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
        h ^= std::uint64_t(c.k) + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
        return std::size_t(h);
    }
};

} // End anonymous namespace


triSurface::triSurface(const std::vector<vec3>& soup, scalar mergeDistance)
{
    std::vector<label> soupToPoint;
    merge(soup, std::max<scalar>(mergeDistance, 0), soupToPoint);

    // Faces on the merged points, degenerate ones dropped.
    std::vector<face> faces;
    faces.reserve(soup.size()/3);
    for (std::size_t t = 0; t + 2 < soup.size(); t += 3)
    {
        const face f{soupToPoint[t], soupToPoint[t + 1], soupToPoint[t + 2]};
        if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0])
        {
            ++repairs_.nDegenerate;
            continue;
        }
        const vec3& a = points_[f[0]];
        const vec3& b = points_[f[1]];
        const vec3& c = points_[f[2]];
        const scalar lMax2 =
            std::max({magSqr(b - a), magSqr(c - b), magSqr(a - c)});
        // Area below 1e-12 of the longest edge squared: a needle or a line.
        if (mag(cross(b - a, c - a)) <= 1e-12*lMax2)
        {
            ++repairs_.nDegenerate;
            continue;
        }
        faces.push_back(f);
    }

    // Coincident triangles cancel in pairs (their crossings cancel in a
    // ray parity count too).
    std::vector<face> keys(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i)
    {
        keys[i] = faces[i];
        std::sort(keys[i].begin(), keys[i].end());
    }
    std::vector<std::size_t> order(faces.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
        [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
    std::vector<char> keep(faces.size(), 1);
    for (std::size_t i = 0; i < order.size();)
    {
        std::size_t j = i + 1;
        while (j < order.size() && keys[order[j]] == keys[order[i]])
        {
            ++j;
        }
        const std::size_t n = j - i;
        for (std::size_t m = i + (n % 2); m < j; ++m)
        {
            keep[order[m]] = 0;
            ++repairs_.nDuplicate;
        }
        i = j;
    }
    for (std::size_t i = 0; i < faces.size(); ++i)
    {
        if (keep[i])
        {
            faces_.push_back(faces[i]);
        }
    }

    analyseEdges();
}


void triSurface::merge
(
    const std::vector<vec3>& soup,
    scalar mergeDistance,
    std::vector<label>& soupToPoint
)
{
    scalar maxAbs = 0;
    for (const vec3& p : soup)
    {
        maxAbs = std::max({maxAbs, std::abs(p.x), std::abs(p.y),
                           std::abs(p.z)});
    }
    // Cells at least mergeDistance wide, and coarse enough for 64-bit
    // cell indices; only the distance test decides a merge.
    const scalar cell = std::max({mergeDistance, maxAbs*std::ldexp(scalar(1), -40),
                                  std::numeric_limits<scalar>::min()});
    const scalar d2 = mergeDistance*mergeDistance;

    std::unordered_map<cellKey, std::vector<label>, cellHash> cells;
    cells.reserve(soup.size());
    soupToPoint.resize(soup.size());
    for (std::size_t s = 0; s < soup.size(); ++s)
    {
        const vec3& p = soup[s];
        const cellKey c
        {
            std::int64_t(std::floor(p.x/cell)),
            std::int64_t(std::floor(p.y/cell)),
            std::int64_t(std::floor(p.z/cell))
        };
        label found = -1;
        for (int di = -1; di <= 1 && found < 0; ++di)
        {
            for (int dj = -1; dj <= 1 && found < 0; ++dj)
            {
                for (int dk = -1; dk <= 1 && found < 0; ++dk)
                {
                    const auto it =
                        cells.find({c.i + di, c.j + dj, c.k + dk});
                    if (it == cells.end())
                    {
                        continue;
                    }
                    for (const label q : it->second)
                    {
                        if (magSqr(points_[q] - p) <= d2)
                        {
                            found = q;
                            break;
                        }
                    }
                }
            }
        }
        if (found < 0)
        {
            found = label(points_.size());
            points_.push_back(p);
            cells[c].push_back(found);
        }
        else if (points_[found] != p)
        {
            ++repairs_.nMergedPoints;
        }
        soupToPoint[s] = found;
    }
}


void triSurface::analyseEdges()
{
    // (smaller point, larger point, face, whether the face runs small ->
    // large), sorted so that the uses of an edge are adjacent.
    struct use { label a, b, f; bool forward; };
    std::vector<use> uses;
    uses.reserve(3*faces_.size());
    for (std::size_t f = 0; f < faces_.size(); ++f)
    {
        for (int e = 0; e < 3; ++e)
        {
            const label p = faces_[f][e];
            const label q = faces_[f][(e + 1) % 3];
            uses.push_back({std::min(p, q), std::max(p, q), label(f), p < q});
        }
    }
    std::sort(uses.begin(), uses.end(), [](const use& x, const use& y)
    {
        return x.a != y.a ? x.a < y.a : (x.b != y.b ? x.b < y.b : x.f < y.f);
    });

    // Manifold neighbours: (face, face, same direction?).
    std::vector<std::vector<std::pair<label, bool>>> next(faces_.size());
    openEdges_.clear();
    for (std::size_t i = 0; i < uses.size();)
    {
        std::size_t j = i + 1;
        while (j < uses.size() && uses[j].a == uses[i].a
            && uses[j].b == uses[i].b)
        {
            ++j;
        }
        if ((j - i) % 2)
        {
            openEdges_.push_back({uses[i].a, uses[i].b});
        }
        if (j - i == 2)
        {
            const bool same = uses[i].forward == uses[i + 1].forward;
            next[uses[i].f].push_back({uses[i + 1].f, same});
            next[uses[i + 1].f].push_back({uses[i].f, same});
        }
        i = j;
    }

    // Shells, oriented consistently by a walk across manifold edges: a
    // neighbour running the shared edge the same way is flipped.
    outward_.assign(faces_.size(), 0);
    std::vector<label> shellOf(faces_.size(), -1);
    std::vector<label> stack;
    nShells_ = 0;
    for (std::size_t f0 = 0; f0 < faces_.size(); ++f0)
    {
        if (shellOf[f0] >= 0)
        {
            continue;
        }
        shellOf[f0] = label(nShells_);
        outward_[f0] = 1;
        stack.push_back(label(f0));
        while (!stack.empty())
        {
            const label f = stack.back();
            stack.pop_back();
            for (const auto& [g, same] : next[f])
            {
                if (shellOf[g] < 0)
                {
                    shellOf[g] = label(nShells_);
                    outward_[g] = same ? -outward_[f] : outward_[f];
                    stack.push_back(g);
                }
            }
        }
        ++nShells_;
    }

    // Each shell outwards: a point just off a triangle on its normal side
    // lies inside the material when the normal points inwards. The three
    // largest triangles of the shell vote, and the inside test is the
    // watertight three-ray one of triSurfaceInside, on all the shells (so
    // that an inner shell comes out as a cavity): a few queries per shell,
    // not a pass over every triangle.
    constexpr int nVoters = 3;
    std::vector<std::array<label, nVoters>> voters(nShells_);
    std::vector<std::array<scalar, nVoters>> voterArea(nShells_);
    for (std::size_t s = 0; s < nShells_; ++s)
    {
        voters[s].fill(-1);
        voterArea[s].fill(-1);
    }
    for (std::size_t f = 0; f < faces_.size(); ++f)
    {
        const vec3& a = points_[faces_[f][0]];
        scalar area = magSqr(cross(points_[faces_[f][1]] - a,
                                   points_[faces_[f][2]] - a));
        // (Faces whose area overflows still get a place.)
        area = std::isfinite(area) ? area : 0;
        label candidate = label(f);
        auto& v = voters[shellOf[f]];
        auto& va = voterArea[shellOf[f]];
        for (int i = 0; i < nVoters; ++i)
        {
            if (v[i] < 0 || area > va[i])
            {
                std::swap(v[i], candidate);
                std::swap(va[i], area);
                if (candidate < 0)
                {
                    break;
                }
            }
        }
    }
    const triSurfaceInside inside(*this);
    std::vector<signed char> flipShell(nShells_, 1);
    for (std::size_t s = 0; s < nShells_; ++s)
    {
        int inwards = 0, votes = 0;
        for (const label f : voters[s])
        {
            if (f < 0)
            {
                continue;
            }
            const face& F = faces_[f];
            const vec3& a = points_[F[0]];
            const vec3& b = points_[F[1]];
            const vec3& c = points_[F[2]];
            const vec3 n = scalar(outward_[f])*cross(b - a, c - a);
            const scalar twiceArea = mag(n);
            if (!(twiceArea > 0) || !std::isfinite(twiceArea))
            {
                continue;
            }
            // A thousandth of the triangle's size off its centre.
            const vec3 p = (a + b + c)/scalar(3)
              + (1e-3*std::sqrt(twiceArea)/twiceArea)*n;
            inwards += inside.inside(p);
            ++votes;
        }
        flipShell[s] = 2*inwards > votes ? -1 : 1;
    }
    for (std::size_t f = 0; f < faces_.size(); ++f)
    {
        outward_[f] *= flipShell[shellOf[f]];
    }
}


boundBox triSurface::bounds() const
{
    boundBox b = boundBox::invalid();
    for (const face& f : faces_)
    {
        for (const label p : f)
        {
            b.add(points_[p]);
        }
    }
    return b;
}


scalar triSurface::volume() const
{
    // About the centre of the bounds, for round-off far from the origin.
    const boundBox bb = bounds();
    if (!bb.valid())
    {
        return 0;
    }
    const vec3 o = 0.5*(bb.min + bb.max);
    scalar v = 0;
    for (std::size_t f = 0; f < faces_.size(); ++f)
    {
        const vec3 a = points_[faces_[f][0]] - o;
        const vec3 b = points_[faces_[f][1]] - o;
        const vec3 c = points_[faces_[f][2]] - o;
        v += outward_[f]*dot(a, cross(b, c));
    }
    return v/6;
}

} // End namespace sphvcpm
