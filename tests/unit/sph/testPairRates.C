/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The host's pair form of the fluid rates (each pair once, pairRates.H)
// against the gather form (fluidRatesOp, each particle sums all its
// neighbours) on disordered clouds of fluid over wall layers, 2D and 3D,
// both kernels, cells of 2h, h and 2h/3, laminar and artificial viscosity, SPS
// on and off: the accelerations, density rates and viscous step terms agree
// to round-off, and the pair form gives the same bits serial and threaded.
// Wall particles out of reach of the fluid (nearFluidOp) are skipped. The
// contact push between fluid and wall or solid is on.
// With the lower layers a moving solid instead of a wall, the solid
// particles' rates (the reaction of the fluid's forces) agree in both
// forms too, and the fluid and the solid together conserve momentum to
// round-off.

#include "cellList.H"
#include "fluidInteractions.H"
#include "pairRates.H"
#include "parallel.H"
#include "sphModel.H"
#include "../testPrecision.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace sphvcpm;

namespace
{

struct cloud
{
    int nDim;
    scalar dp, h;
    cellList cells;
    particleFields f;
    pairConstants c;
    std::vector<std::uint8_t> nearFluid;
    label n = 0;

    // A jittered lattice of nx x ny (x nz) nodes; the lowest six layers are
    // wall particles, the deepest of them out of reach of the fluid.
    // Random velocity, density, pressure and SPS stress.
    cloud(int nDim_, int nx, int ny, int nz, int divisor, bool sps,
          bool laminar, scalar support, unsigned seed,
          std::uint8_t lowKind = wallKind)
    :
        nDim(nDim_), dp(0.01), h(0.5*support*0.01)
    {
        std::mt19937_64 gen(seed);
        std::uniform_real_distribution<scalar> u(-1, 1);
        if (nDim == 2) nz = 1;
        n = label(nx)*ny*nz;
        f.resize(n, sps, false);
        if (lowKind == solidKind) f.link.resize(n);
        label k = 0;
        for (int z = 0; z < nz; ++z)
        for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x, ++k)
        {
            const bool wall = (nDim == 2 ? y : z) < 6;
            const scalar jitter = wall ? 0 : 0.3*dp;
            f.position[k] = {(x + 0.5)*dp + jitter*u(gen),
                             (y + 0.5)*dp + jitter*u(gen),
                             nDim == 3 ? (z + 0.5)*dp + jitter*u(gen) : 0};
            f.kind[k] = wall ? lowKind : fluidKind;
            f.velocity[k] = wall && lowKind == wallKind ? vec3{0, 0, 0}
              : vec3{u(gen), u(gen), nDim == 3 ? u(gen) : 0};
            if (!f.link.empty()) f.link[k] = k;
            f.rho[k] = 1000*(1 + 0.01*u(gen));
            f.p[k] = 1e4*u(gen);
            f.mass[k] = 1000*std::pow(dp, nDim);
            f.body[k] = wall ? 0 : 1;
            f.id[k] = k;
            if (sps)
            {
                f.tau[k] = {u(gen), u(gen), u(gen), u(gen), u(gen), u(gen)};
            }
        }
        // Shuffle, then sort by cell as the solver does.
        std::vector<label> perm(n);
        for (label i = 0; i < n; ++i) perm[i] = i;
        std::shuffle(perm.begin(), perm.end(), gen);
        f.reorder(perm, n, sps, false);
        const point upper{(nx + 1)*dp, (ny + 1)*dp, (nz + 1)*dp};
        const cellGrid grid = makeCellGrid({-dp, -dp, nDim == 3 ? -dp : 0},
            upper, 2*h, divisor, nDim);
        buildCellList(openmpExec{}, grid, f.position.data(), f.kind.data(), n,
                      cells);
        f.reorder(cells.order, cells.nInside, sps, false);
        parallelFor(openmpExec{}, n, inverseDensityOp{f.view()});
        nearFluid.resize(n);
        parallelFor(openmpExec{}, n, nearFluidOp{grid, cells.keys.data(),
            f.kind.data(), cells.blockHasFluid.data(), nearFluid.data()});

