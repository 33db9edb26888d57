/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "particleFields.H"
#include "parallel.H"

namespace sphvcpm
{

void particleFields::resize(const label n, const bool withSps,
                            const bool withShifting)
{
    position.resize(n);
    velocity.resize(n);
    rho.resize(n);
    p.resize(n);
    mass.resize(n);
    kind.resize(n);
    body.resize(n);
    id.resize(n);
    resizeStepFields(n, withSps, withShifting);
}


void particleFields::resizeStepFields(const label n, const bool withSps,
                                      const bool withShifting)
{
    velocity0.resize(n);
    acceleration.resize(n);
    rho0.resize(n);
    drho.resize(n);
    invRho.resize(n);
    tau.resize(withSps ? n : 0);
    shiftGradient.resize(withShifting ? n : 0);
    divR.resize(withShifting ? n : 0);
}


namespace
{

template<class T>
void gather(std::vector<T>& field, const std::vector<label>& order,
            const label n, std::vector<T>& scratch)
{
    scratch.resize(n);
    const T* src = field.data();
    T* dst = scratch.data();
    const label* o = order.data();
    parallelFor(openmpExec{}, n, [=](label k) { dst[k] = src[o[k]]; });
    field.swap(scratch);
    field.resize(n);
}

} // End anonymous namespace


void particleFields::reorder(const std::vector<label>& order, const label n,
                             const bool withSps, const bool withShifting)
{
    {
        std::vector<vec3> scratch;
        gather(position, order, n, scratch);
        gather(velocity, order, n, scratch);
    }
    {
        std::vector<scalar> scratch;
        gather(rho, order, n, scratch);
        // The pressure of the fluid is used before it is next recomputed
        // (wall extrapolation and rates at the start of a step).
        gather(p, order, n, scratch);
        gather(mass, order, n, scratch);
    }
    {
        std::vector<std::uint8_t> scratch;
        gather(kind, order, n, scratch);
        gather(body, order, n, scratch);
    }
    {
        std::vector<label> scratch;
        gather(id, order, n, scratch);
    }
    // Recomputed every step: only the size changes.
    resizeStepFields(n, withSps, withShifting);
}


particleView particleFields::view()
{
    return particleView
    {
        size(),
        position.data(), velocity.data(), rho.data(), p.data(), mass.data(),
        kind.data(), body.data(), id.data(), velocity0.data(), rho0.data(),
        acceleration.data(), drho.data(), invRho.data(),
        tau.empty() ? nullptr : tau.data(),
        shiftGradient.empty() ? nullptr : shiftGradient.data(),
        divR.empty() ? nullptr : divR.data()
    };
}


std::size_t particleFields::bytesPerParticle() const
{
    std::size_t b = 4*sizeof(vec3) + 6*sizeof(scalar) + 2 + sizeof(label);
    b += sizeof(std::uint32_t) + sizeof(label);   // sort key and order
    b += sizeof(scalar);                          // viscous step term
    if (!tau.empty()) b += sizeof(symmTensor);
    if (!shiftGradient.empty()) b += sizeof(vec3) + sizeof(scalar);
    return b;
}

} // End namespace sphvcpm
