/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The SPH building blocks against analysis (docs/solver.md, Equations):
// kernel normalisation and gradients, lattice sums, the Tait equation of
// state, the fluid rates on a block of particles (rest state, uniform
// pressure, hydrostatic pressure and density, momentum and mass
// conservation, laminar viscosity on linear and parabolic shear), the
// symplectic predictor/corrector and the Verlet step.

#include "cellList.H"
#include "fluidInteractions.H"
#include "parallel.H"
#include "sphModel.H"
#include "../testPrecision.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <ostream>
#include <random>
#include <string>
#include <vector>

using namespace sphvcpm;

namespace sphvcpm
{
// For GoogleTest's messages (vectors and points).
template<class T>
inline void PrintTo(const Vec3<T>& v, std::ostream* os)
{
    *os << '(' << v.x << ' ' << v.y << ' ' << v.z << ')';
}
}

namespace
{

// * * * * * * * * * * * * * * * Kernel helpers * * * * * * * * * * * * * * //

// Composite Simpson rule of f over [a, b] with n (even) intervals.
scalar simpson(const std::function<scalar(scalar)>& f, const scalar a,
               const scalar b, const int n)
{
    const scalar dx = (b - a)/n;
    scalar sum = f(a) + f(b);
    for (int k = 1; k < n; ++k)
    {
        sum += (k % 2 ? 4 : 2)*f(a + k*dx);
    }
    return sum*dx/3;
}

// The integral of W over the plane (2D) or space (3D), radially; split at
// r = h where the cubic spline changes branch.
template<class Kernel>
scalar kernelIntegral(const Kernel& k, const int nDim)
{
    auto f = [&](const scalar r)
    {
        return nDim == 3 ? 4*M_PI*r*r*k.W(r) : 2*M_PI*r*k.W(r);
    };
    return simpson(f, 0, k.h, 4000) + simpson(f, k.h, 2*k.h, 4000);
}

template<class Kernel>
void checkKernel(const std::string& name)
{
    for (const int nDim : {2, 3})
    {
        SCOPED_TRACE(name + " " + std::to_string(nDim) + "D");
        for (const scalar h : {1.0, 0.015, 3.7e-4})
        {
            const Kernel k(h, nDim);
            EXPECT_DOUBLE_EQ(k.support(), 2*h);

            // Normalisation.
            EXPECT_NEAR(kernelIntegral(k, nDim), 1.0, test::tol(1e-9, 1e-5)) << "h = " << h;

            // Compact support, positivity, monotone decrease.
            // q = (2h)(1/h) may round to 2(1 - eps): W(2h) is then the
            // value at that q, (eps)^3 or (eps)^4 of W(0), not exactly 0.
            // In float eps is 6e-8: (eps)^3 of W(0), and 2 + 1e-12 == 2.
            EXPECT_LT(k.W(2*h), test::tol(1e-40, 1e-20)*k.W(0));
            EXPECT_LT(std::fabs(k.gradFactor(2*h)),
                      test::tol(1e-28, 1e-12)*k.W(0)/(h*h));
            const scalar beyond = 2 + test::tol(1e-12, 1e-6);
            EXPECT_EQ(k.W(beyond*h), 0);
            EXPECT_EQ(k.W(2.5*h), 0);
            EXPECT_EQ(k.gradFactor(beyond*h), 0);
            EXPECT_EQ(k.gradFactor(3*h), 0);
            scalar previous = k.W(0);
            EXPECT_GT(previous, 0);
            for (int m = 1; m <= 2000; ++m)
            {
                const scalar r = 2*h*m/2000;
                const scalar W = k.W(r);
                ASSERT_GE(W, 0) << "r/h = " << r/h;
                ASSERT_LE(W, previous) << "r/h = " << r/h;
                previous = W;
                if (m < 2000)
                {
                    ASSERT_LT(k.gradFactor(r), 0) << "r/h = " << r/h;
                }
            }

            // gradFactor = (1/r) dW/dr, against central differences.
            for (const scalar q :
                 {0.02, 0.1, 0.37, 0.7, 0.99, 1.01, 1.3, 1.62, 1.9, 1.98})
            {
                const scalar r = q*h;
                // A wider difference in float, whose W has 7 digits.
                const scalar dr = test::tol(1e-5, 1e-3)*h;
                const scalar dWdr = (k.W(r + dr) - k.W(r - dr))/(2*dr);
                const scalar G = k.gradFactor(r);
                EXPECT_NEAR(G*r, dWdr, test::tol(1e-7, 1e-3)*std::fabs(dWdr)
                    + test::tol(1e-9, 1e-3)*k.W(0)/h)
                    << "q = " << q << " h = " << h;
            }
        }
    }
}

// Sums over a square (2D) or cubic (3D) lattice of spacing dp around the
// lattice point at the origin: sum V W, -sum V G r^2 (the divergence of
// position), sum V gradW and sum V |gradW|.
struct latticeSums
{
    scalar sumW = 0, divR = 0;
    vec3 sumGrad{0, 0, 0};
    scalar sumAbsGrad = 0;
};

template<class Kernel>
latticeSums latticeSum(const Kernel& k, const int nDim, const scalar dp,
                       const vec3& offset)
{
    latticeSums s;
    const scalar V = nDim == 3 ? dp*dp*dp : dp*dp;
    const int reach = int(std::ceil(k.support()/dp)) + 1;
    const int zReach = nDim == 3 ? reach : 0;
    for (int a = -reach; a <= reach; ++a)
    {
        for (int b = -reach; b <= reach; ++b)
        {
            for (int c = -zReach; c <= zReach; ++c)
            {
                // x_ij = x_i - x_j with x_i at offset
                const vec3 xj{a*dp + offset.x, b*dp + offset.y,
                              c*dp + offset.z};
                const vec3 xij = offset - xj;
                const scalar r = mag(xij);
                s.sumW += V*k.W(r);
                if (r > 0)
                {
                    const scalar G = k.gradFactor(r);
                    s.divR -= V*G*r*r;
                    s.sumGrad += (V*G)*xij;
                    s.sumAbsGrad += V*std::fabs(G)*r;
                }
            }
        }
    }
    return s;
}

template<class Kernel>
void checkLattice(const std::string& name)
{
    for (const int nDim : {2, 3})
    {
        SCOPED_TRACE(name + " " + std::to_string(nDim) + "D");
        for (const scalar dp : {1.0, 0.01, 2.5e-4})
        {
            const Kernel k(1.5*dp, nDim);
            const vec3 offset{0.3*dp, -0.7*dp, nDim == 3 ? 0.1*dp : 0};
            const latticeSums s = latticeSum(k, nDim, dp, offset);
            EXPECT_NEAR(s.sumW, 1.0, 0.02) << "dp = " << dp;
            EXPECT_NEAR(s.divR, nDim, 0.03*nDim) << "dp = " << dp;
            EXPECT_LT(mag(s.sumGrad), test::tol(1e-12, 1e-6)*s.sumAbsGrad) << "dp = " << dp;
        }
    }
}


// * * * * * * * * * * * * * * * A block of fluid * * * * * * * * * * * * * //

const scalar rho0 = 1000;
const scalar c0 = 20;

// nx x ny fluid particles (2D) on a square lattice of spacing dp, built
// in a shuffled order, sorted by cell with the cell list, with the
// constants of the pair terms filled by hand.
template<class Kernel>
struct fluidBlock
{
    int nx, ny;
    scalar dp, h;
    Kernel kernel;
    taitEquationOfState eos;
    cellGrid grid;
    cellList list;
    particleFields f;
    pairConstants c;
    label n;

