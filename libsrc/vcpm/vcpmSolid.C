/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "vcpmSolid.H"

#include "error.H"

#include <sstream>

namespace sphvcpm
{

vcpmSolid::vcpmSolid(const vcpmMaterial& material,
                     const std::vector<vec3>& reference)
:
    position(reference),
    velocity(reference.size(), vec3{0, 0, 0}),
    force(reference.size(), vec3{0, 0, 0}),
    externalForce(reference.size(), vec3{0, 0, 0}),
    clamped(reference.size(), 0),
    clampVelocity(reference.size(), vec3{0, 0, 0}),
    stretchSum(2*reference.size(), 0),
    material_(material),
    reference_(reference),
    bonds_(reference, material.l0)
{
    const std::size_t thin = bonds_.withoutSecondLayer().size();
    if (thin)
    {
        std::ostringstream os;
        os << "VCPM solid: " << thin << " of " << reference.size()
           << " particles have no second-neighbour bond (first: "
           << bonds_.withoutSecondLayer()[0]
           << "); the solid is too thin there to carry shear";
        warning(os.str());
    }
}


scalar vcpmSolid::kineticEnergy() const
{
    scalar sum = 0;
    for (const vec3& v : velocity) sum += magSqr(v);
    return 0.5*material_.mass*sum;
}


vonMisesModel vcpmSolid::vonMisesKind() const
{
    if (material_.lattice == vcpmLattice::simpleCubic3D)
    {
        return vonMisesModel::full3D;
    }
    return material_.plane == planeModel::planeStress
         ? vonMisesModel::planeStress : vonMisesModel::planeStrain;
}


std::vector<vec3> vcpmSolid::displacement() const
{
    std::vector<vec3> u(reference_.size());
    for (std::size_t p = 0; p < u.size(); ++p)
    {
        u[p] = position[p] - reference_[p];
    }
    return u;
}


std::vector<scalar> vcpmSolid::vonMisesOf
(
    const std::vector<stressTensor>& s
) const
{
    std::vector<scalar> vm(s.size());
    for (std::size_t p = 0; p < s.size(); ++p)
    {
        vm[p] = vonMises(s[p], vonMisesKind(), material_.nu);
    }
    return vm;
}

} // End namespace sphvcpm
