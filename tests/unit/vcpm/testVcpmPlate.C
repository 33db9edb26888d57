/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The oscillating plate of Gray, Monaghan & Swift (2001),
// OSCILLATING_PLATE.md: a cantilever L = 0.2, H = 0.02 (E = 2 MPa,
// nu = 0.3975, rho = 1000, plane strain as the reference's K implies)
// started from rest shape with the first-mode velocity profile
// V_f c0 f(x/L), run undamped for ten periods. Checks the period of the
// tip-centre deflection against Euler-Bernoulli and that the energy does
// not grow: with the surface correction (the default) against the
// reference directly, without it against the error model.

#include "vcpmBeam.H"
#include "../testPrecision.H"
#include "solidBodySet.H"
#include "vcpmSolid.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace sphvcpm;

namespace
{

// First cantilever mode shape, normalised to f(1) = 1 (the reference's
// M, N, Q form).
scalar firstMode(const scalar xi)
{
    const scalar kL = 1.875104;
    const scalar M = std::sin(kL) + std::sinh(kL);
    const scalar N = std::cos(kL) + std::cosh(kL);
    const scalar Q = 2*(std::cos(kL)*std::sinh(kL) - std::sin(kL)*std::cosh(kL));
    const scalar a = kL*xi;
    return (M*(std::cos(a) - std::cosh(a)) - N*(std::sin(a) - std::sinh(a)))/Q;
}

struct plateResult
{
    scalar period;          // from the zero crossings of the tip deflection
    label nCrossings;
    scalar firstPeak;       // max |w| over the first period
    scalar lastPeak;        // max |w| over the last period
    scalar maxDriftPlain;   // max |E - E0|/E0, E = K + U
    scalar maxDriftShadow;  // max |H - H0|/H0, H = E - dt^2/8 sum|f|^2/m
    scalar growthLastFirst; // mean E over the last period / first - 1
};

// Runs nPeriods of the expected period Texp and measures.
plateResult runPlate(const int nLayers, const scalar Vf, const scalar Texp,
                     const scalar nPeriods, const bool surface,
                     const scalar latticeDamping = 0)
{
    const scalar L = 0.2, H = 0.02, E = 2e6, nu = 0.3975, rho = 1000;
    const scalar l0 = H/nLayers;
    vcpmMaterial m(E, nu, rho, vcpmLattice::square2D, l0,
                   planeModel::planeStrain, 1);
    m.surfaceCorrection = surface;
    // Two columns inside the support, clamped: the clamp carries moment.
    const std::vector<point> X0 =
        cantileverLattice(label(std::lround(L/l0)), nLayers, 2, l0);
    vcpmSolid s(m, X0, clampedBehind(X0));
    s.latticeDamping = latticeDamping;
    const scalar c0 = std::sqrt(E/(3*(1 - 2*nu))/rho);
    std::vector<label> tip;
    for (label p = 0; p < s.size(); ++p)
    {
        const point& X = s.reference()[p];
        if (X.x > 0) s.velocity[p].y = Vf*c0*firstMode(X.x/L);
        if (X.x > L - l0) tip.push_back(p);
    }

    // The tip centre: the mean of the last column (its centreline).
    auto tipDeflection = [&]()
    {
        scalar w = 0;
        for (const label p : tip) w += s.position[p].y - s.reference()[p].y;
        return w/tip.size();
    };

    const scalar dt = m.stableTimeStep(0.5);
    s.computeForces(serialExec{});
    auto energies = [&](scalar& plain, scalar& shadow)
    {
        // Free particles only: a clamped one's force is not in the dynamics.
        scalar f2 = 0;
        for (label p = 0; p < s.size(); ++p)
        {
            if (!s.clamped()[p]) f2 += magSqr(s.force[p]);
        }
        plain = s.kineticEnergy() + s.elasticEnergy(serialExec{});
        shadow = plain - dt*dt/(8*m.mass)*f2;
    };
    scalar E0, H0;
    energies(E0, H0);

    plateResult r{0, 0, 0, 0, 0, 0, 0};
    const long nSteps = std::lround(nPeriods*Texp/dt);
    const long everyE = 20;
    scalar firstCrossing = -1, lastCrossing = -1, wOld = 0, tOld = 0;
    scalar sumFirst = 0, sumLast = 0;
    label nFirst = 0, nLast = 0;
    for (long it = 1; it <= nSteps; ++it)
    {
        s.step(serialExec{}, dt);
        const scalar t = it*dt;
        const scalar w = tipDeflection();
        if (t < Texp) r.firstPeak = std::max(r.firstPeak, std::abs(w));
        if (t > (nPeriods - 1)*Texp)
        {
            r.lastPeak = std::max(r.lastPeak, std::abs(w));
        }
        // Sign changes, linearly interpolated; a quarter period apart at
        // least, so that ripples of the higher modes do not count.
        if (wOld*w < 0)
        {
            const scalar tc = tOld + (t - tOld)*wOld/(wOld - w);
            if (lastCrossing < 0 || tc - lastCrossing > 0.25*Texp)
            {
                if (firstCrossing < 0) firstCrossing = tc;
                lastCrossing = tc;
                ++r.nCrossings;
            }
        }
        wOld = w;
        tOld = t;

        if (it % everyE == 0)
        {
            scalar En, Hn;
            energies(En, Hn);
            r.maxDriftPlain = std::max(r.maxDriftPlain, std::abs(En/E0 - 1));
            r.maxDriftShadow = std::max(r.maxDriftShadow, std::abs(Hn/H0 - 1));
            if (t < Texp) { sumFirst += En; ++nFirst; }
            if (t > (nPeriods - 1)*Texp) { sumLast += En; ++nLast; }
        }
    }
    if (r.nCrossings > 1)
    {
        r.period = 2*(lastCrossing - firstCrossing)/(r.nCrossings - 1);
    }
    r.growthLastFirst = (sumLast/nLast)/(sumFirst/nFirst) - 1;
    return r;
}

} // End anonymous namespace


