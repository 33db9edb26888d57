/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "bondList.H"

#include "error.H"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_map>

namespace sphvcpm
{

namespace
{

// 21 bits per cell coordinate: 2 million cells a side is far beyond any
// solid body of this code.
std::int64_t cellKey(const std::int64_t a, const std::int64_t b,
                     const std::int64_t c)
{
    const std::int64_t bias = 1 << 20;
    return ((a + bias) << 42) | ((b + bias) << 21) | (c + bias);
}

} // End anonymous namespace


bondList::bondList(const std::vector<point>& X, const scalar l0)
{
    build(X, l0);
}


bondList::bondList(const std::vector<point>& X, const scalar l0,
                   const std::function<scalar(label)>& gammaOfLayers,
                   const std::vector<std::uint8_t>& clamped)
{
    build(X, l0);
    correctSurfaces(X, l0, gammaOfLayers);
    correctClampRoots(clamped);
}


void bondList::build(const std::vector<point>& X, const scalar l0)
{
    const label n = label(X.size());
    const scalar cut1 = 1.01*l0;
    const scalar cut2 = 1.01*std::sqrt(2.0)*l0;
    if (!(l0 > 0))
    {
        throw FatalError("VCPM bond list: particle spacing must be positive",
                         "", 0, "dp");
    }

    // Cell linked list in a hash: cells of side cut2, so every bond joins
    // the same or adjacent cells.
    point lo = n ? X[0] : point{0, 0, 0};
    for (const point& p : X)
    {
        lo.x = std::min(lo.x, p.x);
        lo.y = std::min(lo.y, p.y);
        lo.z = std::min(lo.z, p.z);
    }
    std::vector<std::int64_t> cell(3*std::size_t(n));
    std::unordered_map<std::int64_t, label> head;
    head.reserve(2*std::size_t(n));
    std::vector<label> next(n, -1);
    for (label p = 0; p < n; ++p)
    {
        for (int d = 0; d < 3; ++d)
        {
            cell[3*p + d] = std::int64_t(std::floor((X[p][d] - lo[d])/cut2));
        }
        const std::int64_t key = cellKey(cell[3*p], cell[3*p + 1], cell[3*p + 2]);
        auto it = head.find(key);
        if (it != head.end())
        {
            next[p] = it->second;
            it->second = p;
        }
        else
        {
            head.emplace(key, p);
        }
    }

    std::vector<label> count(n, 0);
    std::vector<label> found;
    for (label i = 0; i < n; ++i)
    {
        found.clear();
        for (int a = -1; a <= 1; ++a)
        for (int b = -1; b <= 1; ++b)
        for (int c = -1; c <= 1; ++c)
        {
            auto it = head.find
            (
                cellKey(cell[3*i] + a, cell[3*i + 1] + b, cell[3*i + 2] + c)
            );
            if (it == head.end()) continue;
            for (label j = it->second; j >= 0; j = next[j])
            {
                if (j > i) found.push_back(j);
            }
        }
        // Sorted so that the list does not depend on the hash order.
        std::sort(found.begin(), found.end());
        for (const label j : found)
        {
            const scalar r = mag(X[j] - X[i]);
            if (r < 0.5*l0)
            {
                std::ostringstream os;
                os << "VCPM bond list: particles " << i << " and " << j
                   << " are " << r << " apart, less than dp/2 = " << 0.5*l0
                   << ": the solid is not a lattice of spacing dp";
                throw FatalError(os.str(), "", 0, "dp");
            }
            if (r >= cut2) continue;
            first_.push_back(i);
            second_.push_back(j);
            layer_.push_back(r < cut1 ? 0 : 1);
            length_.push_back(r);
            ++count[i];
            ++count[j];
        }
    }

    // CSR adjacency; bonds of a particle in increasing bond order.
    start_.assign(n + 1, 0);
    for (label p = 0; p < n; ++p)
    {
        start_[p + 1] = start_[p] + count[p];
    }
    adjacency_.resize(start_[n]);
    std::vector<label> fill(start_.begin(), start_.end() - 1);
    for (label b = 0; b < nBonds(); ++b)
    {
        adjacency_[fill[first_[b]]++] = b;
        adjacency_[fill[second_[b]]++] = b;
    }

    for (label p = 0; p < n; ++p)
    {
        if (nBondsOf(p, 1) == 0) withoutSecondLayer_.push_back(p);
    }

    weight_.assign(2*std::size_t(nBonds()), 1);
    pairFactor_.assign(nBonds(), 1);
}


void bondList::correctSurfaces(const std::vector<point>& X, const scalar l0,
                               const std::function<scalar(label)>& gammaOf)
{
    // The partner of p along reference offset d, or -1.
    const scalar tol2 = 1e-4*l0*l0;
    auto neighbour = [&](const label p, const vec3& d) -> label
    {
        for (label a = start_[p]; a < start_[p + 1]; ++a)
        {
            const label k = adjacency_[a];
            const label q = first_[k] == p ? second_[k] : first_[k];
            if (magSqr(toVec3(X[q] - X[p]) - d) < tol2) return q;
        }
        return -1;
    };
    auto bondBetween = [&](const label p, const label q) -> label
    {
        for (label a = start_[p]; a < start_[p + 1]; ++a)
        {
            const label k = adjacency_[a];
            if (first_[k] == q || second_[k] == q) return k;
        }
        return -1;
    };

    // End weights: 2 where the opposite bond at that end is missing (the
    // mirror image stands in for it), else 1.
    for (label k = 0; k < nBonds(); ++k)
    {
        const vec3 d = toVec3(X[second_[k]] - X[first_[k]]);
        if (neighbour(first_[k], -1.0*d) < 0) weight_[2*k] = 2;
        if (neighbour(second_[k], d) < 0) weight_[2*k + 1] = 2;
    }

    // Second-moment shift. Candidate normals: the axis directions of the
    // layer-1 bonds the body has (so a 2D lattice has no z normal).
    std::vector<vec3> axes;
    for (int dir = 0; dir < 3; ++dir)
    {
        vec3 m{0, 0, 0};
        m[dir] = l0;
        for (label k = 0; k < nBonds(); ++k)
        {
            const vec3 d = toVec3(X[second_[k]] - X[first_[k]]);
            if (layer_[k] == 0 && std::abs(std::abs(d[dir]) - l0) < 0.01*l0)
            {
                axes.push_back(m);
                axes.push_back(-1.0*m);
                break;
            }
        }
    }
    // Layers of the member under surface particle p, counted along -m (up
    // to maxShiftLayers: the shift hardly changes beyond). The count stops
    // at the first hole: a surface bond above a void gets the gamma of the
    // ligament above the void (a choice, docs/vcpm.md).
    auto layersUnder = [&](label p, const vec3& m)
    {
        label n = 1;
        while (n < maxShiftLayers && (p = neighbour(p, -1.0*m)) >= 0) ++n;
        return n;
    };
    std::vector<scalar> largestDecrement(nBonds(), 0);
    for (label k = 0; k < nBonds(); ++k)
    {
        if (layer_[k] != 0) continue;
        const label i = first_[k], j = second_[k];
        const vec3 d = toVec3(X[j] - X[i]);
        for (const vec3& m : axes)
        {
            if (std::abs(dot(d, m)) > 0.01*l0*l0) continue;
            if (neighbour(i, m) >= 0 || neighbour(j, m) >= 0) continue;
            // The shift of a strip as thick as the member here (the
            // thinner side at a step).
            const scalar gamma =
                gammaOf(std::min(layersUnder(i, m), layersUnder(j, m)));
            pairFactor_[k] += gamma;
            const label i1 = neighbour(i, -1.0*m), j1 = neighbour(j, -1.0*m);
            const label k1 = i1 < 0 || j1 < 0 ? -1 : bondBetween(i1, j1);
            if (k1 >= 0)
            {
                pairFactor_[k1] -= gamma;
                largestDecrement[k1] = std::max(largestDecrement[k1], gamma);
            }
        }
    }
    // A member 2 or 3 layers thick, or an edge, takes the decrement from
    // several faces; more than one would leave the bond soft or negative
    // (a 3 x 3 x 3 block blew up). At most one is kept.
    for (label k = 0; k < nBonds(); ++k)
    {
        pairFactor_[k] = std::max(pairFactor_[k], 1 - largestDecrement[k]);
    }
}


void bondList::correctClampRoots(const std::vector<std::uint8_t>& clamped)
{
    if (clamped.empty()) return;
    if (label(clamped.size()) != nParticles())
    {
        throw FatalError("VCPM bond list: got "
            + std::to_string(clamped.size()) + " clamp flags, expected "
            + std::to_string(nParticles()) + " (one per particle) or none",
            "", 0, "clamped");
    }
    // A bond from a clamped to a free particle is half inside the clamped
    // particle's rigid cell: its free half takes the whole stretch, at
    // twice the bond's strain. So the free end counts the stretch twice (in
    // its stretch sum and pair energy), the clamped end not at all, and the
    // pair stiffness doubles: under any strain of the free side the bond
    // carries what a bulk bond does, and the clamp holds at the support's
    // face instead of half a spacing inside it (docs/vcpm.md, Clamp roots).
    for (label k = 0; k < nBonds(); ++k)
    {
        const bool a = clamped[first_[k]] != 0, b = clamped[second_[k]] != 0;
        if (a == b) continue;
        const std::size_t freeEnd = 2*std::size_t(k) + (a ? 1 : 0);
        const std::size_t clampedEnd = 2*std::size_t(k) + (a ? 0 : 1);
        weight_[freeEnd] *= 2;
        weight_[clampedEnd] = 0;
        pairFactor_[k] *= 2;
    }
}


label bondList::nBondsOf(const label p, const int layer) const
{
    label c = 0;
    for (label a = start_[p]; a < start_[p + 1]; ++a)
    {
        c += layer_[adjacency_[a]] == layer;
    }
    return c;
}

} // End namespace sphvcpm
