/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "rigidMotion.H"

#include "dictionary.H"
#include "error.H"

#include <cmath>

namespace sphvcpm
{

namespace
{

// Below this length a direction is taken to be a mistake, not a choice.
constexpr scalar smallLength = 1e-12;

// v at unit length, or "" when it gives no direction (why, otherwise).
std::string directionProblem(const vec3& v)
{
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    {
        return "a vector that is not finite gives no direction";
    }
    if (!(mag(unitVector(v)) > 0) || !(std::fmax(std::fabs(v.x),
        std::fmax(std::fabs(v.y), std::fabs(v.z))) > smallLength))
    {
        return "a zero vector gives no direction";
    }
    return "";
}

vec3 normalised(const vec3& v, const std::string& what)
{
    const std::string problem = directionProblem(v);
    if (!problem.empty())
    {
        throw FatalError("Rigid motion: " + what + ": " + problem, "", 0,
            what);
    }
    return unitVector(v);
}

// v normalised, or a FatalError at the keyword's line.
vec3 readDirection(const dictionary& dict, const std::string& key)
{
    const vec3 v = dict.get<vec3>(key);
    const std::string problem = directionProblem(v);
    if (!problem.empty())
    {
        dict.fatalAt(key, "Keyword '" + key + "' in dictionary \""
            + dict.name() + "\": " + problem);
    }
    return unitVector(v);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

rigidMotion::rigidMotion
(
    const dictionary& dict,
    const std::filesystem::path& caseDir,
    const std::vector<std::string>& extraKeywords
)
{
    std::vector<std::string> valid = keywords();
    valid.insert(valid.end(), extraKeywords.begin(), extraKeywords.end());
    dict.checkKeywords(valid);

    const bool hasAngle = dict.found("angle");
    const bool hasOffset = dict.found("offset");
    if (!hasAngle && !hasOffset)
    {
        dict.fatal("Motion \"" + dict.name() + "\" moves nothing: give"
            " angle (with origin and axis), offset (with direction), or"
            " both", "angle");
    }

    // A lone origin, axis or direction is most likely a forgotten angle
    // or offset: say so rather than ignore it.
    auto unused = [&](const std::string& key, const std::string& needs)
    {
        if (dict.found(key))
        {
            dict.fatalAt(key, "Keyword '" + key + "' in dictionary \""
                + dict.name() + "\" has no " + needs + " to go with it");
        }
    };

    if (hasAngle)
    {
        origin_ = dict.get<vec3>("origin");
        axis_ = readDirection(dict, "axis");
        angle_ = timeFunction::read(dict.subDict("angle"), caseDir, true);
    }
    else
    {
        unused("origin", "angle");
        unused("axis", "angle");
    }

    if (hasOffset)
    {
        direction_ = readDirection(dict, "direction");
        offset_ = timeFunction::read(dict.subDict("offset"), caseDir, false);
    }
    else
    {
        unused("direction", "offset");
    }
}


rigidMotion::rigidMotion
(
    const vec3& origin,
    const vec3& axis,
    const timeFunction& angle
)
{
    setRotation(origin, axis, angle);
}


rigidMotion::rigidMotion(const vec3& direction, const timeFunction& offset)
{
    setTranslation(direction, offset);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::vector<std::string> rigidMotion::keywords()
{
    return {"origin", "axis", "angle", "direction", "offset"};
}


void rigidMotion::setTranslation
(
    const vec3& direction,
    const timeFunction& offset
)
{
    direction_ = normalised(direction, "direction");
    offset_ = offset;
}


void rigidMotion::setRotation
(
    const vec3& origin,
    const vec3& axis,
    const timeFunction& angle
)
{
    origin_ = origin;
    axis_ = normalised(axis, "axis");
    angle_ = angle;
}


scalar rigidMotion::wavemakerDepth() const
{
    for (const auto* f : {&angle_, &offset_})
    {
        if (*f && (*f)->wavemakerDepth() > 0) return (*f)->wavemakerDepth();
    }
    return 0;
}


std::string rigidMotion::note() const
{
    std::string n;
    for (const auto* f : {&angle_, &offset_})
    {
        if (*f && !(*f)->note().empty())
        {
            n += (n.empty() ? "" : "; ") + (*f)->note();
        }
    }
    return n;
}


void rigidMotion::restrictToPlane()
{
    origin_.z = 0;
    axis_ = {0, 0, axis_.z < 0 ? scalar(-1) : scalar(1)};
    direction_.z = 0;
    const scalar d = mag(direction_);
    if (d > 0)
    {
        direction_ = (1/d)*direction_;
    }
}


rigidTransform rigidMotion::transform(const scalar t) const
{
    rigidTransform T;
    T.origin = toPoint(origin_);

    // Rodrigues: R = cos I + sin [k]x + (1 - cos) k k^T.
    const scalar theta = angle(t);
    const scalar c = std::cos(theta);
    const scalar s = std::sin(theta);
    const vec3& k = axis_;
    const scalar kk[3] = {k.x, k.y, k.z};
    const scalar skew[3][3] =
    {
        {0, -k.z, k.y},
        {k.z, 0, -k.x},
        {-k.y, k.x, 0}
    };
    for (int i = 0; i < 3; ++i)
    {
        for (int j = 0; j < 3; ++j)
        {
            T.rotation[i][j] =
                (i == j ? c : 0) + s*skew[i][j] + (1 - c)*kk[i]*kk[j];
        }
    }

    T.angularVelocity = (angle_ ? angle_->derivative(t) : 0)*axis_;
    T.angularAcceleration =
        (angle_ ? angle_->secondDerivative(t) : 0)*axis_;

    T.translation = toPoint(offset(t)*direction_);
    T.linearVelocity = (offset_ ? offset_->derivative(t) : 0)*direction_;
    T.linearAcceleration =
        (offset_ ? offset_->secondDerivative(t) : 0)*direction_;
    return T;
}

} // End namespace sphvcpm