namespace
{

const scalar L = 0.2, H = 0.02, E = 2e6, nu = 0.3975, rho = 1000;
const scalar Vf = 0.001;     // tip amplitude about 2.3 mm: linear
const scalar kL = 1.875104;
const scalar EI = E/(1 - nu*nu)*H*H*H/12;
const scalar omega = kL*kL/(L*L)*std::sqrt(EI/(rho*H));
const scalar T = 2*M_PI/omega;      // 0.25403 s; the reference: 0.2540 s

int layers(const int otherwise)
{
    const char* env = std::getenv("SPHVCPM_PLATE_LAYERS");
    return env ? std::atoi(env) : otherwise;
}

void report(const int n, const plateResult& r, const scalar Texp,
            const scalar ratio, const bool surface)
{
    const scalar c0 = std::sqrt(E/(3*(1 - 2*nu))/rho);
    std::printf("oscillating plate n = %d, surface correction %s: T = %.5f s "
                "(%d crossings), Euler-Bernoulli %.5f (raw %+.2f %%), "
                "EI ratio (model) %.4f -> expected %.5f (%+.2f %%)\n",
                n, surface ? "on" : "off", r.period, int(r.nCrossings), T,
                100*(r.period/T - 1), ratio, Texp, 100*(r.period/Texp - 1));
    std::printf("  first peak %.4e m, v0/omega %.4e, v0/omega_lattice %.4e; "
                "energy: max|E/E0 - 1| %.2e, max|H/H0 - 1| %.2e, "
                "last/first period mean E - 1 = %.2e\n",
                r.firstPeak, Vf*c0/omega, Vf*c0/(omega*std::sqrt(ratio)),
                r.maxDriftPlain, r.maxDriftShadow, r.growthLastFirst);
}

void expectNoEnergyGrowth(const plateResult& r)
{
    // No damping: the Verlet-conserved H stays put (measured 1e-10 or
    // less; the geometric nonlinearity at A/L ~ 1 % is the rest), and the
    // mean K + U of the last period is not above the first.
    EXPECT_LT(r.maxDriftShadow, 1e-8);
    EXPECT_LT(r.maxDriftPlain, 1e-4);
    EXPECT_LT(r.growthLastFirst, 1e-6);
}

} // End anonymous namespace