    fluidBlock(const int nx_, const int ny_, const scalar dp_,
               const scalar jitter = 0, const unsigned seed = 1)
    :
        nx(nx_), ny(ny_), dp(dp_), h(1.5*dp_), kernel(h, 2),
        eos(rho0, c0, 7), n(label(nx_)*ny_)
    {
        std::mt19937_64 gen(seed);
        std::uniform_real_distribution<scalar> u(-jitter, jitter);
        std::vector<label> shuffle(n);
        for (label k = 0; k < n; ++k) shuffle[k] = k;
        std::shuffle(shuffle.begin(), shuffle.end(), gen);

        f.resize(n, false, false);
        for (label k = 0; k < n; ++k)
        {
            const label m = shuffle[k];
            const int i = int(m % nx), j = int(m/nx);
            f.position[k] = {(i + 0.5)*dp + u(gen)*dp,
                             (j + 0.5)*dp + u(gen)*dp, 0};
            f.id[k] = m;
        }
        for (label k = 0; k < n; ++k)
        {
            f.velocity[k] = {0, 0, 0};
            f.rho[k] = rho0;
            f.mass[k] = rho0*dp*dp;
            f.kind[k] = fluidKind;
            f.body[k] = 0;
        }
        grid = makeCellGrid({-dp, -dp, 0}, {(nx + 1)*dp, (ny + 1)*dp, 0},
                            kernel.support(), 1, 2);
        buildCellList(openmpExec{}, grid, f.position.data(), f.kind.data(), n,
                      list);
        EXPECT_EQ(list.nInside, n);
        f.reorder(list.order, list.nInside, false, false);
        for (label k = 0; k < n; ++k)
        {
            f.p[k] = 0;
            f.acceleration[k] = {0, 0, 0};
            f.drho[k] = 0;
        }

        c.h = h;
        c.support2 = kernel.support()*kernel.support();
        c.eta2 = 0.01*h*h;
        c.c0 = c0;
        c.rho0 = rho0;
        c.g = {0, 0, 0};
        c.fourNu = 0;
        c.alphaC0H = 0;
        c.laminar = true;
        c.ddtCoefficient = 0.1*2*h*c0;
        c.hydrostaticFactor = rho0/(c0*c0);
        c.sps = false;
        c.shifting = false;
        c.shiftNoBoundary = false;
        c.tensileInvWdp = 0;
    }

    // Lattice indices of particle k (from its unperturbed position).
    int ix(const label k) const { return int(std::floor(f.position[k].x/dp)); }
    int iy(const label k) const { return int(std::floor(f.position[k].y/dp)); }

    // Whether the whole support of particle k lies inside the block.
    bool interior(const label k) const
    {
        const int m = int(std::ceil(kernel.support()/dp));   // 3 layers
        return ix(k) >= m && ix(k) < nx - m && iy(k) >= m && iy(k) < ny - m;
    }

    // Runs the rates over all particles; returns the reduced step terms.
    stepTerms rates()
    {
        parallelFor(openmpExec{}, n, inverseDensityOp{f.view()});
        fluidRatesOp<Kernel> op{kernel, grid, list.cellStart.data(),
                                list.kindEnd.data(), f.view(), c};
        return parallelReduce(openmpExec{}, n, op, stepTerms::identity(n),
                              stepTermsOp{});
    }

    // Whether particle k lies in the m layers next to an edge.
    bool truncated(const label k, const int m) const
    {
        return ix(k) < m || ix(k) >= nx - m || iy(k) < m || iy(k) >= ny - m;
    }

