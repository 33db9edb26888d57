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
    previousForce_.assign(n, vec3{0, 0, 0});
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


label fluidSolidCoupling::subSteps(const std::size_t b, const scalar dt) const
{
    return std::max<label>(1, label(std::ceil(
        dt/solids_.bodies()[b].stableDeltaT*(1 - 1e-12))));
}


void fluidSolidCoupling::setClampMotions
(
    const std::vector<const rigidMotion*>& motions
)
{
    clampMotion_ = motions;
}


bodyMove fluidSolidCoupling::clampMoveOf(const std::size_t b, const double t,
                                         const label k, const scalar subDt)
    const
{
    const rigidMotion* m = b < clampMotion_.size() ? clampMotion_[b] : nullptr;
    return m ? m->move(t + k*double(subDt), t + (k + 1)*double(subDt))
             : bodyMove::none();
}


label fluidSolidCoupling::advance(const double t, const scalar dt,
                                  const std::vector<vec3>& force)
{
    label most = 0;
    const std::vector<point> start = position;
    for (std::size_t b = 0; b < solids_.bodies().size(); ++b)
    {
        vcpmSolid& s = *solids_.bodies()[b].solid;
        const label n = subSteps(b, dt);
        const scalar subDt = dt/n;
        std::copy(force.begin() + offsets_[b],
                  force.begin() + offsets_[b + 1], s.externalForce.begin());
        s.computeForces(openmpExec{});
        vcpmSolidView v = s.view();
        v.contact = contact.empty() ? nullptr : contact.data() + offsets_[b];
        for (label k = 0; k < n; ++k)
        {
            v.clampMove = clampMoveOf(b, t, k, subDt);
            vcpmStep(openmpExec{}, v, subDt);
        }
        most = std::max(most, n);
    }
    copyPositions();
    parallelFor(openmpExec{}, size(), meanVelocityOp{position.data(),
        start.data(), dt, meanVelocity.data()});
    return most;
}


void fluidSolidCoupling::keepForceAsStepStart()
{
    if (device_)
    {
        keepForceOnDevice();
        return;
    }
    fluidForceAtStart = fluidForce;
}


label fluidSolidCoupling::advanceFirstHalf(const double t, const scalar dt)
{
    return device_ ? advanceOnDevice(t, dt, false)
                   : advance(t, dt, fluidForceAtStart);
}


label fluidSolidCoupling::advanceSecondHalf(const double t, const scalar dt)
{
    if (device_)
    {
        return advanceOnDevice(t, dt, true);
    }
    parallelFor(openmpExec{}, size(), heldForceOp{fluidForce.data(),
        fluidForceAtStart.data(), heldForce_.data()});
    return advance(t, dt, heldForce_);
}


label fluidSolidCoupling::advanceVerletStep(const double t, const scalar dt,
                                            const bool firstOrder)
{
    if (device_)
    {
        return advanceVerletOnDevice(t, dt, !firstOrder);
    }
    if (firstOrder)
    {
        heldForce_ = fluidForceAtStart;
    }
    else
    {
        parallelFor(openmpExec{}, size(), verletForceOp{
            fluidForceAtStart.data(), previousForce_.data(),
            heldForce_.data()});
    }
    previousForce_ = fluidForceAtStart;
    const scalar early = (1 - verletMeanWindow)*dt;
    const label n = advance(t, early, heldForce_);
    return n + advance(t + double(early), dt - early, heldForce_);
}


void fluidSolidCoupling::saveStepStart()
{
    if (device_)
    {
        saveStepStartOnDevice();
        return;
    }
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
vec3* fluidSolidCoupling::deviceFluidForce() { return nullptr; }
contactPlane* fluidSolidCoupling::deviceContact() { return nullptr; }
bool fluidSolidCoupling::collapsedOnDevice(scalar) const { return false; }
const point* fluidSolidCoupling::devicePosition() const { return nullptr; }
const vec3* fluidSolidCoupling::deviceMeanVelocity() const { return nullptr; }
bool fluidSolidCoupling::nonFiniteOnDevice() const { return false; }
void fluidSolidCoupling::toHost() {}
label fluidSolidCoupling::advanceOnDevice(double, scalar, bool) { return 0; }
label fluidSolidCoupling::advanceVerletOnDevice(double, scalar, bool)
{
    return 0;
}
label fluidSolidCoupling::advanceOnDeviceUnder(double, scalar, const vec3*)
{
    return 0;
}
void fluidSolidCoupling::keepForceOnDevice() {}
void fluidSolidCoupling::saveStepStartOnDevice() {}
#endif

} // End namespace sphvcpm
