/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Sphere, or circle in 2D.

#include "sphereShape.H"
#include "error.H"

#include <cmath>

namespace sphvcpm
{

sphereShape::sphereShape(std::string name, const vec3& centre,
                         scalar radius, int nDimensions)
:
    shape(std::move(name), nDimensions),
    centre_(centre),
    radius_(radius)
{
    if (!(radius_ > 0))
    {
        fatalError("Sphere '" + name_ + "': radius must be positive, found "
            + shapeDetail::str(radius_));
    }
    if (nDimensions_ == 2)
    {
        centre_.z = 0;
    }
}


sphereShape::sphereShape(std::string name, const dictionary& dict,
                         int nDimensions)
:
    sphereShape
    (
        std::move(name),
        dict.get<vec3>("centre"),
        dict.getPositive("radius"),
        nDimensions
    )
{}


bool sphereShape::inside(const vec3& p, scalar tol) const
{
    vec3 d = p - centre_;
    if (nDimensions_ == 2)
    {
        d.z = 0;
    }
    const scalar r = radius_ + tol;
    return magSqr(d) <= r*r;
}


boundBox sphereShape::bounds() const
{
    const vec3 r{radius_, radius_, radius_};
    return {centre_ - r, centre_ + r};
}


scalar sphereShape::volume() const
{
    const scalar pi = M_PI;
    return nDimensions_ == 2
        ? pi*radius_*radius_
        : 4.0/3.0*pi*radius_*radius_*radius_;
}

} // End namespace sphvcpm
