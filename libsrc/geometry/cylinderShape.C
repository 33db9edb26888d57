/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Finite cylinder along any axis.

#include "cylinderShape.H"
#include "error.H"

#include <algorithm>
#include <cmath>

namespace sphvcpm
{

namespace
{

// point2 of dict, after checking that it differs from point1 (the axis
// would have no direction).
vec3 checkedPoint2(const std::string& name, const dictionary& dict,
                   int nDimensions)
{
    const vec3 p1 = dict.get<vec3>("point1");
    const vec3 p2 = dict.get<vec3>("point2");
    if (p1 == p2)
    {
        dict.fatalAt("point2", "Keyword 'point2': cylinder '" + name
            + "' has point1 == point2 = " + shapeDetail::str(p2, 3)
            + ", so its axis has no direction (point1 and point2 are the"
              " centres of its two end caps" + (nDimensions == 2 ? "; in 2D"
              " an axis along z gives a disc in the z = 0 plane" : "")
            + ")");
    }
    return p2;
}

} // End anonymous namespace


cylinderShape::cylinderShape(std::string name, const vec3& point1,
                             const vec3& point2, scalar radius,
                             int nDimensions)
:
    shape(std::move(name), nDimensions),
    point1_(point1),
    axis_{0, 0, 0},
    length_(mag(point2 - point1)),
    radius_(radius)
{
    if (!(length_ > 0))
    {
        fatalError("Cylinder '" + name_ + "': point1 == point2 = "
            + shapeDetail::str(point1, 3) + ", so its axis has no direction");
    }
    if (!(radius_ > 0))
    {
        fatalError("Cylinder '" + name_ + "': radius must be positive, found "
            + shapeDetail::str(radius_));
    }
    axis_ = (point2 - point1)/length_;
}


cylinderShape::cylinderShape(std::string name, const dictionary& dict,
                             int nDimensions)
:
    cylinderShape
    (
        name,
        dict.get<vec3>("point1"),
        checkedPoint2(name, dict, nDimensions),
        dict.getPositive("radius"),
        nDimensions
    )
{}


bool cylinderShape::inside(const vec3& p, scalar tol) const
{
    const vec3 d = p - point1_;
    const scalar t = dot(d, axis_);
    if (t < -tol || t >= length_ - tol)
    {
        return false;
    }
    const scalar r = radius_ + tol;
    return magSqr(d) - t*t <= r*r;
}


boundBox cylinderShape::bounds() const
{
    // The caps are discs: their extent along axis i is r sqrt(1 - a_i^2).
    const vec3 point2 = point1_ + length_*axis_;
    boundBox b;
    for (int d = 0; d < 3; ++d)
    {
        const scalar e =
            radius_*std::sqrt(std::max(scalar(0), 1 - axis_[d]*axis_[d]));
        b.min[d] = std::min(point1_[d], point2[d]) - e;
        b.max[d] = std::max(point1_[d], point2[d]) + e;
    }
    return b;
}


scalar cylinderShape::volume() const
{
    const scalar pi = M_PI;
    if (nDimensions_ == 3)
    {
        return pi*radius_*radius_*length_;
    }

    const scalar eps = 1e-12;
    if (std::abs(std::abs(axis_.z) - 1) < eps)
    {
        // Axis normal to the plane: a disc where the plane cuts the axis.
        const scalar t = -point1_.z/axis_.z;
        return t >= 0 && t < length_ ? pi*radius_*radius_ : 0;
    }
    if (std::abs(axis_.z) < eps)
    {
        // Axis in a plane parallel to z = 0: a rectangle (or nothing).
        const scalar h = std::abs(point1_.z);
        return h <= radius_
            ? 2*std::sqrt(radius_*radius_ - h*h)*length_
            : 0;
    }
    return -1;
}

} // End namespace sphvcpm
