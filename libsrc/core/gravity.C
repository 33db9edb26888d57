/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "gravity.H"

#include "dictionary.H"
#include "dimensionSet.H"

namespace sphvcpm
{

vec3 readGravity(const std::filesystem::path& caseDir, const int nDimensions)
{
    const auto file = caseDir/"constant/g";
    if (!std::filesystem::exists(file))
    {
        return nDimensions == 3 ? vec3{0, 0, -9.81} : vec3{0, -9.81, 0};
    }
    dictionary dict = dictionary::fromFile(file);
    dict.setCaseDimensions(nDimensions);
    dict.checkKeywords({"dimensions", "value"});
    if (dict.found("dimensions"))
    {
        dict.checkDimensionsEntry("dimensions", dimensions::acceleration());
    }
    const vec3 g = dict.getDimensioned<vec3>("value",
                                             dimensions::acceleration());
    if (nDimensions == 2 && g.z != 0)
    {
        dict.fatalAt("value", "a 2D case lies in the x-y plane:"
            " gravity must have z = 0");
    }
    return g;
}


std::string gravityDefaultNote(const std::filesystem::path& caseDir,
                               const int nDimensions)
{
    if (std::filesystem::exists(caseDir/"constant/g")) return "";
    return nDimensions == 3
        ? " (no constant/g: the 3D default, up is +z)"
        : " (no constant/g: the 2D default, up is +y)";
}

} // End namespace sphvcpm