        c.h = h;
        c.support2 = 4*h*h;
        c.eta2 = 0.01*h*h;
        c.c0 = 30;
        c.rho0 = 1000;
        c.g = nDim == 3 ? vec3{0, 0, -9.81} : vec3{0, -9.81, 0};
        c.laminar = laminar;
        c.fourNu = 4e-3;
        c.alphaC0H = 0.05*c.c0*h;
        c.ddtCoefficient = 0.1*2*h*c.c0;
        c.hydrostaticFactor = c.rho0/(c.c0*c.c0);
        c.sps = sps;
        c.shifting = false;
        c.shiftNoBoundary = false;
        c.tensileInvWdp = 0;
        // The contact push: the first fluid layer lies 0.7-1.3 dp above
        // the top wall layer, so many pairs are within its 0.95 dp.
        sphModel m;
        m.nDimensions = nDim;
        m.dp = dp;
        m.c0 = c.c0;
        m.rho0 = c.rho0;
        c.contact = boundaryContactOf(m);
    }
};

struct rates
{
    std::vector<vec3> acceleration;
    std::vector<scalar> drho, visc;
};

template<class Kernel>
rates gather(cloud& cl, const Kernel& kernel)
{
    std::vector<scalar> visc(cl.n, 0);
    particleView v = cl.f.view();
    parallelFor(openmpExec{}, cl.n, fluidRatesLoopOp<Kernel>{
        {kernel, cl.cells.grid, cl.cells.cellStart.data(),
         cl.cells.kindEnd.data(), v, cl.c},
        visc.data()});
    for (label i = 0; i < cl.n; ++i)
    {
        if (cl.f.kind[i] != fluidKind) visc[i] = 0;
        // The gather form leaves walls' rates as they were.
        if (cl.f.kind[i] == wallKind) cl.f.acceleration[i] = {0, 0, 0};
    }
    return {cl.f.acceleration, cl.f.drho, visc};
}

template<class Exec, class Kernel>
rates pairs(Exec exec, cloud& cl, const Kernel& kernel)
{
    std::vector<scalar> visc(cl.n, 0);
    pairRates(exec, kernel, cl.cells, cl.nearFluid.data(), cl.f.view(), cl.c,
              visc.data());
    return {cl.f.acceleration, cl.f.drho, visc};
}

// Sum of m a over all particles, against the sum of |m a|.
void expectMomentumConserved(const cloud& cl, const rates& r)
{
    vec3 sum{0, 0, 0};
    scalar scale = 0;
    label nSolid = 0;
    for (label i = 0; i < cl.n; ++i)
    {
        const vec3 f = cl.f.mass[i]*r.acceleration[i];
        sum += f;
        scale += mag(f);
        nSolid += cl.f.kind[i] == solidKind && mag(f) > 0;
    }
    ASSERT_GT(nSolid, 10);
    EXPECT_LT(mag(sum), test::tol(1e-13, 1e-6)*scale);
}

// The solid's rates in both forms and the momentum balance.
template<class Kernel>
void compareSolid(int nDim, int divisor, bool sps, bool laminar)
{
    SCOPED_TRACE(::testing::Message() << "solid, " << nDim << "D, cells of 2h/"
        << divisor << (sps ? ", SPS" : "")
        << (laminar ? ", laminar" : ", artificial"));
    cloud cl(nDim, 14, 16, 14, divisor, sps, laminar, 3, 11u + divisor,
             solidKind);
    const Kernel kernel(cl.h, nDim);
    const rates a = gather(cl, kernel);
    const rates b = pairs(openmpExec{}, cl, kernel);
    scalar aScale = 0, aErr = 0;
    for (label i = 0; i < cl.n; ++i)
    {
        aScale = std::max(aScale, mag(a.acceleration[i]));
        aErr = std::max(aErr, mag(a.acceleration[i] - b.acceleration[i]));
    }
    ASSERT_GT(aScale, 0);
    EXPECT_LT(aErr, test::tol(1e-12, 1e-5)*aScale);
    expectMomentumConserved(cl, a);
    expectMomentumConserved(cl, b);
}

