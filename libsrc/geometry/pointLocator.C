/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Uniform-grid point locator.

#include "pointLocator.H"
#include "error.H"
#include "shape.H"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sphvcpm
{

pointLocator::pointLocator(std::vector<vec3> points, scalar cellSize)
:
    points_(std::move(points)),
    cellSize_(cellSize),
    bounds_(boundBox::invalid())
{
    if (!(cellSize_ > 0) || !std::isfinite(cellSize_))
    {
        fatalError("pointLocator: the cell size must be positive, found "
            + shapeDetail::str(cellSize_));
    }
    if (points_.empty())
    {
        return;
    }

    for (const vec3& p : points_)
    {
        bounds_.add(p);
    }
    scalar nCells = 1;
    for (int d = 0; d < 3; ++d)
    {
        n_[d] = std::int64_t
        (
            std::floor((bounds_.max[d] - bounds_.min[d])/cellSize_)
        ) + 1;
        nCells *= scalar(n_[d]);
    }
    if (!(nCells < 4e18))
    {
        fatalError("pointLocator: " + std::to_string(points_.size())
            + " points spread over too many cells of size "
            + shapeDetail::str(cellSize_));
    }

    const std::size_t n = points_.size();
    std::vector<std::int64_t> cellOf(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const vec3& p = points_[i];
        cellOf[i] = key(cellIndex(p, 0), cellIndex(p, 1), cellIndex(p, 2));
    }

    // A dense cell array costs 4 bytes a cell: take it while that is
    // comparable with the points themselves.
    dense_ = nCells <= 8.0*scalar(n) + 1048576.0;
    std::vector<vec3> sorted(n);
    if (dense_)
    {
        // Counting sort: stable, linear.
        cellStart_.assign(std::size_t(nCells) + 1, 0);
        for (const std::int64_t c : cellOf)
        {
            ++cellStart_[c + 1];
        }
        for (std::size_t c = 1; c < cellStart_.size(); ++c)
        {
            cellStart_[c] += cellStart_[c - 1];
        }
        std::vector<label> next(cellStart_.begin(), cellStart_.end() - 1);
        for (std::size_t i = 0; i < n; ++i)
        {
            sorted[next[cellOf[i]]++] = points_[i];
        }
    }
    else
    {
        std::vector<std::pair<std::int64_t, label>> order(n);
        for (std::size_t i = 0; i < n; ++i)
        {
            order[i] = {cellOf[i], label(i)};
        }
        std::sort(order.begin(), order.end());
        for (std::size_t i = 0; i < n; ++i)
        {
            sorted[i] = points_[order[i].second];
            if (i == 0 || order[i].first != order[i - 1].first)
            {
                keys_.push_back(order[i].first);
                keyStart_.push_back(label(i));
            }
        }
        keyStart_.push_back(label(n));
    }
    points_.swap(sorted);
}


std::int64_t pointLocator::cellIndex(const vec3& p, int d) const
{
    const scalar x = std::floor((p[d] - bounds_.min[d])/cellSize_);
    // Far away: any index two cells out has no occupied neighbours, and
    // clamping keeps the conversion to an integer defined.
    if (!(x >= -1))
    {
        return -2;
    }
    if (!(x <= scalar(n_[d])))
    {
        return n_[d] + 1;
    }
    return std::int64_t(x);
}


void pointLocator::cellRange(std::int64_t k, label& first, label& last)
    const
{
    if (dense_)
    {
        first = cellStart_[k];
        last = cellStart_[k + 1];
        return;
    }
    const auto it = std::lower_bound(keys_.begin(), keys_.end(), k);
    if (it == keys_.end() || *it != k)
    {
        first = last = 0;
        return;
    }
    const std::size_t at = std::size_t(it - keys_.begin());
    first = keyStart_[at];
    last = keyStart_[at + 1];
}


template<class F>
bool pointLocator::visitNear(const vec3& p, F f) const
{
    if (points_.empty())
    {
        return false;
    }
    std::int64_t c[3];
    for (int d = 0; d < 3; ++d)
    {
        c[d] = cellIndex(p, d);
    }
    for (std::int64_t k = c[2] - 1; k <= c[2] + 1; ++k)
    {
        if (k < 0 || k >= n_[2])
        {
            continue;
        }
        for (std::int64_t j = c[1] - 1; j <= c[1] + 1; ++j)
        {
            if (j < 0 || j >= n_[1])
            {
                continue;
            }
            for (std::int64_t i = c[0] - 1; i <= c[0] + 1; ++i)
            {
                if (i < 0 || i >= n_[0])
                {
                    continue;
                }
                label first, last;
                cellRange(key(i, j, k), first, last);
                for (label q = first; q < last; ++q)
                {
                    if (f(points_[q]))
                    {
                        return true;
                    }
                }
            }
        }
    }
    return false;
}


bool pointLocator::anyWithin(const vec3& p, scalar distance) const
{
    if (distance > cellSize_)
    {
        fatalError("pointLocator: query distance " + shapeDetail::str(distance)
            + " exceeds the cell size " + shapeDetail::str(cellSize_));
    }
    const scalar d2 = distance*distance;
    return visitNear(p, [&](const vec3& q) { return magSqr(q - p) < d2; });
}


scalar pointLocator::nearestWithinCell(const vec3& p) const
{
    vec3 nearest;
    return nearestWithinCell(p, nearest);
}


scalar pointLocator::nearestWithinCell(const vec3& p, vec3& nearest) const
{
    scalar best = cellSize_;
    nearest = p;
    visitNear(p, [&](const vec3& q)
    {
        const scalar d = mag(q - p);
        if (d < best)
        {
            best = d;
            nearest = q;
        }
        return false;
    });
    return best;
}

} // End namespace sphvcpm
