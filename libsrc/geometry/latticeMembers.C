/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "latticeMembers.H"
#include "error.H"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>

namespace sphvcpm
{

namespace
{

using cell = std::array<std::int64_t, 3>;

// 21 bits per axis: room for 2 million layers each way.
std::int64_t packed(const cell& c)
{
    const std::int64_t offset = 1 << 20, mask = (1 << 21) - 1;
    return ((c[0] + offset) & mask) | (((c[1] + offset) & mask) << 21)
         | (((c[2] + offset) & mask) << 42);
}

// The cell of point p on the lattice through p0; false when p lies more
// than dp/4 off that lattice's nodes.
bool latticeCell(const vec3& p, const vec3& p0, const scalar dp, cell& c)
{
    bool onNode = true;
    for (int a = 0; a < 3; ++a)
    {
        const scalar s = (p[a] - p0[a])/dp;
        c[a] = std::llround(s);
        onNode = onNode && std::abs(s - scalar(c[a])) <= 0.25;
    }
    return onNode;
}

} // End anonymous namespace


bool onOneLattice(const std::vector<vec3>& points, const scalar dp)
{
    return points.empty() || onLatticeThrough(points, points.front(), dp);
}


bool onLatticeThrough(const std::vector<vec3>& points, const vec3& p0,
                      const scalar dp)
{
    cell c;
    return std::all_of(points.begin(), points.end(), [&](const vec3& p)
        { return latticeCell(p, p0, dp, c); });
}


latticeMembers findThinMembers
(
    const std::vector<vec3>& points,
    const scalar dp,
    const int nDimensions,
    const label maxLayers,
    const bool skipEdges
)
{
    return findThinMembersByOwner(points, std::vector<label>(points.size(), 0),
        1, dp, nDimensions, maxLayers, skipEdges).front();
}


std::vector<latticeMembers> findThinMembersByOwner
(
    const std::vector<vec3>& points,
    const std::vector<label>& owner,
    const label nOwners,
    const scalar dp,
    const int nDimensions,
    const label maxLayers,
    const bool skipEdges
)
{
    std::vector<latticeMembers> results(std::max<label>(nOwners, 1));
    const std::size_t n = points.size();
    if (!n)
    {
        return results;
    }
    if (owner.size() != n)
    {
        fatalError("findThinMembersByOwner: " + std::to_string(owner.size())
            + " owners for " + std::to_string(n) + " points");
    }

    // Integer cells relative to the first point: every body lies on one
    // lattice, so differences are whole multiples of dp.
    std::vector<cell> cells(n);
    std::unordered_map<std::int64_t, label> index;
    index.reserve(2*n);
    for (std::size_t p = 0; p < n; ++p)
    {
        if (!latticeCell(points[p], points[0], dp, cells[p]))
        {
            fatalError("findThinMembers: the particles are not on one"
                       " lattice of spacing dp");
        }
        index[packed(cells[p])] = label(p);
    }
    auto neighbour = [&](label p, int a, int step) -> label
    {
        cell c = cells[p];
        c[a] += step;
        const auto it = index.find(packed(c));
        return it == index.end() ? -1 : it->second;
    };

    // Unbroken runs along each axis, counted from the run's first node,
    // and each node's place in its run (0 for the first).
    std::vector<std::array<label, 3>> run(n, {0, 0, 0});
    std::vector<std::array<label, 3>> place(n, {0, 0, 0});
    for (int a = 0; a < nDimensions; ++a)
    {
        for (label p = 0; p < label(n); ++p)
        {
            if (neighbour(p, a, -1) >= 0)
            {
                continue;   // not the first of its run
            }
            label length = 0;
            for (label q = p; q >= 0; q = neighbour(q, a, +1))
            {
                ++length;
            }
            label k = 0;
            for (label q = p; q >= 0; q = neighbour(q, a, +1))
            {
                run[q][a] = length;
                place[q][a] = k++;
            }
        }
    }

    for (label p = 0; p < label(n); ++p)
    {
        if (owner[p] < 0 || owner[p] >= label(results.size()))
        {
            fatalError("findThinMembersByOwner: owner "
                + std::to_string(owner[p]) + " of point "
                + std::to_string(p) + " is not in [0, "
                + std::to_string(results.size()) + ")");
        }
        latticeMembers& result = results[owner[p]];
        // Second neighbours: diagonal in some pair of axes.
        for (int a = 0; a < nDimensions && !result.hasSecondNeighbours; ++a)
        {
            for (int b = a + 1; b < nDimensions; ++b)
            {
                for (const int sb : {-1, 1})
                {
                    cell c = cells[p];
                    c[a] += 1;
                    c[b] += sb;
                    if (index.count(packed(c)))
                    {
                        result.hasSecondNeighbours = true;
                    }
                }
            }
        }

        int shortAxis = 0;
        for (int a = 1; a < nDimensions; ++a)
        {
            if (run[p][a] < run[p][shortAxis]) shortAxis = a;
        }
        const label thickness = run[p][shortAxis];
        if (thickness >= maxLayers
         || (result.thinnestLayers >= 0 && thickness >= result.thinnestLayers))
        {
            continue;
        }
        bool nearEdge = false;
        for (int b = 0; b < nDimensions && skipEdges; ++b)
        {
            nearEdge = nearEdge || (b != shortAxis
             && std::min(place[p][b], run[p][b] - 1 - place[p][b])
                < thickness);
        }
        if (nearEdge)
        {
            continue;
        }
        // Slender: 2 x thickness particles in a row no thicker than p.
        for (int b = 0; b < nDimensions; ++b)
        {
            if (b == shortAxis)
            {
                continue;
            }
            label length = 1;
            for (const int step : {-1, 1})
            {
                for
                (
                    label q = neighbour(p, b, step);
                    q >= 0 && run[q][shortAxis] <= thickness
                 && length < 2*thickness;
                    q = neighbour(q, b, step)
                )
                {
                    ++length;
                }
            }
            if (length >= 2*thickness)
            {
                result.thinnestLayers = thickness;
                result.where = p;
                break;
            }
        }
    }
    return results;
}

} // End namespace sphvcpm