template<class Kernel>
void compare(int nDim, int divisor, bool sps, bool laminar)
{
    SCOPED_TRACE(::testing::Message() << nDim << "D, cells of 2h/" << divisor
        << (sps ? ", SPS" : "") << (laminar ? ", laminar" : ", artificial"));
    cloud cl(nDim, 14, 16, 14, divisor, sps, laminar, 3, 7u + divisor);
    const Kernel kernel(cl.h, nDim);
    if (Kernel::tensileCorrection)
    {
        cl.c.tensileInvWdp = 1/kernel.W(cl.dp);
    }
    const rates a = gather(cl, kernel);
    const rates b = pairs(openmpExec{}, cl, kernel);
    const rates s = pairs(serialExec{}, cl, kernel);

    scalar aScale = 0, dScale = 0, vScale = 0;
    label nFluid = 0;
    for (label i = 0; i < cl.n; ++i)
    {
        if (cl.f.kind[i] != fluidKind) continue;
        aScale = std::max(aScale, mag(a.acceleration[i]));
        dScale = std::max(dScale, std::fabs(a.drho[i]));
        vScale = std::max(vScale, a.visc[i]);
        nFluid += cl.f.kind[i] == fluidKind;
    }
    ASSERT_GT(nFluid, 100);
    // Some walls are skipped as out of reach of the fluid, some are not.
    const label nWalls = cl.n - nFluid;
    const label nNear = label(std::count(cl.nearFluid.begin(),
                                         cl.nearFluid.end(), 1)) - nFluid;
    EXPECT_GT(nNear, 0);
    EXPECT_LT(nNear, nWalls);
    ASSERT_GT(aScale, 0);
    ASSERT_GT(dScale, 0);
    ASSERT_GT(vScale, 0);
    // Walls have no rates (the gather form leaves them as they were).
    scalar aErr = 0, dErr = 0, vErr = 0;
    for (label i = 0; i < cl.n; ++i)
    {
        if (cl.f.kind[i] != fluidKind) continue;
        aErr = std::max(aErr, mag(a.acceleration[i] - b.acceleration[i]));
        dErr = std::max(dErr, std::fabs(a.drho[i] - b.drho[i]));
        vErr = std::max(vErr, std::fabs(a.visc[i] - b.visc[i]));
        ASSERT_EQ(b.acceleration[i].x, s.acceleration[i].x) << i;
        ASSERT_EQ(b.acceleration[i].y, s.acceleration[i].y) << i;
        ASSERT_EQ(b.acceleration[i].z, s.acceleration[i].z) << i;
        ASSERT_EQ(b.drho[i], s.drho[i]) << i;
    }
    // The two forms sum in different orders: 7 digits agree in float.
    EXPECT_LT(aErr, test::tol(1e-12, 1e-5)*aScale);
    EXPECT_LT(dErr, test::tol(1e-12, 1e-5)*dScale);
    EXPECT_LT(vErr, test::tol(1e-12, 1e-5)*vScale);
}

} // End anonymous namespace


TEST(pairRates, equalsGatherForm)
{
    for (const int nDim : {2, 3})
    {
        for (const int divisor : {1, 2, 3})
        {
            for (const bool sps : {false, true})
            {
                compare<wendlandC2Kernel>(nDim, divisor, sps, true);
                compare<wendlandC2Kernel>(nDim, divisor, sps, false);
                compare<cubicSplineKernel>(nDim, divisor, sps, true);
            }
        }
    }
}


TEST(pairRates, solidReactionConservesMomentum)
{
    for (const int nDim : {2, 3})
    {
        for (const int divisor : {1, 2, 3})
        {
            compareSolid<wendlandC2Kernel>(nDim, divisor, false, true);
            compareSolid<wendlandC2Kernel>(nDim, divisor, true, false);
            compareSolid<cubicSplineKernel>(nDim, divisor, false, true);
        }
    }
}
