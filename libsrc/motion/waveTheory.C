/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "waveTheory.H"

#include <cmath>

namespace sphvcpm
{

scalar waveNumber(const scalar omega, const scalar depth, const scalar g)
{
    // g k tanh(kd) - w^2 increases with k; Newton from the deep-water k
    // (below the root) takes a few steps.
    scalar k = omega*omega/g;
    for (int i = 0; i < 100; ++i)
    {
        const scalar th = std::tanh(k*depth);
        const scalar f = g*k*th - omega*omega;
        const scalar df = g*th + g*k*depth*(1 - th*th);
        const scalar step = f/df;
        k -= step;
        if (std::abs(step) <= 1e-14*k) break;
    }
    return k;
}


scalar pistonHeightOverStroke(const scalar kd)
{
    return 2*(std::cosh(2*kd) - 1)/(std::sinh(2*kd) + 2*kd);
}


scalar flapHeightOverStroke(const scalar kd)
{
    return 4*(std::sinh(kd)/kd)*(kd*std::sinh(kd) - std::cosh(kd) + 1)
          /(std::sinh(2*kd) + 2*kd);
}


scalar micheBreakingHeight(const scalar k, const scalar depth)
{
    const scalar pi = 3.14159265358979323846;
    return 0.142*(2*pi/k)*std::tanh(k*depth);
}

} // End namespace sphvcpm
