/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "cellList.H"
#include "error.H"

#include <cmath>
#include <limits>
#include <string>

namespace sphvcpm
{

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
    // A hair larger than support/divisor, so that a pair a rounding error
    // inside the support is never two cells further than the reach.
    g.cellSize = support/divisor*(1 + 1e-9);
    g.invCellSize = 1/g.cellSize;
    g.reach = divisor;
    auto count = [&](scalar length)
    {
        const scalar c = std::floor(length*g.invCellSize) + 1;
        if (!(c >= 1) || c > 1e6)
        {
            fatalError("makeCellGrid: the domain bounds give "
                + std::to_string(c) + " cells in one direction (length "
                + std::to_string(length) + " m, cell size "
                + std::to_string(g.cellSize) + " m); check the domain");
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
    // The sort key holds the cell and the kind in 32 bits (cellKey).
    if (total >= double(label(1) << (32 - kindBitsOfCellKey)) - 1)
    {
        fatalError("makeCellGrid: " + std::to_string(total)
            + " cells do not fit the 32-bit cell key (at most 2^30); the"
              " domain is too large for the particle spacing");
    }
    return g;
}

} // End namespace sphvcpm
