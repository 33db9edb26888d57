/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "motionSet.H"

#include "dictionary.H"
#include "dictionaryParser.H"
#include "error.H"
#include "formatting.H"

#include <algorithm>

namespace sphvcpm
{

namespace fs = std::filesystem;

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

motionSet::motionSet(const dictionary& dict, const fs::path& caseDir)
{
    for (const std::string& name : dict.keys())
    {
        if (!dict.isDict(name))
        {
            dict.fatalAt(name, "Keyword '" + name + "' in " + dict.name()
                + ": every entry is a motion, a sub-dictionary"
                  " { bodies (...); origin ...; axis ...; angle {...} }");
        }
        const dictionary& sub = dict.subDict(name);

        // bodies first: a motion that moves no body is a mistake whatever
        // its other keywords say.
        const std::vector<std::string> bodies =
            sub.get<std::vector<std::string>>("bodies");
        const entry& bodiesEntry = sub.lookupEntry("bodies");
        if (bodies.empty())
        {
            sub.fatalAt("bodies", "Keyword 'bodies' in dictionary \""
                + sub.name() + "\": names no body");
        }
        for (std::size_t i = 0; i < bodies.size(); ++i)
        {
            const std::string& body = bodies[i];
            if (std::find(bodies.begin(), bodies.begin() + i, body)
             != bodies.begin() + i)
            {
                sub.fatalAt("bodies", "Keyword 'bodies' in dictionary \""
                    + sub.name() + "\": body " + body + " is named twice");
            }
            for (const namedMotion& m : motions_)
            {
                if (std::find(m.bodies.begin(), m.bodies.end(), body)
                 != m.bodies.end())
                {
                    sub.fatalAt("bodies", "Keyword 'bodies' in dictionary \""
                        + sub.name() + "\": body " + body + " is already"
                          " moved by motion " + m.name + " (" + m.file
                        + " line " + std::to_string(m.line) + "); a body"
                          " follows one motion");
                }
            }
        }

        motions_.push_back
        (
            namedMotion
            {
                name,
                bodies,
                rigidMotion(sub, caseDir, {"bodies"}),
                bodiesEntry.file(),
                bodiesEntry.line()
            }
        );
    }
}


motionSet motionSet::read(const fs::path& caseDir, const int nDimensions)
{
    const fs::path file = caseDir/"constant"/"motion";
    if (!fs::is_regular_file(file))
    {
        fatalError("Prescribed motions: " + file.string() + " does not"
            " exist");
    }
    dictionary dict = dictionary::fromFile(file);
    dict.setCaseDimensions(nDimensions);
    if (dict.keys().empty())
    {
        // Present but empty (a truncated or half-written file): a case
        // whose bodies stand still has no constant/motion at all.
        fatalIOError(file.string(), 0, "Prescribed motions: " + file.string()
            + " defines no motion; remove the file if no body moves");
    }
    return motionSet(dict, caseDir);
}


motionSet motionSet::readIfPresent(const fs::path& caseDir,
                                   const int nDimensions)
{
    if (!fs::exists(caseDir/"constant"/"motion"))
    {
        return motionSet();
    }
    return read(caseDir, nDimensions);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const rigidMotion* motionSet::motionOf(const std::string& bodyName) const
{
    const namedMotion* m = namedMotionOf(bodyName);
    return m ? &m->motion : nullptr;
}


const namedMotion* motionSet::namedMotionOf(const std::string& bodyName)
    const
{
    for (const namedMotion& m : motions_)
    {
        if (std::find(m.bodies.begin(), m.bodies.end(), bodyName)
         != m.bodies.end())
        {
            return &m;
        }
    }
    return nullptr;
}


std::vector<std::string> motionSet::bodies() const
{
    std::vector<std::string> all;
    for (const namedMotion& m : motions_)
    {
        all.insert(all.end(), m.bodies.begin(), m.bodies.end());
    }
    return all;
}


void motionSet::checkBodies
(
    const std::vector<std::string>& allowed,
    const std::vector<std::string>& all,
    const std::string& what
) const
{
    for (const namedMotion& m : motions_)
    {
        for (const std::string& body : m.bodies)
        {
            if (std::find(all.begin(), all.end(), body) == all.end())
            {
                const std::string near =
                    dictionaryDetail::closest(body, all);
                fatalIOError(m.file, m.line, "Keyword 'bodies' of motion "
                    + m.name + ": the case has no body " + body
                    + (near.empty() ? "" : " (did you mean " + near + "?)")
                    + "; its bodies are " + str(all), "bodies");
            }
            if (std::find(allowed.begin(), allowed.end(), body)
             == allowed.end())
            {
                fatalIOError(m.file, m.line, "Keyword 'bodies' of motion "
                    + m.name + ": " + body + " is not " + what
                    + "; the bodies that can move are "
                    + str(allowed), "bodies");
            }
        }
    }
}

} // End namespace sphvcpm
