/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "particleFields.H"
#include "parallel.H"

namespace sphvcpm
{

void particleFields::resize(const label n, const bool withSps,
                            const bool withShifting, const bool withPrevious)
{
    velocityPrevious.resize(withPrevious ? n : 0);
    rhoPrevious.resize(withPrevious ? n : 0);
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


void particleFields::reorder(const std::vector<label>& order, const label n,
                             const bool withSps, const bool withShifting)
{
    // The fields recomputed every step are the targets of the gather, so
    // one pass over the particles (one parallel region) moves every field
    // that lives across steps, without adding memory. The pressure of the
    // fluid moves too: the wall extrapolation and the rates at the start
    // of a step use it before it is recomputed.
    velocity0.resize(n);
    acceleration.resize(n);
    rho0.resize(n);
    drho.resize(n);
    invRho.resize(n);
    std::vector<std::uint8_t> newKind(n), newBody(n);
    std::vector<label> newId(n);
    std::vector<label> newLink(link.empty() ? 0 : n);
    std::vector<point>& newPosition =
        positionScratchOf(positionScratch, velocity0);
    newPosition.resize(n);
    parallelFor(openmpExec{}, n, reorderOp{order.data(),
        position.data(), newPosition.data(),
        velocity.data(), acceleration.data(),
        rho.data(), rho0.data(),
        p.data(), drho.data(),
        mass.data(), invRho.data(),
        kind.data(), newKind.data(),
        body.data(), newBody.data(),
        id.data(), newId.data(),
        link.empty() ? nullptr : link.data(), newLink.data()});
    position.swap(newPosition);
    velocity.swap(acceleration);
    rho.swap(rho0);
    p.swap(drho);
    mass.swap(invRho);
    kind.swap(newKind);
    body.swap(newBody);
    id.swap(newId);
    link.swap(newLink);
    position.resize(n);
    velocity.resize(n);
    rho.resize(n);
    p.resize(n);
    mass.resize(n);
    if (!velocityPrevious.empty())
    {
        // A second gather, into two of the step fields that the first one
        // has just freed.
        acceleration.resize(n);
        drho.resize(n);
        parallelFor(openmpExec{}, n, reorderPreviousOp{order.data(),
            velocityPrevious.data(), acceleration.data(),
            rhoPrevious.data(), drho.data()});
        velocityPrevious.swap(acceleration);
        rhoPrevious.swap(drho);
        velocityPrevious.resize(n);
        rhoPrevious.resize(n);
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
        divR.empty() ? nullptr : divR.data(),
        link.empty() ? nullptr : link.data(),
        velocityPrevious.empty() ? nullptr : velocityPrevious.data(),
        rhoPrevious.empty() ? nullptr : rhoPrevious.data()
    };
}


std::size_t particleFields::bytesPerParticle() const
{
    std::size_t b = sizeof(point) + 3*sizeof(vec3) + 6*sizeof(scalar) + 2
                  + sizeof(label);
    if (sizeof(point) != sizeof(vec3)) b += sizeof(point);  // its scratch
    b += sizeof(std::uint32_t) + sizeof(label);   // sort key and order
    b += sizeof(scalar);                          // viscous step term
    if (!tau.empty()) b += sizeof(symmTensor);
    if (!shiftGradient.empty()) b += sizeof(vec3) + sizeof(scalar);
    if (!link.empty()) b += sizeof(label);
    if (!velocityPrevious.empty()) b += sizeof(vec3) + sizeof(scalar);
    return b;
}

} // End namespace sphvcpm
