/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Wall layers around a box.

#include "containerShape.H"
#include "error.H"

namespace sphvcpm
{

namespace
{

label checkedLayers(const dictionary& dict)
{
    const label n = dict.get<label>("layers");
    if (n < 1)
    {
        dict.fatalAt("layers", "Keyword 'layers': a container needs at least"
            " one layer of wall particles, found " + std::to_string(n));
    }
    return n;
}


// max of dict, after checking that it is above min.
vec3 checkedMax(const dictionary& dict, int nDimensions)
{
    const vec3 max = dict.get<vec3>("max");
    shapeDetail::checkAbove(dict, "min", dict.get<vec3>("min"), "max", max,
                            nDimensions);
    return max;
}

} // End anonymous namespace


containerShape::containerShape(std::string name, const vec3& min,
                               const vec3& max, label layers, bool openTop,
                               int nDimensions, scalar dp)
:
    shape(std::move(name), nDimensions),
    inner_{min, max},
    outer_{min, max},
    layers_(layers),
    openTop_(openTop)
{
    for (int d = 0; d < nDimensions_; ++d)
    {
        if (!(max[d] > min[d]))
        {
            fatalError("Container '" + name_ + "': max "
                + shapeDetail::str(max, nDimensions_) + " is not above min "
                + shapeDetail::str(min, nDimensions_));
        }
    }
    if (layers_ < 1)
    {
        fatalError("Container '" + name_ + "': layers must be at least 1, "
            "found " + std::to_string(layers_));
    }
    if (!(dp > 0))
    {
        fatalError("Container '" + name_ + "': dp must be positive");
    }

    const scalar thickness = layers_*dp;
    const int up = nDimensions_ - 1;
    for (int d = 0; d < 3; ++d)
    {
        outer_.min[d] -= thickness;
        if (!(openTop_ && d == up))
        {
            outer_.max[d] += thickness;
        }
    }
}


containerShape::containerShape(std::string name, const dictionary& dict,
                               int nDimensions, scalar dp)
:
    containerShape
    (
        std::move(name),
        dict.get<vec3>("min"),
        checkedMax(dict, nDimensions),
        checkedLayers(dict),
        dict.getOrDefault<bool>("openTop", false),
        nDimensions,
        dp
    )
{}


bool containerShape::inside(const vec3& p, scalar tol) const
{
    return outer_.contains(p, nDimensions_, tol)
        && !inner_.contains(p, nDimensions_, tol);
}


scalar containerShape::volume() const
{
    return outer_.volume(nDimensions_) - inner_.volume(nDimensions_);
}

} // End namespace sphvcpm
