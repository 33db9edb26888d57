/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "dampingZones.H"

#include "dictionary.H"
#include "dimensionSet.H"
#include "error.H"
#include "formatting.H"

#include <utility>

namespace sphvcpm
{

dampingZones readDampingZones(const std::filesystem::path& caseDir,
                              const int nDimensions,
                              std::vector<std::string>* description)
{
    dampingZones zones;
    const auto file = caseDir/"constant/dampingZones";
    if (!std::filesystem::exists(file))
    {
        return zones;
    }
    dictionary dict = dictionary::fromFile(file);
    dict.setCaseDimensions(nDimensions);
    for (const std::string& name : dict.keys())
    {
        if (!dict.isDict(name))
        {
            dict.fatalAt(name, "Keyword '" + name + "' in " + dict.name()
                + ": every entry is a damping zone, a sub-dictionary"
                  " { start (x y z); end (x y z); rate r; }");
        }
        if (zones.n == dampingZones::maxZones)
        {
            dict.fatalAt(name, "Zone '" + name + "': at most "
                + std::to_string(dampingZones::maxZones) + " damping zones"
                  " are supported");
        }
        const dictionary& sub = dict.subDict(name);
        sub.checkKeywords({"start", "end", "rate"});
        const vec3 start =
            sub.getDimensioned<vec3>("start", dimensions::length());
        const vec3 end = sub.getDimensioned<vec3>("end", dimensions::length());
        for (const auto& [key, p] : {std::pair<const char*, vec3>{"start",
            start}, {"end", end}})
        {
            if (nDimensions == 2 && p.z != 0)
            {
                sub.fatalAt(key, "Keyword '" + std::string(key) + "': a 2D"
                    " case lies in the x-y plane, so z must be 0");
            }
        }
        const scalar length = mag(end - start);
        if (!(length > 0))
        {
            sub.fatalAt("end", "Zone '" + name + "': end " + str(end)
                + " must differ from start: the zone's damping rises from"
                  " start to end");
        }
        const scalar rate =
            sub.getDimensioned<scalar>("rate", dimensionSet(0, 0, -1));
        if (!(rate > 0))
        {
            sub.fatalAt("rate", "Keyword 'rate' of zone '" + name
                + "': expected a relaxation rate > 0 [1/s], found "
                + str(rate));
        }
        dampingZone& z = zones.zone[zones.n++];
        z.start = toPoint(start);
        z.along = (1/(length*length))*(end - start);
        z.rate = rate;
        if (description)
        {
            description->push_back(name + ": from " + str(start) + " to "
                + str(end) + ", rate " + str(rate) + " 1/s");
        }
    }
    return zones;
}

} // End namespace sphvcpm
