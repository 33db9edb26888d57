/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Field registry, resizing and permutation of a particle body.

#include "particleBody.H"
#include "error.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace sphvcpm
{

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

namespace
{

const char* kindName(fieldKind kind)
{
    switch (kind)
    {
        case fieldKind::scalarField: return "scalarField";
        case fieldKind::vectorField: return "vectorField";
        case fieldKind::labelField: return "labelField";
    }
    return "unknown";
}


// new[i] = old[order[i]] for one field.
template<class T>
void permute(std::vector<T>& field, const std::vector<label>& order)
{
    std::vector<T> result(field.size());
    const label n = label(order.size());
    #pragma omp parallel for if (n > 100000)
    for (label i = 0; i < n; ++i)
    {
        result[i] = field[order[i]];
    }
    field.swap(result);
}


// Stable compaction of one field: keeps the entries whose flag is zero.
template<class T>
void compact(std::vector<T>& field, const std::vector<char>& flags)
{
    std::size_t kept = 0;
    for (std::size_t i = 0; i < field.size(); ++i)
    {
        if (!flags[i])
        {
            field[kept++] = field[i];
        }
    }
    field.resize(kept);
}

} // End anonymous namespace


std::vector<vec3> toVectors(const std::vector<point>& x)
{
    std::vector<vec3> out(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) out[i] = toVec3(x[i]);
    return out;
}


std::string bodyTypeName(bodyType type)
{
    switch (type)
    {
        case bodyType::fluid: return "fluid";
        case bodyType::wall: return "wall";
        case bodyType::solid: return "solid";
    }
    return "unknown";
}


bodyType bodyTypeFromName(const std::string& name)
{
    for (bodyType t : {bodyType::fluid, bodyType::wall, bodyType::solid})
    {
        if (name == bodyTypeName(t))
        {
            return t;
        }
    }
    fatalError("Unknown body type '" + name
        + "'\nValid body types are: fluid wall solid");
}


// * * * * * * * * * * * * * * * Constructor * * * * * * * * * * * * * * * //

particleBody::particleBody(std::string name, bodyType type, int nDimensions,
                           scalar dp)
:
    name_(std::move(name)),
    type_(type),
    nDimensions_(nDimensions),
    dp_(dp)
{
    // The name becomes a directory of every time directory.
    if
    (
        name_.empty() || name_[0] == '.' || name_ == "uniform"
     || name_.find_first_of("/\\ \t\n\"'") != std::string::npos
    )
    {
        fatalError("Invalid body name '" + name_ + "': a body name is a "
            "directory name, not empty, not hidden, not 'uniform' and "
            "without slashes, blanks or quotes");
    }
    if (nDimensions_ != 2 && nDimensions_ != 3)
    {
        fatalError("Body '" + name_ + "': nDimensions is "
            + std::to_string(nDimensions_) + ", expected 2 or 3");
    }
    if (!(std::isfinite(dp_) && dp_ > 0))
    {
        std::ostringstream os;
        os << dp_;
        fatalError("Body '" + name_ + "': particle spacing dp is " + os.str()
            + ", expected a positive number");
    }
    labelFields_["id"];
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void particleBody::resize(label n)
{
    if (n < 0)
    {
        fatalError("Body '" + name_ + "': cannot resize to "
            + std::to_string(n) + " particles");
    }
    const label old = size_;
    if (n > old && label(n - old) > std::numeric_limits<label>::max() - nextId_)
    {
        fatalError("Body '" + name_ + "': ids of " + std::to_string(n - old)
            + " new particles would overflow a label (next id "
            + std::to_string(nextId_) + ")");
    }
    for (auto& f : scalarFields_)
    {
        f.second.resize(n, scalar(0));
    }
    position_.resize(n, point{0, 0, 0});
    for (auto& f : vectorFields_)
    {
        f.second.resize(n, vec3{0, 0, 0});
    }
    for (auto& f : labelFields_)
    {
        f.second.resize(n, label(0));
    }
    std::vector<label>& ids = labelFields_["id"];
    for (label i = old; i < n; ++i)
    {
        ids[i] = nextId_++;
    }
    size_ = n;
}


label particleBody::append(const point& p)
{
    const label i = size_;
    resize(size_ + 1);
    position_[i] = p;
    return i;
}


std::vector<scalar>& particleBody::addScalarField(const std::string& name,
                                                  scalar init)
{
    if (hasField(name))
    {
        return scalarField(name);
    }
    checkFieldName(name);
    return scalarFields_[name] = std::vector<scalar>(size_, init);
}


std::vector<vec3>& particleBody::addVectorField(const std::string& name,
                                                const vec3& init)
{
    if (hasField(name))
    {
        return vectorField(name);
    }
    checkFieldName(name);
    return vectorFields_[name] = std::vector<vec3>(size_, init);
}


std::vector<label>& particleBody::addLabelField(const std::string& name,
                                                label init)
{
    if (hasField(name))
    {
        return labelField(name);
    }
    checkFieldName(name);
    return labelFields_[name] = std::vector<label>(size_, init);
}


bool particleBody::hasField(const std::string& name) const
{
    return scalarFields_.count(name) || vectorFields_.count(name)
        || labelFields_.count(name) || isPointField(name);
}


fieldKind particleBody::kindOf(const std::string& name) const
{
    if (scalarFields_.count(name))
    {
        return fieldKind::scalarField;
    }
    if (vectorFields_.count(name) || isPointField(name))
    {
        return fieldKind::vectorField;
    }
    if (labelFields_.count(name))
    {
        return fieldKind::labelField;
    }
    missingField(name, "field");
}


std::vector<std::string> particleBody::fieldNames() const
{
    std::vector<std::string> names;
    for (const auto& f : scalarFields_)
    {
        names.push_back(f.first);
    }
    for (const auto& f : vectorFields_)
    {
        names.push_back(f.first);
    }
    names.push_back("position");
    for (const auto& f : labelFields_)
    {
        names.push_back(f.first);
    }
    std::sort(names.begin(), names.end());
    return names;
}


void particleBody::checkFieldName(const std::string& name) const
{
    // Every field is a file next to bodyProperties when written.
    if
    (
        name.empty() || name[0] == '.' || name == "bodyProperties"
     || name.find_first_of("/\\ \t\n\"'") != std::string::npos
    )
    {
        fatalError("Body '" + name_ + "': invalid field name '" + name
            + "': a field name is a file name, not empty, not hidden, not "
            "'bodyProperties' and without slashes, blanks or quotes");
    }
}


void particleBody::missingField(const std::string& name,
                                const char* expected) const
{
    std::string message = "Body '" + name_ + "' has no " + expected + " '"
        + name + "'";
    if (isPointField(name))
    {
        message += ": it is a vectorField of points, position()";
    }
    else if (hasField(name))
    {
        message += ": it is a " + std::string(kindName(kindOf(name)));
    }
    message += "\nFields of body '" + name_ + "':";
    for (const auto& n : fieldNames())
    {
        message += " " + n;
    }
    fatalError(message);
}


std::vector<scalar>& particleBody::scalarField(const std::string& name)
{
    const auto iter = scalarFields_.find(name);
    if (iter == scalarFields_.end())
    {
        missingField(name, "scalarField");
    }
    return iter->second;
}


const std::vector<scalar>& particleBody::scalarField(
    const std::string& name) const
{
    const auto iter = scalarFields_.find(name);
    if (iter == scalarFields_.end())
    {
        missingField(name, "scalarField");
    }
    return iter->second;
}


std::vector<vec3>& particleBody::vectorField(const std::string& name)
{
    const auto iter = vectorFields_.find(name);
    if (iter == vectorFields_.end())
    {
        missingField(name, "vectorField");
    }
    return iter->second;
}


const std::vector<vec3>& particleBody::vectorField(
    const std::string& name) const
{
    const auto iter = vectorFields_.find(name);
    if (iter == vectorFields_.end())
    {
        missingField(name, "vectorField");
    }
    return iter->second;
}


std::vector<label>& particleBody::labelField(const std::string& name)
{
    const auto iter = labelFields_.find(name);
    if (iter == labelFields_.end())
    {
        missingField(name, "labelField");
    }
    return iter->second;
}


const std::vector<label>& particleBody::labelField(
    const std::string& name) const
{
    const auto iter = labelFields_.find(name);
    if (iter == labelFields_.end())
    {
        missingField(name, "labelField");
    }
    return iter->second;
}


bool particleBody::removeField(const std::string& name)
{
    if (name == "position" || name == "id")
    {
        fatalError("Body '" + name_ + "': field '" + name
            + "' cannot be removed");
    }
    return scalarFields_.erase(name) + vectorFields_.erase(name)
         + labelFields_.erase(name) > 0;
}


void particleBody::reorder(const std::vector<label>& order)
{
    if (label(order.size()) != size_)
    {
        fatalError("Body '" + name_ + "': reorder with "
            + std::to_string(order.size()) + " indices for "
            + std::to_string(size_) + " particles");
    }
    // A repeated index would duplicate one particle and lose another.
    std::vector<char> seen(size_, 0);
    for (label i = 0; i < size_; ++i)
    {
        const label j = order[i];
        if (j < 0 || j >= size_ || seen[j])
        {
            fatalError("Body '" + name_ + "': reorder index "
                + std::to_string(j) + " at " + std::to_string(i) + " is "
                + (j < 0 || j >= size_ ? "out of range" : "repeated")
                + ": the order must be a permutation of 0.."
                + std::to_string(size_ - 1));
        }
        seen[j] = 1;
    }
    permute(position_, order);
    for (auto& f : scalarFields_)
    {
        permute(f.second, order);
    }
    for (auto& f : vectorFields_)
    {
        permute(f.second, order);
    }
    for (auto& f : labelFields_)
    {
        permute(f.second, order);
    }
}


label particleBody::remove(const std::vector<char>& flags)
{
    if (label(flags.size()) != size_)
    {
        fatalError("Body '" + name_ + "': remove with "
            + std::to_string(flags.size()) + " flags for "
            + std::to_string(size_) + " particles");
    }
    const label removed = label(std::count_if(flags.begin(), flags.end(),
        [](char f) { return f != 0; }));
    if (removed == 0)
    {
        return 0;
    }
    compact(position_, flags);
    for (auto& f : scalarFields_)
    {
        compact(f.second, flags);
    }
    for (auto& f : vectorFields_)
    {
        compact(f.second, flags);
    }
    for (auto& f : labelFields_)
    {
        compact(f.second, flags);
    }
    // Ids of removed particles are not given out again.
    size_ -= removed;
    return removed;
}

} // End namespace sphvcpm
