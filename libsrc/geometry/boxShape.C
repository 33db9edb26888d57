/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Axis-aligned box.

#include "boxShape.H"
#include "error.H"

namespace sphvcpm
{

boxShape::boxShape(std::string name, const vec3& min, const vec3& max,
                   int nDimensions)
:
    shape(std::move(name), nDimensions),
    box_{min, max}
{
    for (int d = 0; d < nDimensions_; ++d)
    {
        if (!(max[d] > min[d]))
        {
            fatalError("Box '" + name_ + "': max "
                + shapeDetail::str(max, nDimensions_) + " is not above min "
                + shapeDetail::str(min, nDimensions_));
        }
    }
}


boxShape::boxShape(std::string name, const dictionary& dict,
                   int nDimensions)
:
    shape(std::move(name), nDimensions),
    box_{dict.get<vec3>("min"), dict.get<vec3>("max")}
{
    shapeDetail::checkAbove(dict, "min", box_.min, "max", box_.max,
                            nDimensions_);
}


bool boxShape::inside(const vec3& p, scalar tol) const
{
    return box_.contains(p, nDimensions_, tol);
}

} // End namespace sphvcpm
