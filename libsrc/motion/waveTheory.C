/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "waveTheory.H"

#include <cmath>
#include <limits>

namespace sphvcpm
{

namespace
{

// x/sinh(x) for x >= 0, written as 2x e^{-x}/(1 - e^{-2x}) so that it tends
// to 0 for large x without sinh overflowing (x > 710), and stays accurate
// for small x (expm1).
scalar xOverSinh(const scalar x)
{
    if (x == 0) return 1;
    return 2*x*std::exp(-x)/(-std::expm1(-2*x));
}

} // End anonymous namespace


scalar waveNumber(const scalar omega, const scalar depth, const scalar g,
                  int* iterations)
{
    // In y = kd the relation is y tanh(y) = x, x = w^2 d/g. Newton from
    // Eckart's approximation y = x/sqrt(tanh x) (within 5 % from shallow
    // to deep water, exact in both limits) takes a few steps at any kd;
    // from the deep-water y = x it took a dozen or more at small kd.
    const scalar x = omega*omega*depth/g;
    int steps = 0;
    scalar y = x > 0 ? x/std::sqrt(std::tanh(x)) : 0;
    while (x > 0 && std::isfinite(x) && steps < 50)
    {
        const scalar th = std::tanh(y);
        const scalar step = (y*th - x)/(th + y*(1 - th*th));
        ++steps;
        // A step to y <= 0 (a safeguard: Eckart's start is within 5 %) is
        // a halving instead.
        y = step < y ? y - step : y/2;
        if (std::abs(step)
         <= 4*std::numeric_limits<scalar>::epsilon()*y) break;
    }
    if (iterations) *iterations = steps;
    return y/depth;
}


scalar pistonHeightOverStroke(const scalar kd)
{
    // 2 (cosh 2kd - 1)/(sinh 2kd + 2kd) divided through by sinh 2kd.
    if (kd == 0) return 0;
    return 2*std::tanh(kd)/(1 + xOverSinh(2*kd));
}


scalar flapHeightOverStroke(const scalar kd)
{
    // The piston's times (kd sinh kd - cosh kd + 1)/(kd sinh kd)
    // = 1 - tanh(kd/2)/kd.
    if (kd == 0) return 0;
    return pistonHeightOverStroke(kd)*(1 - std::tanh(kd/2)/kd);
}


scalar micheBreakingHeight(const scalar k, const scalar depth)
{
    const scalar pi = 3.14159265358979323846;
    return 0.142*(2*pi/k)*std::tanh(k*depth);
}

} // End namespace sphvcpm