// Issue 4's check on the default path (surface correction on): the period
// within 3 % of the reference's Euler-Bernoulli T = 0.2540 s, raw, at
// H/l0 = 5 layers (260 particles, 2 clamped columns), the fewest that pass
// (docs/vcpm.md: +0.9 % at 5, the rest shear and rotary inertia; 4
// layers: see there), and no energy growth
// over ten periods. SPHVCPM_PLATE_LAYERS=n runs another resolution.
TEST(vcpmSolid, oscillatingPlate)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    ASSERT_TRUE(vcpmMaterial::defaultSurfaceCorrection);
    const int n = layers(5);
    const plateResult r = runPlate(n, Vf, T, 10.25,
                                   vcpmMaterial::defaultSurfaceCorrection);
    const vcpmMaterial m(E, nu, rho, vcpmLattice::square2D, H/n,
                         planeModel::planeStrain, 1);
    report(n, r, T, 1 + thinMemberStiffnessError(n, m), true);
    EXPECT_GE(r.nCrossings, 20);
    EXPECT_NEAR(r.period/T, 1, 0.03);
    // The reference's other check: the first peak against the linear
    // v0/omega, V_f <= 0.01 (measured -1.2 % at 5 layers: the period's
    // +0.9 % and the higher modes the start excites).
    const scalar c0 = std::sqrt(E/(3*(1 - 2*nu))/rho);
    EXPECT_NEAR(r.firstPeak/(Vf*c0/omega), 1, 0.03);
    expectNoEnergyGrowth(r);
}

// The plain lattice (surfaceCorrection off), 6 layers (372 particles): its
// bending stiffness is low by thinMemberStiffnessError(off) (-12.7 % here),
// the raw period 8 % long; against Euler-Bernoulli times sqrt(EI/EI_lattice)
// from that model it is within 3 % (measured +1.1 %).
TEST(vcpmSolid, oscillatingPlateUncorrected)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    const int n = layers(6);
    const scalar ratio =
        1 + thinMemberStiffnessError(n, nu, planeModel::planeStrain, false);
    const scalar Texp = T/std::sqrt(ratio);
    const plateResult r = runPlate(n, Vf, Texp, 10.25, false);
    report(n, r, Texp, ratio, false);
    EXPECT_GE(r.nCrossings, 20);
    EXPECT_NEAR(r.period/Texp, 1, 0.03);
    expectNoEnergyGrowth(r);
}

// Lattice damping (bondForceOp) at the solver's default ratio for the
// lattice's highest mode: the plate's first mode keeps its period, and its
// amplitude decays as stiffness-proportional damping C = beta K predicts,
// zeta1 = beta omega1/2 with beta = zeta/omega_s, omega_s = sqrt(2 k1/m):
// 2e-5 at this coarse lattice (5 layers), 0.14 % of the amplitude over the
// 9.25 periods from the first peak to the last.
TEST(vcpmSolid, oscillatingPlateLatticeDamping)
{
    SPHVCPM_DOUBLE_ONLY();
    const int n = 5;
    const plateResult plain = runPlate(n, Vf, T, 10.25, true);
    const scalar zeta = solidBodySet::defaultLatticeDamping;
    const plateResult damped = runPlate(n, Vf, T, 10.25, true, zeta);
    const vcpmMaterial m(E, nu, rho, vcpmLattice::square2D, H/n,
                         planeModel::planeStrain, 1);
    const scalar beta = zeta/std::sqrt(2*m.k1/m.mass);
    const scalar omega1 = 2*M_PI/plain.period;
    const scalar expectedLoss =
        1 - std::exp(-0.5*beta*omega1*omega1*9.25*plain.period);
    const scalar loss = 1 - (damped.lastPeak/damped.firstPeak)
                           /(plain.lastPeak/plain.firstPeak);
    std::printf("lattice damping %.3f: T = %.6f s (undamped %.6f s, %+.2e); "
                "amplitude lost over 9.25 periods %.3e, beta K predicts "
                "%.3e\n", zeta, damped.period, plain.period,
                damped.period/plain.period - 1, loss, expectedLoss);
    EXPECT_GE(damped.nCrossings, 20);
    EXPECT_NEAR(damped.period/plain.period, 1, 1e-4);
    EXPECT_GT(loss, 0.5*expectedLoss);
    EXPECT_LT(loss, 2*expectedLoss);
}
