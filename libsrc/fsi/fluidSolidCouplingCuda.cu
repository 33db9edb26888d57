/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The coupling on the GPU: the solids' state (positions, velocities,
// forces, clamps, stretch sums) in flat device arrays in the coupling's
// solid order, each body's bond list beside them, and the coupling's own
// arrays (fluid forces, the mean velocity, the step-start copies). The
// sub-cycle runs vcpmStep (vcpmInteractions.H) on views into the flat
// arrays, so nothing crosses the bus during a step; toHost() brings the
// state back for writes, function objects and diagnoses.
#include "fluidSolidCoupling.H"
#include "fluidInteractions.H"
#include "parallelCuda.cuh"

#include <vector>

namespace sphvcpm
{

namespace
{

template<class T>
deviceBuffer<T> uploaded(const std::vector<T>& host)
{
    deviceBuffer<T> d(label(host.size()));
    if (!host.empty()) d.copyFromHost(host);
    return d;
}

template<class T>
void copyOnDevice(deviceBuffer<T>& to, const deviceBuffer<T>& from)
{
    copyDeviceToDevice(to.data(), from.data(), sizeof(T)*from.size());
}

// The smallest index of a non-finite position (n when none).
struct firstNonFiniteOp
{
    const point* position;
    label n;

    SPHVCPM_HD label operator()(const label i) const
    {
        return isFinite(position[i]) ? n : i;
    }
};

} // End anonymous namespace


// One body's bond list in device memory (its indices are the body's own).
struct deviceBonds
{
    label nBonds;
    deviceBuffer<label> first, second;
    deviceBuffer<std::uint8_t> layer;
    deviceBuffer<scalar> length, weight, pairFactor;
    deviceBuffer<label> start, adjacency;

    explicit deviceBonds(const bondList& b)
    :
        nBonds(b.nBonds()),
        first(uploaded(b.first())),
        second(uploaded(b.second())),
        layer(uploaded(b.layer())),
        length(uploaded(b.length())),
        weight(uploaded(b.weight())),
        pairFactor(uploaded(b.pairFactor()))
    {
        // The CSR arrays are not exposed as vectors: copy through the view.
        const bondView v = b.view();
        const label n = b.nParticles();
        start = deviceBuffer<label>(v.start, n + 1);
        adjacency = deviceBuffer<label>(v.adjacency, v.start[n]);
    }

