/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "cellList.H"
#include "formatting.H"
#include "error.H"

#include <cmath>
#include <limits>
#include <string>

namespace sphvcpm
{

namespace
{

// Cells of support/divisor: a hair larger, so that a pair a rounding error
// inside the support is never two cells further than the reach.
scalar cellSizeOf(const scalar support, const int divisor)
{
    return support/divisor*(1 + 1e-9);
}

// Cells along one direction of the given length (the upper bound itself
// is inside).
scalar cellCount(const scalar length, const scalar invCellSize)
{
    return std::floor(length*invCellSize) + 1;
}

// The most cells the 32-bit sort key holds with the kind (cellKey).
const double maxCells = double(label(1) << (32 - kindBitsOfCellKey)) - 1;

} // End anonymous namespace


int defaultCellDivisor(const point& lower, const point& upper,
                       const scalar support, const int nDimensions,
                       const label nParticles, const bool onGpu)
{
    auto cellsOf = [&](const int divisor)
    {
        const scalar inv = 1/cellSizeOf(support, divisor);
        double cells = 1;
        for (int d = 0; d < nDimensions; ++d)
        {
            cells *= cellCount(upper[d] - lower[d], inv);
        }
        return cells;
    };
    // Cells of 2h/3 walk fewer candidates per neighbour on the GPU
    // (1.2-1.35 times faster in 3D, docs/benchmarks.md), but a mostly
    // empty domain would pay for them in every per-cell pass.
    if (onGpu && cellsOf(3) <= 16.0*nParticles && cellsOf(3) < double(1 << 29))
    {
        return 3;
    }
    return cellsOf(2) < maxCells ? 2 : 1;
}


cellGrid makeCellGrid(const point& lower, const point& upper,
                      const scalar support, const int divisor,
                      const int nDimensions)
{
    if (!(support > 0) || divisor < 1)
    {
        fatalError("makeCellGrid: support radius must be > 0 and the cell"
                   " divisor >= 1");
    }
    cellGrid g;
    g.origin = lower;
    g.cellSize = cellSizeOf(support, divisor);
    g.invCellSize = 1/g.cellSize;
    g.reach = divisor;
    auto count = [&](scalar length)
    {
        const scalar c = cellCount(length, g.invCellSize);
        if (!(c >= 1) || c > 1e6)
        {
            fatalError("The domain's bounds give " + str(double(c))
                + " cells in one direction (length " + str(double(length))
                + " m, cell size " + str(double(g.cellSize)) + " m):"
                  " check the domain of system/sphSchemes, or, without one,"
                  " the particles' positions (a particle far from the rest:"
                  " a damaged field file, or a motion of constant/motion"
                  " that throws a wall far away)");
        }
        return int(c);
    };
    g.nx = count(upper.x - lower.x);
    g.ny = count(upper.y - lower.y);
    g.nz = nDimensions == 3 ? count(upper.z - lower.z) : 1;
    if (nDimensions != 3)
    {
        // 2D: z = 0 everywhere; the one layer of cells is centred on it.
        g.origin.z = -0.5*g.cellSize;
    }
    const double total = double(g.nx)*g.ny*g.nz;
    if (total >= maxCells)
    {
        fatalError("The domain's " + str(total)
            + " cells do not fit the 32-bit cell key (at most 2^30); the"
              " domain is too large for the particle spacing (cellDivisor 1"
              " in system/sphSchemes gives the fewest cells)");
    }
    return g;
}

} // End namespace sphvcpm
