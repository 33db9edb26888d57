/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Selection of a shape by name and the reading helpers the shapes share.

#include "shape.H"
#include "boxShape.H"
#include "containerShape.H"
#include "cylinderShape.H"
#include "error.H"
#include "sphereShape.H"
#include "polygonShape.H"
#include "seedFillShape.H"
#include "stlShape.H"
#include "surfaceLayersShape.H"

#include <sstream>

namespace sphvcpm
{

shape::shape(std::string name, int nDimensions)
:
    name_(std::move(name)),
    nDimensions_(nDimensions)
{
    if (nDimensions_ != 2 && nDimensions_ != 3)
    {
        fatalError("Shape '" + name_ + "': nDimensions must be 2 or 3, found "
            + std::to_string(nDimensions_));
    }
}


const std::vector<std::string>& shape::types()
{
    static const std::vector<std::string> names =
        {"box", "container", "cylinder", "polygon", "seedFill", "sphere",
         "stl", "surfaceLayers"};
    return names;
}


std::unique_ptr<shape> shape::New
(
    const std::string& name,
    const dictionary& dict,
    int nDimensions,
    scalar dp,
    const std::vector<std::string>& extraKeywords,
    const std::filesystem::path& caseDir,
    const vec3& latticeOrigin
)
{
    const std::string type = dict.getWord("shape", types());

    // Keywords first, so a misspelt one is named rather than reported as
    // a missing one.
    const auto check = [&](const std::vector<std::string>& own)
    {
        std::vector<std::string> valid{"shape"};
        valid.insert(valid.end(), own.begin(), own.end());
        valid.insert(valid.end(), extraKeywords.begin(), extraKeywords.end());
        dict.checkKeywords(valid);
    };

    if (type == "box")
    {
        check(boxShape::keywords());
        return std::make_unique<boxShape>(name, dict, nDimensions);
    }
    if (type == "sphere")
    {
        check(sphereShape::keywords());
        return std::make_unique<sphereShape>(name, dict, nDimensions);
    }
    if (type == "cylinder")
    {
        check(cylinderShape::keywords());
        return std::make_unique<cylinderShape>(name, dict, nDimensions);
    }
    if (type == "polygon")
    {
        check(polygonShape::keywords());
        return std::make_unique<polygonShape>(name, dict, nDimensions);
    }
    if (type == "stl" && nDimensions == 2)
    {
        check(stlShape::keywords());
        return std::make_unique<stlSliceShape>(name, dict, nDimensions,
                                               caseDir);
    }
    if (type == "stl")
    {
        check(stlShape::keywords());
        return std::make_unique<stlShape>(name, dict, nDimensions, caseDir);
    }
    if (type == "seedFill")
    {
        check(seedFillShape::keywords());
        return std::make_unique<seedFillShape>(name, dict, nDimensions, dp,
                                               latticeOrigin, caseDir);
    }
    if (type == "surfaceLayers")
    {
        check(surfaceLayersShape::keywords());
        return std::make_unique<surfaceLayersShape>(name, dict, nDimensions,
                                                    dp, caseDir);
    }
    check(containerShape::keywords());
    return std::make_unique<containerShape>(name, dict, nDimensions, dp);
}


std::string shapeDetail::str(scalar v)
{
    std::ostringstream os;
    os.precision(10);
    os << v;
    return os.str();
}


std::string shapeDetail::str(const vec3& v, int nDimensions)
{
    std::ostringstream os;
    os.precision(10);
    os << '(' << v.x << ' ' << v.y;
    if (nDimensions == 3)
    {
        os << ' ' << v.z;
    }
    os << ')';
    return os.str();
}


void shapeDetail::checkAbove
(
    const dictionary& dict,
    const std::string& minKey,
    const vec3& min,
    const std::string& maxKey,
    const vec3& max,
    int nDimensions
)
{
    static const char* axes[] = {"x", "y", "z"};
    for (int d = 0; d < nDimensions; ++d)
    {
        if (!(max[d] > min[d]))
        {
            dict.fatalAt(maxKey, "Keyword '" + maxKey + "': " + maxKey + " "
                + str(max, nDimensions) + " is not above " + minKey + " "
                + str(min, nDimensions) + " in " + axes[d] + " ("
                + (nDimensions == 2 ? "x and y count in 2D" : "x, y and z "
                   "count in 3D") + ")");
        }
    }
}

} // End namespace sphvcpm