    bondView view() const
    {
        return {nBonds, first.data(), second.data(), layer.data(),
                length.data(), weight.data(), pairFactor.data(),
                start.data(), adjacency.data()};
    }
};


struct deviceSolids
{
    std::vector<deviceBonds> bonds;
    // The solids, flat in the coupling's order.
    deviceBuffer<point> position;
    deviceBuffer<vec3> velocity, force, clampVelocity;
    deviceBuffer<std::uint8_t> clamped;
    deviceBuffer<scalar> stretchSum;             // 2 per particle
    // The coupling's arrays.
    deviceBuffer<vec3> fluidForce, fluidForceAtStart, heldForce;
    deviceBuffer<vec3> previousForce;    // F^{n-1} of the Verlet steps
    deviceBuffer<vec3> meanVelocity;
    deviceBuffer<point> halfStart, startPosition;
    deviceBuffer<vec3> startVelocity, startMeanVelocity;
    deviceBuffer<contactPlane> contact;          // empty without contact
};


void deviceSolidsDeleter::operator()(deviceSolids* solids) const
{
    delete solids;
}


void fluidSolidCoupling::useDevice()
{
    // Flat host copies of what the bodies hold, in the coupling's order.
    std::vector<vec3> velocity, clampVelocity;
    std::vector<std::uint8_t> clamped;
    std::vector<scalar> stretchSum;
    device_.reset(new deviceSolids);
    for (solidBody& body : solids_.bodies())
    {
        const vcpmSolid& s = *body.solid;
        device_->bonds.emplace_back(s.bonds());
        velocity.insert(velocity.end(), s.velocity.begin(), s.velocity.end());
        clampVelocity.insert(clampVelocity.end(), s.clampVelocity.begin(),
                             s.clampVelocity.end());
        clamped.insert(clamped.end(), s.clamped().begin(), s.clamped().end());
        stretchSum.insert(stretchSum.end(), s.stretchSum.begin(),
                          s.stretchSum.end());
    }
    deviceSolids& d = *device_;
    const label n = size();
    d.position = uploaded(position);
    d.velocity = uploaded(velocity);
    d.force = deviceBuffer<vec3>(n);
    d.clampVelocity = uploaded(clampVelocity);
    d.clamped = uploaded(clamped);
    d.stretchSum = uploaded(stretchSum);
    d.fluidForce = uploaded(fluidForce);
    d.fluidForceAtStart = uploaded(fluidForceAtStart);
    d.heldForce = deviceBuffer<vec3>(n);
    d.previousForce = uploaded(previousForce_);
    d.meanVelocity = uploaded(meanVelocity);
    d.halfStart = deviceBuffer<point>(n);
    d.startPosition = deviceBuffer<point>(n);
    d.startVelocity = deviceBuffer<vec3>(n);
    d.startMeanVelocity = deviceBuffer<vec3>(n);
    if (!contact.empty()) d.contact = uploaded(contact);
}


vec3* fluidSolidCoupling::deviceFluidForce()
{
    return device_->fluidForce.data();
}


contactPlane* fluidSolidCoupling::deviceContact()
{
    return contact.empty() ? nullptr : device_->contact.data();
}


const point* fluidSolidCoupling::devicePosition() const
{
    return device_->position.data();
}


const vec3* fluidSolidCoupling::deviceMeanVelocity() const
{
    return device_->meanVelocity.data();
}


void fluidSolidCoupling::keepForceOnDevice()
{
    copyOnDevice(device_->fluidForceAtStart, device_->fluidForce);
}


void fluidSolidCoupling::saveStepStartOnDevice()
{
    deviceSolids& d = *device_;
    copyOnDevice(d.startPosition, d.position);
    copyOnDevice(d.startVelocity, d.velocity);
    copyOnDevice(d.startMeanVelocity, d.meanVelocity);
}


label fluidSolidCoupling::advanceOnDevice(const double t, const scalar dt,
                                          const bool secondHalf)
{
    deviceSolids& d = *device_;
    const label nAll = size();
    if (secondHalf)
    {
        parallelFor(cudaExec{}, nAll, heldForceOp{d.fluidForce.data(),
            d.fluidForceAtStart.data(), d.heldForce.data()});
    }
    return advanceOnDeviceUnder(t, dt, secondHalf ? d.heldForce.data()
                                                  : d.fluidForceAtStart.data());
}


label fluidSolidCoupling::advanceVerletOnDevice(const double t,
                                                const scalar dt,
                                                const bool secondOrder)
{
    deviceSolids& d = *device_;
    if (secondOrder)
    {
        parallelFor(cudaExec{}, size(), verletForceOp{
            d.fluidForceAtStart.data(), d.previousForce.data(),
            d.heldForce.data()});
    }
    else
    {
        copyOnDevice(d.heldForce, d.fluidForceAtStart);
    }
    copyOnDevice(d.previousForce, d.fluidForceAtStart);
    const scalar early = (1 - verletMeanWindow)*dt;
    const label n = advanceOnDeviceUnder(t, early, d.heldForce.data());
    return n + advanceOnDeviceUnder(t + double(early), dt - early,
                                    d.heldForce.data());
}


label fluidSolidCoupling::advanceOnDeviceUnder(const double t,
                                               const scalar dt,
                                               const vec3* held)
{
    deviceSolids& d = *device_;
    const label nAll = size();
    copyOnDevice(d.halfStart, d.position);

    label most = 0;
    for (std::size_t b = 0; b < solids_.bodies().size(); ++b)
    {
        const vcpmSolid& s = *solids_.bodies()[b].solid;
        const label o = offsets_[b];
        vcpmSolidView v{s.size(), d.bonds[b].view(), s.constants(),
            s.material().mass, s.gravity, s.damping, s.bondViscosity(),
            d.position.data() + o,
            d.velocity.data() + o, d.force.data() + o, held + o,
            d.clamped.data() + o, d.clampVelocity.data() + o,
            d.stretchSum.data() + 2*o, bodyMove::none(),
            contact.empty() ? nullptr : d.contact.data() + o};
        const label n = subSteps(b, dt);
        const scalar subDt = dt/n;
        vcpmComputeForces(cudaExec{}, v);
        for (label k = 0; k < n; ++k)
        {
            v.clampMove = clampMoveOf(b, t, k, subDt);
            vcpmStep(cudaExec{}, v, subDt);
        }
        most = std::max(most, n);
    }
    parallelFor(cudaExec{}, nAll, meanVelocityOp{d.position.data(),
        d.halfStart.data(), dt, d.meanVelocity.data()});
    return most;
}


bool fluidSolidCoupling::nonFiniteOnDevice() const
{
    const label n = size();
    return parallelReduce(cudaExec{}, n,
        firstNonFiniteOp{device_->position.data(), n}, n, minOp()) < n;
}


bool fluidSolidCoupling::collapsedOnDevice(const scalar fraction) const
{
    for (std::size_t b = 0; b < solids_.bodies().size(); ++b)
    {
        const bondView bonds = device_->bonds[b].view();
        if (parallelReduce(cudaExec{}, bonds.nBonds, collapsedBondOp{bonds,
                device_->position.data() + offsets_[b], fraction},
                bonds.nBonds, minOp()) < bonds.nBonds)
        {
            return true;
        }
    }
    return false;
}


void fluidSolidCoupling::toHost()
{
    if (!device_) return;
    deviceSolids& d = *device_;
    const label n = size();
    std::vector<vec3> velocity(n);
    d.position.copyToHost(position.data(), n);
    d.velocity.copyToHost(velocity.data(), n);
    d.meanVelocity.copyToHost(meanVelocity.data(), n);
    d.fluidForce.copyToHost(fluidForce.data(), n);
    d.fluidForceAtStart.copyToHost(fluidForceAtStart.data(), n);
    startPosition_.resize(n);
    startVelocity_.resize(n);
    startMeanVelocity_.resize(n);
    d.startPosition.copyToHost(startPosition_.data(), n);
    d.startVelocity.copyToHost(startVelocity_.data(), n);
    d.startMeanVelocity.copyToHost(startMeanVelocity_.data(), n);
    for (std::size_t b = 0; b < solids_.bodies().size(); ++b)
    {
        vcpmSolid& s = *solids_.bodies()[b].solid;
        std::copy(position.begin() + offsets_[b],
                  position.begin() + offsets_[b + 1], s.position.begin());
        std::copy(velocity.begin() + offsets_[b],
                  velocity.begin() + offsets_[b + 1], s.velocity.begin());
    }
}

} // End namespace sphvcpm