    label countInterior() const
    {
        label count = 0;
        for (label k = 0; k < n; ++k) count += interior(k);
        return count;
    }
};

// The largest |a| of the particles that are not interior.
template<class Block>
scalar maxEdgeAcceleration(const Block& b)
{
    scalar m = 0;
    for (label k = 0; k < b.n; ++k)
    {
        if (!b.interior(k)) m = std::max(m, mag(b.f.acceleration[k]));
    }
    return m;
}

// Sum m a and sum |m a| over the block.
template<class Block>
void momentumSums(const Block& b, vec3& sum, scalar& sumAbs)
{
    sum = {0, 0, 0};
    sumAbs = 0;
    for (label k = 0; k < b.n; ++k)
    {
        sum += b.f.mass[k]*b.f.acceleration[k];
        sumAbs += b.f.mass[k]*mag(b.f.acceleration[k]);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Kernels  * * * * * * * * * * * * * * * //

TEST(sphKernels, wendlandC2)
{
    checkKernel<wendlandC2Kernel>("wendlandC2");

    // Wendland C2: alpha h^2 = 7/(4 pi) in 2D, alpha h^3 = 21/(16 pi) in
    // 3D, and G(0) = -5 alpha/h^2 (bwenh of DualSPHysics).
    const scalar h = 0.02;
    EXPECT_NEAR(wendlandC2Kernel(h, 2).alpha*h*h, 0.557042, 1e-6);
    EXPECT_NEAR(wendlandC2Kernel(h, 3).alpha*h*h*h, 0.417782, 1e-6);
    EXPECT_NEAR(wendlandC2Kernel(h, 2).gradFactor(1e-12*h)*std::pow(h, 4),
                -2.7852, 1e-4);
    EXPECT_NEAR(wendlandC2Kernel(h, 3).gradFactor(1e-12*h)*std::pow(h, 5),
                -2.08891, 1e-5);
}

TEST(sphKernels, cubicSpline)
{
    checkKernel<cubicSplineKernel>("cubicSpline");

    for (const int nDim : {2, 3})
    {
        const scalar h = 0.013;
        const cubicSplineKernel k(h, nDim);
        // Continuity of W and of dW/dr at q = 1; W(h) = alpha/4.
        const scalar below = (1 - 1e-13)*h, above = (1 + 1e-13)*h;
        EXPECT_NEAR(k.W(below), k.W(above), 1e-10*k.W(0));
        EXPECT_NEAR(k.W(h), 0.25*k.alpha, test::tol(1e-14, 1e-6)*k.alpha);
        EXPECT_NEAR(k.gradFactor(below), k.gradFactor(above),
                    1e-10*std::fabs(k.gradFactor(h)));
        EXPECT_NEAR(k.gradFactor(h), -0.75*k.alpha/(h*h),
                    test::tol(1e-12, 1e-6)*k.alpha/(h*h));
        // W -> 0 continuously at q = 2.
        EXPECT_LT(k.W((2 - 1e-6)*h), 1e-17*k.W(0));
        EXPECT_LT(k.W(2*h), test::tol(1e-40, 1e-20)*k.W(0));
    }
}

TEST(sphKernels, shareInFrontOfAPlane)
{
    // Half the kernel on either side of a plane through the point, all of
    // it 2h in front, and a fine lattice's sum of W dV over the half-space
    // in between.
    const scalar h = 0.015;
    for (const int nDim : {2, 3})
    {
        SCOPED_TRACE(std::to_string(nDim) + "D");
        const wendlandC2Kernel w(h, nDim);
        const cubicSplineKernel c(h, nDim);
        for (const scalar d : {0.0, 0.3, -0.7, 1.4, 2.0, 2.5, -2.0})
        {
            const scalar share = kernelShareInFrontOfPlane(w, nDim, d*h);
            EXPECT_NEAR(share + kernelShareInFrontOfPlane(w, nDim, -d*h), 1,
                        1e-6);
            EXPECT_NEAR(kernelShareInFrontOfPlane(c, nDim, d*h)
                      + kernelShareInFrontOfPlane(c, nDim, -d*h), 1,
                        1e-6);
            if (d == 0) EXPECT_NEAR(share, 0.5, 1e-6);
            if (d >= 2) EXPECT_EQ(share, 1);
            // The lattice sum over the half-space x > -d h (the cells
            // the plane cuts by their part in front).
            const int n = nDim == 2 ? 200 : 60;
            const scalar step = 4*h/n;
            scalar sum = 0;
            for (int i = 0; i < n; ++i)
            {
                const scalar x = -2*h + (i + 0.5)*step;
                const scalar inFront = std::clamp(
                    (x + 0.5*step + d*h)/step, scalar(0), scalar(1));
                for (int j = 0; j < n; ++j)
                {
                    const scalar y = -2*h + (j + 0.5)*step;
                    for (int k = 0; k < (nDim == 3 ? n : 1); ++k)
                    {
                        const scalar z =
                            nDim == 3 ? -2*h + (k + 0.5)*step : 0;
                        sum += inFront*w.W(std::sqrt(x*x + y*y + z*z))
                             *std::pow(step, nDim);
                    }
                }
            }
            EXPECT_NEAR(share, sum, 2e-3) << "d = " << d;
        }
    }
}

TEST(sphKernels, latticeSums)
{
    checkLattice<wendlandC2Kernel>("wendlandC2");
    checkLattice<cubicSplineKernel>("cubicSpline");
}


// * * * * * * * * * * * * * * * Equation of state * * * * * * * * * * * * * //

TEST(taitEquationOfState, relations)
{
    for (const scalar gamma : {7.0, 1.4, 1.0})
    {
        SCOPED_TRACE("gamma = " + std::to_string(gamma));
        const taitEquationOfState eos(rho0, c0, gamma);
        EXPECT_DOUBLE_EQ(eos.B, c0*c0*rho0/gamma);
        EXPECT_EQ(eos.pressure(rho0), 0);
        EXPECT_DOUBLE_EQ(eos.density(0), rho0);
        EXPECT_DOUBLE_EQ(eos.soundSpeed(rho0), c0);

        for (const scalar rho : {950.0, 990.5, 999.999, 1000.0, 1000.001,
                                 1003.7, 1021.3, 1100.0})
        {
            const scalar p = eos.pressure(rho);
            EXPECT_NEAR(eos.density(p), rho, test::tol(1e-12, 1e-6)*rho) << "rho " << rho;
            EXPECT_EQ(p > 0, rho > rho0);
            EXPECT_NEAR(p, eos.B*(std::pow(rho/rho0, gamma) - 1),
                        test::tol(1e-13, 1e-6)*eos.B) << "rho " << rho;
            // c^2 = dp/drho (a wider difference in float)
            const scalar d = test::tol(1e-4, 0.1);
            const scalar dpdrho =
                (eos.pressure(rho + d) - eos.pressure(rho - d))/(2*d);
            const scalar cs = eos.soundSpeed(rho);
            EXPECT_NEAR(cs*cs, dpdrho, test::tol(1e-7, 1e-3)*cs*cs) << "rho " << rho;
        }
        for (const scalar p : {-1e4, -10.0, 0.5, 123.0, 5e4})
        {
            EXPECT_NEAR(eos.pressure(eos.density(p)), p, test::tol(1e-10, 1e-6)*eos.B)
                << "p " << p;
        }
    }
}

TEST(taitEquationOfState, gamma7FastPathEqualsPow)
{
    const taitEquationOfState eos(998.2, 37.5, 7);
    ASSERT_EQ(eos.gamma, 7.0);
    std::mt19937_64 gen(3);
    std::uniform_real_distribution<scalar> u(0.5, 1.5);
    for (int m = 0; m < 1000; ++m)
    {
        const scalar rho = eos.rho0*u(gen);
        const scalar reference = eos.B*(std::pow(rho/eos.rho0, 7.0) - 1);
        // A few roundings of (rho/rho0)^7 and of the subtraction of 1.
        const scalar scale =
            eos.B*std::max(1.0, std::pow(rho/eos.rho0, 7.0));
        ASSERT_NEAR(eos.pressure(rho), reference, test::tol(1e-15, 1e-6)*scale)
            << "rho " << rho;
    }
    // The fast path is taken only for gamma exactly 7.
    const taitEquationOfState near7(998.2, 37.5, 7.001);
    EXPECT_NEAR(near7.pressure(1010.0),
                near7.B*(std::pow(1010.0/998.2, 7.001) - 1),
                test::tol(1e-13, 1e-6)*near7.B);
}


// * * * * * * * * * * * * * * * * Fluid rates * * * * * * * * * * * * * * //

TEST(fluidRates, restStateGivesZeroRates)
{
    fluidBlock<wendlandC2Kernel> b(20, 20, 0.01);
    b.c.fourNu = 4e-3;
    const stepTerms t = b.rates();
    EXPECT_EQ(t.firstBad, b.n);
    EXPECT_EQ(t.maxAcc2, 0);
    EXPECT_EQ(t.maxVel2, 0);
    EXPECT_EQ(t.maxVisc, 0);
    for (label k = 0; k < b.n; ++k)
    {
        // Every pair term vanishes, at the edges too.
        EXPECT_EQ(b.f.drho[k], 0) << k;
        EXPECT_EQ(mag(b.f.acceleration[k]), 0) << k;
    }
    EXPECT_EQ(b.countInterior(), 14*14);
}

TEST(fluidRates, uniformPressure)
{
    fluidBlock<wendlandC2Kernel> b(20, 20, 0.01);
    const scalar P = 5000;
    for (label k = 0; k < b.n; ++k) b.f.p[k] = P;
    const stepTerms t = b.rates();
    EXPECT_EQ(t.firstBad, b.n);

    const scalar edge = maxEdgeAcceleration(b);
    // Scale: P/(rho dp) (a pressure jump P over one spacing).
    EXPECT_GT(edge, 0.1*P/(rho0*b.dp));
    const point centre{10*b.dp, 10*b.dp, 0};
    scalar maxAcc2 = 0;
    for (label k = 0; k < b.n; ++k)
    {
        const vec3 a = b.f.acceleration[k];
        maxAcc2 = std::max(maxAcc2, magSqr(a));
        EXPECT_EQ(b.f.drho[k], 0) << k;
        if (b.interior(k))
        {
            EXPECT_LT(mag(a), test::tol(1e-12, 1e-5)*edge)
                << "interior particle " << k;
            continue;
        }
        // Outward, for the particles whose support is cut by an edge: with
        // h = 1.5 dp (support 3 dp) those of the first two layers.
        const int m = 2;
        if (!b.truncated(k, m))
        {
            continue;
        }
        const point x = b.f.position[k];
        EXPECT_GT(dot(a, toVec3(x - centre)), 0) << "particle " << k;
        if (b.ix(k) < m) { EXPECT_LT(a.x, 0) << k; }
        if (b.ix(k) >= b.nx - m) { EXPECT_GT(a.x, 0) << k; }
        if (b.iy(k) < m) { EXPECT_LT(a.y, 0) << k; }
        if (b.iy(k) >= b.ny - m) { EXPECT_GT(a.y, 0) << k; }
        // and not small: at least a tenth of the largest edge value
        const scalar along = std::max(std::fabs(a.x), std::fabs(a.y));
        EXPECT_GT(along, 0.1*edge) << k;
    }
    EXPECT_DOUBLE_EQ(t.maxAcc2, maxAcc2);
    // The block as a whole is not pushed anywhere.
    vec3 sum;
    scalar sumAbs;
    momentumSums(b, sum, sumAbs);
    EXPECT_LT(mag(sum), test::tol(1e-13, 1e-5)*sumAbs);
}

// p = rho0 g (H - y) with rho = rho0: the pressure gradient balances
// gravity in the interior, to the lattice error of -sum V G y^2 = 1.
TEST(fluidRates, hydrostaticPressureBalancesGravity)
{
    fluidBlock<wendlandC2Kernel> b(20, 20, 0.01);
    const scalar g0 = 9.81, H = 0.25;
    b.c.g = {0, -g0, 0};
    for (label k = 0; k < b.n; ++k)
    {
        b.f.p[k] = rho0*g0*(H - b.f.position[k].y);
    }
    b.rates();
    label count = 0;
    for (label k = 0; k < b.n; ++k)
    {
        if (!b.interior(k)) continue;
        ++count;
        const vec3 a = b.f.acceleration[k];
        EXPECT_NEAR(a.y, g0, 0.03*g0) << k;
        EXPECT_NEAR(a.x, 0, test::tol(1e-10, 1e-4)*g0) << k;
    }
    EXPECT_EQ(count, 14*14);
}

// Density diffusion (Fourtakas): a hydrostatic density field
// rho = rho0 + (rho0/c0^2) rho0 g (H - y) gives no diffusion at all, while
// the uncorrected (Molteni-Colagrossi) term does not vanish.
TEST(fluidRates, fourtakasDiffusionVanishesForHydrostaticDensity)
{
    fluidBlock<wendlandC2Kernel> b(20, 20, 0.01);
    const scalar g0 = 9.81, H = 0.25;
    b.c.g = {0, -g0, 0};
    for (label k = 0; k < b.n; ++k)
    {
        b.f.rho[k] = rho0 + b.c.hydrostaticFactor*g0*(H - b.f.position[k].y);
        b.f.mass[k] = b.f.rho[k]*b.dp*b.dp;
        b.f.p[k] = 0;
    }
    b.rates();
    scalar maxCorrected = 0;
    for (label k = 0; k < b.n; ++k)
    {
        maxCorrected = std::max(maxCorrected, std::fabs(b.f.drho[k]));
    }

    b.c.hydrostaticFactor = 0;
    b.rates();
    scalar maxPlain = 0, minInteriorPlain = 1e300;
    for (label k = 0; k < b.n; ++k)
    {
        maxPlain = std::max(maxPlain, std::fabs(b.f.drho[k]));
        if (b.interior(k))
        {
            minInteriorPlain =
                std::min(minInteriorPlain, std::fabs(b.f.drho[k]));
        }
    }
    EXPECT_GT(maxPlain, 0);
    // In float the densities (about 1000) keep 4 digits of their
    // hydrostatic differences, which the correction cancels.
    EXPECT_LT(maxCorrected, test::tol(1e-9, 1e-3)*maxPlain);
    // A linear field has zero Laplacian: the plain term is small in the
    // interior too (it is not zero at the edges).
    EXPECT_LT(minInteriorPlain, test::tol(1e-9, 1e-5)*maxPlain);
}

// Sum_i V_i drho_i = 0 for density diffusion alone (pairwise
// antisymmetric): mass is conserved, with or without the hydrostatic part.
TEST(fluidRates, densityDiffusionConservesMass)
{
    fluidBlock<wendlandC2Kernel> b(20, 20, 0.01, 0.2, 7);
    std::mt19937_64 gen(8);
    std::uniform_real_distribution<scalar> u(-1, 1);
    for (label k = 0; k < b.n; ++k)
    {
        b.f.rho[k] = rho0*(1 + 0.02*u(gen));
        b.f.mass[k] = rho0*b.dp*b.dp;
    }
    for (const scalar g0 : {0.0, 9.81})
    {
        b.c.g = {0, -g0, 0};
        b.rates();
        scalar sum = 0, sumAbs = 0;
        for (label k = 0; k < b.n; ++k)
        {
            const scalar V = b.f.mass[k]/b.f.rho[k];
            sum += V*b.f.drho[k];
            sumAbs += V*std::fabs(b.f.drho[k]);
        }
        EXPECT_GT(sumAbs, 0);
        EXPECT_LT(std::fabs(sum), test::tol(1e-12, 1e-6)*sumAbs) << "g = " << g0;
    }
}

// Pair forces are antisymmetric: sum m a = 0 to round-off for random
// velocities, pressures and densities on a jittered block, with the
// laminar and the artificial viscosity, and with the cubic spline and
// Monaghan's tensile term.
template<class Kernel>
void checkMomentum(const bool laminar, const bool tensile,
                   const bool uniformDensity)
{
    SCOPED_TRACE(std::string(laminar ? "laminar" : "artificial")
                 + (tensile ? ", tensile term" : "")
                 + (uniformDensity ? ", uniform rho" : ", random rho"));
    fluidBlock<Kernel> b(20, 20, 0.01, 0.2, 5);
    std::mt19937_64 gen(6);
    std::uniform_real_distribution<scalar> u(-1, 1);
    b.c.g = {0, 0, 0};
    b.c.ddtCoefficient = 0;
    b.c.hydrostaticFactor = 0;
    b.c.laminar = laminar;
    b.c.fourNu = laminar ? 4e-3 : 0;
    b.c.alphaC0H = laminar ? 0 : 0.02*c0*b.h;
    if (tensile)
    {
        b.c.tensileInvWdp = 1/b.kernel.W(b.dp);
    }
    for (label k = 0; k < b.n; ++k)
    {
        b.f.velocity[k] = {u(gen), u(gen), 0};
        b.f.rho[k] = uniformDensity ? rho0 : rho0*(1 + 0.01*u(gen));
        b.f.mass[k] = rho0*b.dp*b.dp*(1 + 0.1*u(gen));
        b.f.p[k] = 2000*u(gen);
    }
    const stepTerms t = b.rates();
    EXPECT_EQ(t.firstBad, b.n);
    vec3 sum;
    scalar sumAbs;
    momentumSums(b, sum, sumAbs);
    EXPECT_GT(sumAbs, 0);
    EXPECT_LT(mag(sum), test::tol(1e-13, 1e-6)*sumAbs);

    scalar maxVel2 = 0, maxAcc2 = 0;
    for (label k = 0; k < b.n; ++k)
    {
        maxVel2 = std::max(maxVel2, magSqr(b.f.velocity[k]));
        maxAcc2 = std::max(maxAcc2, magSqr(b.f.acceleration[k]));
    }
    EXPECT_EQ(t.maxVel2, maxVel2);
    EXPECT_EQ(t.maxAcc2, maxAcc2);
    EXPECT_GT(t.maxVisc, 0);
}

TEST(fluidRates, momentumConservation)
{
    for (const bool uniformDensity : {true, false})
    {
        checkMomentum<wendlandC2Kernel>(true, false, uniformDensity);
        checkMomentum<wendlandC2Kernel>(false, false, uniformDensity);
        checkMomentum<cubicSplineKernel>(true, true, uniformDensity);
        checkMomentum<cubicSplineKernel>(false, true, uniformDensity);
    }
}

// Fluid over a wall (the lowest 3 rows) and beside a solid (the leftmost
// 3 columns), the wall and solid at zero extrapolated pressure. Under
// tension the fluid's pressure counts as zero in its pairs with them: a
// boundary never pulls fluid into itself, so the fluid moves as if the
// boundary had no mass. Under compression the boundary pushes the fluid
// away.
TEST(fluidRates, boundariesPushButNeverPull)
{
    for (const scalar P : {-2000.0, 2000.0})
    {
        fluidBlock<wendlandC2Kernel> b(20, 20, 0.01);
        for (label k = 0; k < b.n; ++k)
        {
            const bool wall = b.iy(k) < 3, solid = b.ix(k) < 3;
            b.f.kind[k] = wall ? wallKind : solid ? solidKind : fluidKind;
            b.f.p[k] = b.f.kind[k] == fluidKind ? P : 0;
        }
        b.rates();
        std::vector<vec3> withBoundary(b.f.acceleration.begin(),
                                       b.f.acceleration.end());
        for (label k = 0; k < b.n; ++k)
        {
            if (b.f.kind[k] != fluidKind) b.f.mass[k] = 0;
        }
        b.rates();
        // The boundary's share of the acceleration of fluid particle k,
        // next to it along component c (y: the wall, x: the solid).
        label near = 0;
        const auto check = [&](const label k, const int c, const char* what)
        {
            ++near;
            const vec3 push = withBoundary[k] - b.f.acceleration[k];
            const scalar along = c == 0 ? push.x : push.y;
            if (P < 0)
            {
                EXPECT_LT(mag(push), test::tol(1e-12, 1e-5)*mag(withBoundary[k]))
                    << "fluid particle " << k << " pulled by the " << what;
            }
            else
            {
                EXPECT_GT(along, 0.05*P/(rho0*b.dp)) << k << " beside the " << what;
            }
        };
        for (label k = 0; k < b.n; ++k)
        {
            if (b.f.kind[k] != fluidKind) continue;
            // The first two rows above the wall and the first two columns
            // beside the solid, away from each other and from the block's
            // other edges.
            const int i = b.ix(k), j = b.iy(k);
            if (j <= 4 && i >= 6 && i <= 16) check(k, 1, "wall");
            if (i <= 4 && j >= 6 && j <= 16) check(k, 0, "solid");
        }
        EXPECT_EQ(near, 2*2*11);
    }
}

// The Adami wall pressure of a wall on a prescribed motion: the fluid's
// pressure continued into the wall along g - a_w (its acceleration). With
// the hydrostatic field of a tank accelerating upwards at a,
// p = rho0 (g + a) (H - y) at rest in the tank, the Shepard sums make the
// wall's extrapolation exact: p_w = rho0 (g + a) (H - y_w) to round-off,
// on the two floor rows that fluid reaches. Without the wall's
// acceleration (the fixed wall's g alone) they would miss it by
// rho0 a (y_mean - y_w), y_mean the kernel-weighted height of the fluid
// they see, here a = 2 g over 2-3 dp: hundreds of pascals, caught.
TEST(fluidRates, adamiWallPressureOfAcceleratedWall)
{
    fluidBlock<wendlandC2Kernel> b(20, 20, 0.01);
    const scalar g0 = 9.81, a = 2*g0, H = 0.2;
    for (label k = 0; k < b.n; ++k)
    {
        b.f.kind[k] = b.iy(k) < 3 ? wallKind : fluidKind;
        b.f.body[k] = b.f.kind[k] == wallKind ? 1 : 0;
    }
    // Sorted again, now by kind within each cell (forEachFluidCandidate).
    buildCellList(openmpExec{}, b.grid, b.f.position.data(), b.f.kind.data(),
                  b.n, b.list);
    b.f.reorder(b.list.order, b.list.nInside, false, false);
    const scalar yFloor = 3*b.dp;
    for (label k = 0; k < b.n; ++k)
    {
        b.f.p[k] = b.f.kind[k] == fluidKind
                 ? rho0*(g0 + a)*(H - (b.f.position[k].y - yFloor)) : -1;
    }
    bodyMove moves[2] = {bodyMove::none(), bodyMove::none()};
    moves[1].moves = 1;
    moves[1].to.linearAcceleration = {0, a, 0};
    std::vector<std::uint8_t> nearFluid(b.n, 1);
    const auto wallPressures = [&](const bodyMove* m)
    {
        adamiWallOp<wendlandC2Kernel> op{b.kernel, b.grid, b.list.cellStart.data(),
            b.list.kindEnd.data(), b.f.view(), b.eos, b.c.support2, {0, -g0, 0},
            nearFluid.data(), m};
        parallelFor(openmpExec{}, b.n, op);
        std::vector<scalar> p(b.n);
        for (label k = 0; k < b.n; ++k) p[k] = b.f.p[k];
        return p;
    };
    const std::vector<scalar> moving = wallPressures(moves);
    const std::vector<scalar> fixedWall = wallPressures(nullptr);
    label count = 0;
    scalar worstFixed = 0;
    for (label k = 0; k < b.n; ++k)
    {
        if (b.f.kind[k] != wallKind || b.ix(k) < 3 || b.ix(k) >= b.nx - 3) continue;
        if (b.iy(k) == 0)
        {
            // 3 dp below the first fluid row: at the edge of the support
            // (h = 1.5 dp), no fluid in reach, p = 0 either way.
            EXPECT_EQ(moving[k], 0) << k;
            continue;
        }
        ++count;
        const scalar exact = rho0*(g0 + a)*(H - (b.f.position[k].y - yFloor));
        EXPECT_NEAR(moving[k], exact, test::tol(1e-9, 1e-4)*exact) << k;
        EXPECT_NEAR(b.f.rho[k], b.eos.density(fixedWall[k]), 1e-9*rho0) << k;
        worstFixed = std::max(worstFixed, std::abs(fixedWall[k] - exact));
    }
    EXPECT_EQ(count, 2*14);
    EXPECT_GT(worstFixed, 0.5*rho0*a*b.dp);
}

// The contact push between fluid and boundary particles (boundaryContact):
// with no pressure and no motion it is the only force. A fluid particle
// moved toward a wall or solid particle of the same spacing gets
// m_b C(r) x_fb, of magnitude A c0^2/r_c (1 - r/r_c)^2 with
// r_c = 0.95 dp; a solid gets the opposite momentum; nothing else moves;
// at 0.96 dp (beyond r_c), between two fluid particles or with A = 0 there
// is no push. A boundary particle of half the spacing (mass/8 in 3D)
// pushes within r_c = 0.95 (dp + dp/2)/2.
TEST(fluidRates, boundaryContactPush)
{
    const scalar A = 1;
    for (const std::uint8_t kind : {wallKind, solidKind})
    {
        for (const scalar gap : {0.3, 0.9, 0.96})
        {
            for (const bool fluidPair : {false, true})
            {
                fluidBlock<wendlandC2Kernel> b(12, 12, 0.01);
                sphModel m;
                m.nDimensions = 2;
                m.dp = b.dp;
                m.c0 = c0;
                m.rho0 = rho0;
                m.contact = A;
                b.c.contact = boundaryContactOf(m);
                const scalar rc = 0.95*b.dp;
                label mover = -1, target = -1;
                for (label k = 0; k < b.n; ++k)
                {
                    if (b.iy(k) < 3 && !fluidPair) b.f.kind[k] = kind;
                    if (b.ix(k) == 6 && b.iy(k) == 3) mover = k;
                    if (b.ix(k) == 6 && b.iy(k) == 2) target = k;
                }
                // Move the particle at (6, 3) to gap dp above (6, 2), then
                // sort again.
                const label moverId = b.f.id[mover];
                const label targetId = b.f.id[target];
                b.f.position[mover].y = b.f.position[target].y + gap*b.dp;
                buildCellList(openmpExec{}, b.grid, b.f.position.data(),
                              b.f.kind.data(), b.n, b.list);
                b.f.reorder(b.list.order, b.list.nInside, false, false);
                for (label k = 0; k < b.n; ++k)
                {
                    if (b.f.id[k] == moverId) mover = k;
                    if (b.f.id[k] == targetId) target = k;
                }
                b.rates();

                const vec3 d =
                    toVec3(b.f.position[mover] - b.f.position[target]);
                const scalar r = mag(d);
                EXPECT_EQ(r < rc, gap < 0.95);
                const bool pushed = !fluidPair && r < rc;
                const scalar s = 1 - r/rc;
                const vec3 expected = pushed
                  ? (A*c0*c0/rc*s*s/r)*d : vec3{0, 0, 0};
                const vec3 a = b.f.acceleration[mover];
                EXPECT_LT(mag(a - expected), 1e-12*(1 + mag(expected)))
                    << "kind " << int(kind) << ", gap " << gap
                    << (fluidPair ? ", fluid pair" : "");
                if (pushed)
                {
                    EXPECT_GT(a.y, 1e-4*c0*c0/b.dp);
                }
                // The solid's reaction: equal and opposite momentum.
                if (kind == solidKind && !fluidPair)
                {
                    const vec3 sum = b.f.mass[mover]*a
                                   + b.f.mass[target]*b.f.acceleration[target];
                    EXPECT_LT(mag(sum), 1e-12*b.f.mass[mover]*(1 + mag(a)));
                }
                for (label k = 0; k < b.n; ++k)
                {
                    if (k == mover || k == target) continue;
                    if (b.f.kind[k] == wallKind) continue;
                    EXPECT_EQ(mag(b.f.acceleration[k]), 0) << k;
                }
            }
        }
    }

    // The law alone: a finer boundary particle (dp_b = dp/2), in 3D, and
    // A = 0.
    sphModel m;
    m.nDimensions = 3;
    m.dp = 0.01;
    m.c0 = c0;
    m.rho0 = rho0;
    m.contact = A;
    const boundaryContact law = boundaryContactOf(m);
    const scalar mb = rho0*std::pow(0.5*m.dp, 3);
    const scalar rc = 0.95*0.75*m.dp;
    for (const scalar r : {0.1*rc, 0.7*rc, 0.999*rc, 1.001*rc, 0.9*m.dp})
    {
        const scalar s = 1 - r/rc;
        const scalar expected = r < rc
          ? A*c0*c0/(rho0*std::pow(m.dp, 3))*s*s/(rc*r) : 0;
        // In float, 1 - r/rc near rc carries rc/(rc - r) times the
        // rounding: 1e-4 relative at 0.999 rc.
        EXPECT_NEAR(law(r*r, mb), expected, test::tol(1e-12, 1e-3)*expected)
            << r/rc;
    }
    m.contact = 0;
    EXPECT_EQ(boundaryContactOf(m)(0.01*rc*rc, mb), 0);
}

// Linear shear u_x = gamma y: the laminar term is zero in the interior.
TEST(fluidRates, laminarLinearShear)
{
    fluidBlock<wendlandC2Kernel> b(20, 20, 0.01);
    const scalar nu = 1e-3, gammaDot = 3.0;
    b.c.fourNu = 4*nu;
    for (label k = 0; k < b.n; ++k)
    {
        b.f.velocity[k] = {gammaDot*b.f.position[k].y, 0, 0};
    }
    const stepTerms t = b.rates();
    EXPECT_EQ(t.firstBad, b.n);
    const scalar edge = maxEdgeAcceleration(b);
    EXPECT_GT(edge, 0.1*nu*gammaDot/b.dp);
    for (label k = 0; k < b.n; ++k)
    {
        if (b.interior(k))
        {
            EXPECT_LT(mag(b.f.acceleration[k]), test::tol(1e-10, 1e-5)*edge) << k;
        }
        // Incompressible: no density rate anywhere inside.
        if (b.interior(k))
        {
            EXPECT_LT(std::fabs(b.f.drho[k]),
                      test::tol(1e-10, 1e-6)*rho0*gammaDot) << k;
        }
    }
}

// Parabolic profile u_x = y^2: the laminar term approximates
// nu d2u/dy2 = 2 nu in the interior.
TEST(fluidRates, laminarParabolicProfile)
{
    for (const scalar dp : {0.01, 0.005})
    {
        fluidBlock<wendlandC2Kernel> b(20, 20, dp);
        const scalar nu = 1e-3;
        b.c.fourNu = 4*nu;
        for (label k = 0; k < b.n; ++k)
        {
            const scalar y = b.f.position[k].y;
            b.f.velocity[k] = {y*y, 0, 0};
        }
        b.rates();
        label count = 0;
        for (label k = 0; k < b.n; ++k)
        {
            if (!b.interior(k)) continue;
            ++count;
            const vec3 a = b.f.acceleration[k];
            EXPECT_NEAR(a.x, 2*nu, 0.05*2*nu) << "dp " << dp << " k " << k;
            EXPECT_NEAR(a.y, 0, 1e-10*nu) << "dp " << dp << " k " << k;
        }
        EXPECT_EQ(count, 14*14);
    }
}

// Uniform expansion v = eps x: the continuity term gives
// drho/dt = -rho div v = -2 eps rho in the interior (to the lattice error
// of -sum V G r^2 = 2); the artificial viscosity acts only on approaching
// pairs: nothing at all under expansion, under compression a force at the
// edges only (its interior sum is symmetric).
TEST(fluidRates, uniformExpansionAndArtificialViscosity)
{
    fluidBlock<wendlandC2Kernel> b(20, 20, 0.01);
    b.c.laminar = false;
    b.c.alphaC0H = 0.02*c0*b.h;
    const point centre{10*b.dp, 10*b.dp, 0};
    for (const scalar eps : {0.5, -0.5})
    {
        SCOPED_TRACE("eps = " + std::to_string(eps));
        for (label k = 0; k < b.n; ++k)
        {
            b.f.velocity[k] = eps*toVec3(b.f.position[k] - centre);
        }
        const stepTerms t = b.rates();
        EXPECT_EQ(t.firstBad, b.n);
        // max h |v_ij.x_ij|/(r^2 + eta^2) = h |eps| r^2/(r^2 + eta^2) < h|eps|
        EXPECT_LT(t.maxVisc, b.h*std::fabs(eps));
        EXPECT_GT(t.maxVisc, 0.97*b.h*std::fabs(eps));

        label count = 0;
        for (label k = 0; k < b.n; ++k)
        {
            if (b.interior(k))
            {
                ++count;
                EXPECT_NEAR(b.f.drho[k], -2*eps*rho0, 0.03*2*std::fabs(eps)*rho0)
                    << k;
            }
        }
        EXPECT_EQ(count, 14*14);

        const scalar edge = maxEdgeAcceleration(b);
        if (eps > 0)
        {
            EXPECT_EQ(edge, 0);
        }
        else
        {
            EXPECT_GT(edge, 0);
            for (label k = 0; k < b.n; ++k)
            {
                if (b.interior(k))
                {
                    EXPECT_LT(mag(b.f.acceleration[k]),
                              test::tol(1e-12, 1e-5)*edge) << k;
                }
            }
        }
        if (eps > 0)
        {
            for (label k = 0; k < b.n; ++k)
            {
                EXPECT_EQ(mag(b.f.acceleration[k]), 0) << k;
            }
        }
    }
}

// A non-finite pressure is reported as the smallest index of a particle
// whose rates are not finite.
TEST(fluidRates, firstBadReportsNonFiniteRates)
{
    fluidBlock<wendlandC2Kernel> b(20, 20, 0.01);
    const label bad = b.n/2;
    b.f.p[bad] = std::numeric_limits<scalar>::quiet_NaN();
    const stepTerms t = b.rates();
    label expected = b.n;
    for (label k = 0; k < b.n; ++k)
    {
        if (!isFinite(b.f.acceleration[k]) || !isFinite(b.f.drho[k]))
        {
            expected = std::min(expected, k);
        }
    }
    EXPECT_LE(expected, bad);
    EXPECT_EQ(t.firstBad, expected);
}


// * * * * * * * * * * * * * * * * Integration * * * * * * * * * * * * * * //

namespace
{

struct integrator
{
    particleFields f;
    taitEquationOfState eos{rho0, c0, 7};
    vec3 g;
    scalar dt;

    predictorOp predictor()
    {
        return predictorOp{f.view(), eos, g, dt};
    }

    correctorOp corrector()
    {
        return correctorOp{f.view(), eos, g, dt, false, 0, 0, 2, 0};
    }

    label correct()
    {
        const label n = f.size();
        return parallelReduce(serialExec{}, n, corrector(), n, minOp());
    }
};

} // End anonymous namespace

// Constant acceleration: one step of the symplectic scheme is exact.
// Dyadic values make every operation exact, so the comparison is ==.
TEST(symplectic, constantAccelerationDyadic)
{
    integrator s;
    s.f.resize(3, false, false);
    s.g = {0, -8, 0.5};
    s.dt = 1.0/64;
    const point x0{0.25, 0.5, 0.75};
    const vec3 v0{1.5, -0.5, 0.25}, a{2, -4, 0.5};
    for (label k = 0; k < 3; ++k)
    {
        s.f.position[k] = x0;
        s.f.velocity[k] = v0;
        s.f.acceleration[k] = a;
        s.f.rho[k] = 1000;
        s.f.drho[k] = 64;
        s.f.mass[k] = 1;
        s.f.kind[k] = k == 1 ? wallKind : fluidKind;
    }
    parallelFor(serialExec{}, 3, s.predictor());
    EXPECT_EQ(s.f.position[0], x0 + (0.5*s.dt)*v0);
    EXPECT_EQ(s.f.velocity[0], v0 + (0.5*s.dt)*(a + s.g));
    EXPECT_EQ(s.f.velocity0[0], v0);
    EXPECT_EQ(s.f.rho0[0], 1000);
    EXPECT_EQ(s.f.rho[0], 1000 + 0.5*s.dt*64);
    EXPECT_EQ(s.f.p[0], s.eos.pressure(s.f.rho[0]));

    const label result = s.correct();
    EXPECT_EQ(result, 3);
    const vec3 ag = a + s.g;
    for (const label k : {0, 2})
    {
        EXPECT_EQ(s.f.velocity[k], v0 + s.dt*ag) << k;
        EXPECT_EQ(s.f.position[k], x0 + s.dt*v0 + (0.5*s.dt*s.dt)*ag) << k;
        const scalar rhoHalf = 1000 + 0.5*s.dt*64;
        const scalar eps = -64/rhoHalf*s.dt;
        EXPECT_DOUBLE_EQ(s.f.rho[k], 1000*(2 - eps)/(2 + eps)) << k;
        EXPECT_EQ(s.f.p[k], s.eos.pressure(s.f.rho[k])) << k;
    }
    // The wall particle is left alone.
    EXPECT_EQ(s.f.position[1], x0);
    EXPECT_EQ(s.f.velocity[1], v0);
    EXPECT_EQ(s.f.rho[1], 1000);
}

// The same with random values, over many steps: positions and velocities
// follow the parabola to round-off.
TEST(symplectic, constantAccelerationManySteps)
{
    std::mt19937_64 gen(9);
    std::uniform_real_distribution<scalar> u(-1, 1);
    integrator s;
    s.f.resize(50, false, false);
    s.g = {0.1, -9.81, 0.3};
    s.dt = 1.7e-3;
    std::vector<point> x0(50);
    std::vector<vec3> v0(50), a(50);
    for (label k = 0; k < 50; ++k)
    {
        x0[k] = {u(gen), u(gen), u(gen)};
        v0[k] = {u(gen), u(gen), u(gen)};
        a[k] = {10*u(gen), 10*u(gen), 10*u(gen)};
        s.f.position[k] = x0[k];
        s.f.velocity[k] = v0[k];
        s.f.rho[k] = rho0;
        s.f.drho[k] = 0;
        s.f.mass[k] = 1;
        s.f.kind[k] = fluidKind;
    }
    const int nSteps = 100;
    for (int step = 0; step < nSteps; ++step)
    {
        for (label k = 0; k < 50; ++k) s.f.acceleration[k] = a[k];
        parallelFor(openmpExec{}, 50, s.predictor());
        ASSERT_EQ(s.correct(), 50);
    }
    const scalar T = nSteps*s.dt;
    for (label k = 0; k < 50; ++k)
    {
        const vec3 ag = a[k] + s.g;
        const vec3 v = v0[k] + T*ag;
        const point x = x0[k] + T*v0[k] + (0.5*T*T)*ag;
        // 100 steps of rounding: 1e-13 in double, 1e-5 in float.
        const scalar rel = test::tol(1e-13, 1e-5);
        EXPECT_LT(mag(s.f.velocity[k] - v), rel*(mag(v0[k]) + T*mag(ag)));
        EXPECT_LT(mag(s.f.position[k] - x),
                  rel*(mag(x0[k]) + T*mag(v0[k]) + T*T*mag(ag)));
        EXPECT_EQ(s.f.rho[k], rho0);
    }
}

// The corrector reports the smallest index of a particle whose density
// turns negative (epsilon > 2) or whose state is not finite.
TEST(symplectic, correctorReportsBadParticles)
{
    integrator s;
    s.f.resize(5, false, false);
    s.g = {0, -9.81, 0};
    s.dt = 1e-4;
    for (label k = 0; k < 5; ++k)
    {
        s.f.position[k] = {0.1*k, 0, 0};
        s.f.velocity[k] = {0, 0, 0};
        s.f.acceleration[k] = {0, 0, 0};
        s.f.rho[k] = rho0;
        s.f.drho[k] = 0;
        s.f.mass[k] = 1;
        s.f.kind[k] = fluidKind;
    }
    parallelFor(serialExec{}, 5, s.predictor());
    EXPECT_EQ(s.correct(), 5);

    // epsilon = -drho/rho dt = 3 on particles 3 and 4.
    parallelFor(serialExec{}, 5, s.predictor());
    for (const label k : {3, 4})
    {
        s.f.drho[k] = -3*s.f.rho[k]/s.dt;
    }
    EXPECT_EQ(s.correct(), 3);
    EXPECT_LT(s.f.rho[3], 0);

    // epsilon just below 2 keeps a (small) positive density.
    for (label k = 0; k < 5; ++k) s.f.rho[k] = rho0, s.f.drho[k] = 0;
    parallelFor(serialExec{}, 5, s.predictor());
    s.f.drho[2] = -1.9*s.f.rho[2]/s.dt;
    EXPECT_EQ(s.correct(), 5);
    EXPECT_GT(s.f.rho[2], 0);

    // A non-finite acceleration on particle 1.
    for (label k = 0; k < 5; ++k) s.f.rho[k] = rho0, s.f.drho[k] = 0;
    parallelFor(serialExec{}, 5, s.predictor());
    s.f.acceleration[1].y = std::numeric_limits<scalar>::infinity();
    s.f.acceleration[4].x = std::numeric_limits<scalar>::quiet_NaN();
    EXPECT_EQ(s.correct(), 1);

    // A wall particle is never reported.
    for (label k = 0; k < 5; ++k)
    {
        s.f.rho[k] = rho0;
        s.f.drho[k] = 0;
        s.f.acceleration[k] = {0, 0, 0};
        s.f.position[k] = {0.1*k, 0, 0};
        s.f.velocity[k] = {0, 0, 0};
    }
    s.f.kind[0] = wallKind;
    parallelFor(serialExec{}, 5, s.predictor());
    s.f.drho[0] = -3*rho0/s.dt;
    s.f.rho0[0] = rho0;
    EXPECT_EQ(s.correct(), 5);
}


// Far from the origin (a 2 km domain): a slow particle's steps are kept
// and a pair's separation is exact to the physics' precision. In float a
// position at 1 km is resolved to 6.1e-5 m, so positions are points,
// double in both builds (primitives.H); a float position would not move at
// all here.
TEST(symplectic, slowParticleFarFromTheOriginMoves)
{
    integrator s;
    s.f.resize(2, false, false);
    s.g = {0, 0, 0};
    s.dt = 1e-5;
    const point x0{1000.125, -999.875, 0.5};
    const vec3 v0{1e-4, -2e-4, 0};
    for (label k = 0; k < 2; ++k)
    {
        s.f.position[k] = x0 + point{0.003*k, 0.004*k, 0};
        s.f.velocity[k] = v0;
        s.f.acceleration[k] = {0, 0, 0};
        s.f.rho[k] = rho0;
        s.f.drho[k] = 0;
        s.f.mass[k] = 1;
        s.f.kind[k] = fluidKind;
    }
    const label nSteps = 1000;
    for (label step = 0; step < nSteps; ++step)
    {
        parallelFor(serialExec{}, 2, s.predictor());
        ASSERT_EQ(s.correct(), 2);
    }
    // 1e-6 m along x and -2e-6 m along y, a 60th of a float's spacing
    // here, to a thousandth (2000 roundings of a double at 1 km).
    const double t = nSteps*double(s.dt);
    for (label k = 0; k < 2; ++k)
    {
        EXPECT_NEAR(s.f.position[k].x, x0.x + 0.003*k + double(v0.x)*t, 1e-9);
        EXPECT_NEAR(s.f.position[k].y, x0.y + 0.004*k + double(v0.y)*t, 1e-9);
    }
    // The separation, rounded once to the physics' precision.
    const vec3 d = toVec3(s.f.position[1] - s.f.position[0]);
    EXPECT_NEAR(mag(d), 0.005, test::tol(1e-12, 1e-9));
}


// * * * * * * * * * * * * * * * * * Verlet  * * * * * * * * * * * * * * * //

namespace
{

label verletStep(particleFields& f, const taitEquationOfState& eos,
                 const vec3& g, const scalar dt, const scalar span)
{
    const label n = f.size();
    return parallelReduce(serialExec{}, n, verletOp{f.view(), eos, g, dt,
        span}, n, minOp());
}

} // End anonymous namespace

// Constant acceleration and density rate: the Euler step and the Verlet
// step over a span of two steps are both exact (dyadic values: ==), and
// each keeps the state it started from as the previous one. A wall
// particle is left alone.
TEST(verlet, constantAccelerationDyadic)
{
    const taitEquationOfState eos{rho0, c0, 7};
    particleFields f;
    f.resize(2, false, false, true);
    const vec3 g{0, -8, 0.5};
    const scalar dt = 1.0/64;
    const point x0{0.25, 0.5, 0.75};
    const vec3 v0{1.5, -0.5, 0.25}, a{2, -4, 0.5};
    for (label k = 0; k < 2; ++k)
    {
        f.position[k] = x0;
        f.velocity[k] = v0;
        f.acceleration[k] = a;
        f.rho[k] = 1000;
        f.drho[k] = 64;
        f.mass[k] = 1;
        f.kind[k] = k == 1 ? wallKind : fluidKind;
    }
    const vec3 ag = a + g;
    // Euler step (span 0): t = dt.
    EXPECT_EQ(verletStep(f, eos, g, dt, 0), 2);
    EXPECT_EQ(f.position[0], x0 + dt*v0 + (0.5*dt*dt)*ag);
    EXPECT_EQ(f.velocity[0], v0 + dt*ag);
    EXPECT_EQ(f.rho[0], 1000 + dt*64);
    EXPECT_EQ(f.velocityPrevious[0], v0);
    EXPECT_EQ(f.rhoPrevious[0], 1000);
    EXPECT_EQ(f.p[0], eos.pressure(f.rho[0]));
    // Verlet step over the span of two steps: t = 2 dt.
    EXPECT_EQ(verletStep(f, eos, g, dt, 2*dt), 2);
    EXPECT_EQ(f.position[0], x0 + (2*dt)*v0 + (2*dt*dt)*ag);
    EXPECT_EQ(f.velocity[0], v0 + (2*dt)*ag);
    EXPECT_EQ(f.rho[0], 1000 + 2*dt*64);
    EXPECT_EQ(f.velocityPrevious[0], v0 + dt*ag);
    EXPECT_EQ(f.rhoPrevious[0], 1000 + dt*64);
    EXPECT_EQ(f.position[1], x0);
    EXPECT_EQ(f.velocity[1], v0);
    EXPECT_EQ(f.rho[1], 1000);
    // A density driven below zero is reported, a wall's never.
    f.drho[0] = -1e6;
    f.drho[1] = -1e6;
    EXPECT_EQ(verletStep(f, eos, g, dt, 2*dt), 0);
    f.kind[0] = wallKind;
    EXPECT_EQ(verletStep(f, eos, g, dt, 2*dt), 2);
}

// Many steps of varying size under constant acceleration, an Euler step
// every 40: the parabola to round-off, as the symplectic scheme.
TEST(verlet, constantAccelerationVaryingSteps)
{
    std::mt19937_64 gen(11);
    std::uniform_real_distribution<scalar> u(-1, 1);
    const taitEquationOfState eos{rho0, c0, 7};
    particleFields f;
    f.resize(50, false, false, true);
    const vec3 g{0.1, -9.81, 0.3};
    std::vector<point> x0(50);
    std::vector<vec3> v0(50), a(50);
    for (label k = 0; k < 50; ++k)
    {
        x0[k] = {u(gen), u(gen), u(gen)};
        v0[k] = {u(gen), u(gen), u(gen)};
        a[k] = {10*u(gen), 10*u(gen), 10*u(gen)};
        f.position[k] = x0[k];
        f.velocity[k] = v0[k];
        f.rho[k] = rho0;
        f.drho[k] = 0;
        f.mass[k] = 1;
        f.kind[k] = fluidKind;
    }
    scalar T = 0, dtBefore = 0;
    for (int step = 0; step < 100; ++step)
    {
        const scalar dt = 1.7e-3*(1 + 0.3*u(gen));
        for (label k = 0; k < 50; ++k) f.acceleration[k] = a[k];
        ASSERT_EQ(verletStep(f, eos, g, dt,
                             step % 40 == 0 ? 0 : dtBefore + dt), 50);
        T += dt;
        dtBefore = dt;
    }
    for (label k = 0; k < 50; ++k)
    {
        const vec3 ag = a[k] + g;
        const vec3 v = v0[k] + T*ag;
        const point x = x0[k] + T*v0[k] + (0.5*T*T)*ag;
        const scalar rel = test::tol(1e-13, 1e-5);
        EXPECT_LT(mag(f.velocity[k] - v), rel*(mag(v0[k]) + T*mag(ag)));
        EXPECT_LT(mag(f.position[k] - x),
                  rel*(mag(x0[k]) + T*mag(v0[k]) + T*T*mag(ag)));
        EXPECT_EQ(f.rho[k], rho0);
    }
}

// A harmonic oscillator (a = -w^2 x): the Verlet scheme keeps its energy
// bounded and its period to second order, with an Euler step every 40
// steps (these add a first-order error of their own, small at 40).
TEST(verlet, harmonicOscillatorPeriod)
{
    const taitEquationOfState eos{rho0, c0, 7};
    particleFields f;
    f.resize(1, false, false, true);
    f.kind[0] = fluidKind;
    f.mass[0] = 1;
    f.rho[0] = rho0;
    f.drho[0] = 0;
    const scalar w = 2*M_PI;       // period 1
    const vec3 g{0, 0, 0};
    f.position[0] = {1, 0, 0};
    f.velocity[0] = {0, 0, 0};
    const int perPeriod = 200;
    const scalar dt = scalar(1)/perPeriod;
    scalar eMax = 0, eMin = 1e30, lastX = 1;
    int step = 0;
    std::vector<scalar> crossings;      // downward zero crossings of x
    for (; step < 20*perPeriod; ++step)
    {
        f.acceleration[0] = -w*w*toVec3(f.position[0]);
        verletStep(f, eos, g, dt, step % 40 == 0 ? 0 : 2*dt);
        const scalar x = f.position[0].x;
        if (lastX > 0 && x <= 0)
        {
            crossings.push_back((step + lastX/(lastX - x))*dt);
        }
        lastX = x;
        // Energy at the step's own time (v^{n+1} and x^{n+1}).
        const scalar e = 0.5*magSqr(f.velocity[0])
                       + 0.5*w*w*magSqr(f.position[0]);
        eMax = std::max(eMax, e);
        eMin = std::min(eMin, e);
    }
    ASSERT_GE(crossings.size(), 19u);
    const scalar period = (crossings.back() - crossings.front())
                         /(crossings.size() - 1);
    EXPECT_NEAR(period, 1, 2e-3);
    const scalar e0 = 0.5*w*w;
    EXPECT_LT(eMax, 1.02*e0);
    EXPECT_GT(eMin, 0.98*e0);
}
