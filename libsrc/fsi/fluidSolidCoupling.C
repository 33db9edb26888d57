/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "fluidSolidCoupling.H"
#include "error.H"
#include "parallel.H"

#include <algorithm>
#include <cmath>

namespace sphvcpm
{

fluidSolidCoupling::fluidSolidCoupling(solidBodySet& solids)
:
    solids_(solids)
{
    offsets_.push_back(0);
    for (const solidBody& b : solids_.bodies())
    {
        offsets_.push_back(offsets_.back() + b.solid->size());
    }
    const label n = size();
    position.resize(n);
    meanVelocity.resize(n);
    fluidForce.assign(n, vec3{0, 0, 0});
    fluidForceAtStart.assign(n, vec3{0, 0, 0});
    heldForce_.resize(n);
    copyPositions();
    // Until a step has moved them, the solids' own velocity.
    for (std::size_t b = 0; b < solids_.bodies().size(); ++b)
    {
        const vcpmSolid& s = *solids_.bodies()[b].solid;
        std::copy(s.velocity.begin(), s.velocity.end(),
                  meanVelocity.begin() + offsets_[b]);
    }
}


void fluidSolidCoupling::copyPositions()
{
    for (std::size_t b = 0; b < solids_.bodies().size(); ++b)
    {
        const vcpmSolid& s = *solids_.bodies()[b].solid;
        std::copy(s.position.begin(), s.position.end(),
                  position.begin() + offsets_[b]);
    }
}


label fluidSolidCoupling::advance(const scalar dt,
                                  const std::vector<vec3>& force)
{
    label most = 0;
    const std::vector<vec3> start = position;
    for (std::size_t b = 0; b < solids_.bodies().size(); ++b)
    {
        solidBody& body = solids_.bodies()[b];
        vcpmSolid& s = *body.solid;
        // The sub-step: the largest that divides dt and is stable.
        const label n = std::max<label>(1,
            label(std::ceil(dt/body.stableDeltaT*(1 - 1e-12))));
        const scalar subDt = dt/n;
        if (device_)
        {
            advanceOnDevice(b, force.data() + offsets_[b], n, subDt);
            most = std::max(most, n);
            continue;
        }
        std::copy(force.begin() + offsets_[b],
                  force.begin() + offsets_[b + 1], s.externalForce.begin());
        s.computeForces(openmpExec{});
        for (label k = 0; k < n; ++k)
        {
            s.step(openmpExec{}, subDt);
        }
        most = std::max(most, n);
    }
    copyPositions();

    // The mean velocity over this half step.
    const label n = size();
    for (label i = 0; i < n; ++i)
    {
        meanVelocity[i] = (1/dt)*(position[i] - start[i]);
    }
    return most;
}


label fluidSolidCoupling::advanceFirstHalf(const scalar dt)
{
    return advance(dt, fluidForceAtStart);
}


label fluidSolidCoupling::advanceSecondHalf(const scalar dt)
{
    const label n = size();
    for (label i = 0; i < n; ++i)
    {
        heldForce_[i] = scalar(2)*fluidForce[i] - fluidForceAtStart[i];
    }
    return advance(dt, heldForce_);
}


void fluidSolidCoupling::saveStepStart()
{
    // position already holds the solids' positions, in this order.
    startPosition_ = position;
    startVelocity_.clear();
    for (const solidBody& b : solids_.bodies())
    {
        const vcpmSolid& s = *b.solid;
        startVelocity_.insert(startVelocity_.end(), s.velocity.begin(),
                              s.velocity.end());
    }
    startMeanVelocity_ = meanVelocity;
}


void fluidSolidCoupling::restoreStepStart()
{
    for (std::size_t b = 0; b < solids_.bodies().size(); ++b)
    {
        vcpmSolid& s = *solids_.bodies()[b].solid;
        std::copy(startPosition_.begin() + offsets_[b],
                  startPosition_.begin() + offsets_[b + 1],
                  s.position.begin());
        std::copy(startVelocity_.begin() + offsets_[b],
                  startVelocity_.begin() + offsets_[b + 1],
                  s.velocity.begin());
    }
    copyPositions();
    meanVelocity = startMeanVelocity_;
}



#ifndef SPHVCPM_HAVE_CUDA
// Without the CUDA backend the solver never asks for the device.
void deviceSolidsDeleter::operator()(deviceSolids*) const {}
void fluidSolidCoupling::useDevice()
{
    fatalError("no CUDA backend in this build");
}
void fluidSolidCoupling::advanceOnDevice(std::size_t, const vec3*, label,
                                         scalar)
{}
#endif

} // End namespace sphvcpm
