/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Linear wavemaker theory (libsrc/motion/waveTheory.H): the dispersion
// relation solved in a few Newton steps from shallow to deep water, and
// the piston's and flap's transfer functions finite at every kd (their
// closed forms overflowed to NaN beyond kd = 355), equal to the closed
// forms where those are exact, and with their shallow- and deep-water
// limits.

#include "waveTheory.H"

#include "../testPrecision.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace sphvcpm;

namespace
{

constexpr scalar pi = 3.14159265358979323846;

// The closed forms of the transfer functions in long double: exact to
// about 1e-15 of a double for 0.01 <= kd <= 350 (cosh 2kd - 1 loses
// (2kd)^-2 of the digits), overflowing beyond kd = 5600.
long double pistonClosedForm(const long double kd)
{
    return 2*(std::cosh(2*kd) - 1)/(std::sinh(2*kd) + 2*kd);
}

long double flapClosedForm(const long double kd)
{
    return 4*(std::sinh(kd)/kd)*(kd*std::sinh(kd) - std::cosh(kd) + 1)
          /(std::sinh(2*kd) + 2*kd);
}

} // End anonymous namespace


// Linear wave theory: the dispersion relation solved, its shallow- and
// deep-water limits, and the piston's transfer function with its limits.
TEST(waveTheory, dispersionAndPistonTransfer)
{
    const scalar g = 9.81;
    for (const scalar d : {0.05, 0.25, 2.0, 50.0})
    {
        for (const scalar T : {0.5, 1.0, 3.0})
        {
            const scalar w = 2*pi/T, k = waveNumber(w, d, g);
            EXPECT_NEAR(g*k*std::tanh(k*d)/(w*w), 1, 1e-12) << d << " " << T;
        }
    }
    // Shallow water: k -> w/sqrt(g d), here kd = 0.032 and k is above it
    // by (kd)^2/6 = 1.7e-4; deep: k -> w^2/g.
    EXPECT_NEAR(waveNumber(2*pi/20, 0.1, g)*std::sqrt(g*0.1)/(2*pi/20),
                1 + 1.68e-4, 1e-5);
    EXPECT_NEAR(waveNumber(2*pi/0.5, 10, g)*g/std::pow(2*pi/0.5, 2), 1,
                1e-12);
    // The tutorial's wave: T = 1 s in 0.25 m.
    const scalar k = waveNumber(2*pi, 0.25, g);
    EXPECT_NEAR(k, 4.819, 5e-4);
    EXPECT_NEAR(pistonHeightOverStroke(k*0.25), 1.1626, 1e-4);
    // H/S -> kd in shallow water, 2 in deep water.
    EXPECT_NEAR(pistonHeightOverStroke(1e-3)/1e-3, 1, 1e-6);
    EXPECT_NEAR(pistonHeightOverStroke(20), 2, 1e-12);
    // A flap hinged on the floor: H/S -> kd/2 in shallow water (half a
    // piston's volume), 2 in deep water; 0.6427 for the tutorial's wave.
    EXPECT_NEAR(flapHeightOverStroke(1e-3)/0.5e-3, 1, 1e-6);
    EXPECT_NEAR(flapHeightOverStroke(40), 2*(1 - 1.0/40), 1e-12);
    EXPECT_NEAR(flapHeightOverStroke(k*0.25), 0.6427, 1e-4);
    // Miche: H/L = 0.142 in deep water.
    EXPECT_NEAR(micheBreakingHeight(2*pi/1.5, 100), 0.142*1.5, 1e-12);
}

// H/S of the piston and the flap: finite, positive and rising with kd
// from 1e-8 to 1e4 (the closed forms were NaN from kd = 355 on); the
// closed forms' values where those have their digits; kd (piston) and
// kd/2 (flap) in shallow water, 2 and 2 (1 - 1/kd) in deep water.
TEST(waveTheory, transferFunctionsAtEveryDepth)
{
    scalar lastPiston = 0, lastFlap = 0;
    for (scalar e = -8; e <= 4.0001; e += scalar(0.01))
    {
        const scalar kd = std::pow(scalar(10), e);
        const scalar piston = pistonHeightOverStroke(kd);
        const scalar flap = flapHeightOverStroke(kd);
        ASSERT_TRUE(std::isfinite(piston) && std::isfinite(flap)) << kd;
        EXPECT_GE(piston, lastPiston) << kd;
        EXPECT_GE(flap, lastFlap) << kd;
        EXPECT_LT(flap, piston) << kd;
        EXPECT_LE(piston, 2) << kd;
        lastPiston = piston;
        lastFlap = flap;
        if (kd >= scalar(0.01) && kd <= 350)
        {
            EXPECT_NEAR(piston/pistonClosedForm(kd), 1, test::tol(4e-15, 4e-6))
                << kd;
            EXPECT_NEAR(flap/flapClosedForm(kd), 1, test::tol(4e-15, 4e-6))
                << kd;
        }
    }

    // Shallow water: H/S = kd (1 + O(kd^4)) for the piston, kd/2 (1 +
    // kd^2/12 + ...) for the flap, without the closed forms' cancellation
    // (theirs were off by 1.5e-8 at kd = 1e-4).
    for (const scalar kd : {1e-30, 1e-8, 1e-4})
    {
        EXPECT_NEAR(pistonHeightOverStroke(kd)/kd, 1, test::tol(1e-8, 1e-6));
        EXPECT_NEAR(flapHeightOverStroke(kd)/(kd/2), 1, test::tol(1e-8, 1e-6));
    }
    EXPECT_EQ(pistonHeightOverStroke(0), 0);
    EXPECT_EQ(flapHeightOverStroke(0), 0);

    // Deep water: 2 for the piston, 2 (1 - 1/kd) for the flap (its
    // tanh(kd/2)/kd), at and far beyond where cosh 2kd overflowed.
    for (const scalar kd : {50.0, 355.0, 400.0, 1e3, 1e4, 1e6, 1e30})
    {
        EXPECT_SCALAR_EQ(pistonHeightOverStroke(kd), 2);
        EXPECT_NEAR(flapHeightOverStroke(kd), 2*(1 - 1/kd),
                    test::tol(1e-15, 1e-6));
    }
}

// Newton from Eckart's approximation: at most 6 steps for kd from 1e-5
// to 1e4 (from the deep-water k it took 22 at kd = 1e-5), the relation
// met to rounding.
TEST(waveTheory, waveNumberInFewSteps)
{
    const scalar g = 9.81, d = 1;
    for (scalar e = -10; e <= 4.0001; e += scalar(0.05))
    {
        const scalar x = std::pow(scalar(10), e);       // w^2 d/g
        const scalar w = std::sqrt(x*g/d);
        int steps = 0;
        const scalar k = waveNumber(w, d, g, &steps);
        ASSERT_TRUE(std::isfinite(k) && k > 0) << x;
        EXPECT_LE(steps, 6) << x;
        EXPECT_NEAR(k*d*std::tanh(k*d)/x, 1, test::tol(1e-14, 1e-5)) << x;
    }
    // w^2 d/g beyond the numbers: 0 or not finite, for the caller to
    // refuse (timeFunction does).
    EXPECT_EQ(waveNumber(1e-200, 1, g), 0);
    EXPECT_FALSE(std::isfinite(waveNumber(1e200, 1, g)));
}
