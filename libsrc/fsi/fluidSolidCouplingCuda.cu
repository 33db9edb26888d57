/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The solids' sub-cycle on the GPU: each body's bond list, clamps and
// per-particle work arrays live in device memory; a half step uploads the
// state and the held fluid force, runs the sub-steps with the functors of
// vcpmInteractions.H (vcpmStep, as on the host) and brings the state back,
// so that the coupling's host arrays stay the reference (restart, writes,
// undo after a blow-up).
#include "fluidSolidCoupling.H"
#include "parallelCuda.cuh"

#include <vector>

namespace sphvcpm
{

namespace
{

template<class T>
deviceBuffer<T> onDevice(const std::vector<T>& host)
{
    deviceBuffer<T> d(label(host.size()));
    if (!host.empty()) d.copyFromHost(host);
    return d;
}

} // End anonymous namespace


// One body in device memory.
struct deviceSolidBody
{
    vcpmSolid& host;
    deviceBuffer<label> first, second;
    deviceBuffer<std::uint8_t> layer, clamped;
    deviceBuffer<scalar> length, weight, pairFactor, stretchSum;
    deviceBuffer<vec3> position, velocity, force, externalForce,
                       clampVelocity;
    deviceBuffer<label> start, adjacency;

    explicit deviceSolidBody(vcpmSolid& s)
    :
        host(s),
        first(onDevice(s.bonds().first())),
        second(onDevice(s.bonds().second())),
        layer(onDevice(s.bonds().layer())),
        clamped(onDevice(s.clamped)),
        length(onDevice(s.bonds().length())),
        weight(onDevice(s.bonds().weight())),
        pairFactor(onDevice(s.bonds().pairFactor())),
        stretchSum(onDevice(s.stretchSum)),
        position(s.size()),
        velocity(s.size()),
        force(s.size()),
        externalForce(s.size()),
        clampVelocity(onDevice(s.clampVelocity))
    {
        // The CSR arrays are not exposed as vectors: copy through the view.
        const bondView b = s.bonds().view();
        const label n = s.size();
        start = deviceBuffer<label>(b.start, n + 1);
        adjacency = deviceBuffer<label>(b.adjacency, b.start[n]);
    }

    vcpmSolidView view()
    {
        const vcpmSolidView h = host.view();
        const bondView b{h.bonds.nBonds, first.data(), second.data(),
            layer.data(), length.data(), weight.data(), pairFactor.data(),
            start.data(), adjacency.data()};
        return {h.n, b, h.constants, h.mass, h.gravity, h.damping,
                position.data(), velocity.data(), force.data(),
                externalForce.data(), clamped.data(), clampVelocity.data(),
                stretchSum.data()};
    }
};


struct deviceSolids
{
    std::vector<deviceSolidBody> bodies;
};


void deviceSolidsDeleter::operator()(deviceSolids* solids) const
{
    delete solids;
}


void fluidSolidCoupling::useDevice()
{
    device_.reset(new deviceSolids);
    device_->bodies.reserve(solids_.bodies().size());
    for (solidBody& b : solids_.bodies())
    {
        device_->bodies.emplace_back(*b.solid);
    }
}


void fluidSolidCoupling::advanceOnDevice(const std::size_t b,
                                         const vec3* fluidForceOfBody,
                                         const label nSub, const scalar subDt)
{
    deviceSolidBody& d = device_->bodies[b];
    vcpmSolid& s = d.host;
    const label n = s.size();
    d.position.copyFromHost(s.position.data(), n);
    d.velocity.copyFromHost(s.velocity.data(), n);
    d.externalForce.copyFromHost(fluidForceOfBody, n);

    const vcpmSolidView v = d.view();
    vcpmComputeForces(cudaExec{}, v);
    for (label k = 0; k < nSub; ++k)
    {
        vcpmStep(cudaExec{}, v, subDt);
    }
    d.position.copyToHost(s.position.data(), n);
    d.velocity.copyToHost(s.velocity.data(), n);
}

} // End namespace sphvcpm
