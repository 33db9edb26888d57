/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "startState.H"
#include "dictionaryParser.H"
#include "dictionary.H"
#include "error.H"
#include "timeName.H"

#include <algorithm>
#include <cctype>
#include <ostream>

namespace sphvcpm
{

namespace fs = std::filesystem;

void clearInterruptedWrites(const fs::path& caseDir, std::ostream& log)
{
    std::vector<std::string> kept;
    for (const std::string& left : removeInterruptedWrites(caseDir, &kept))
    {
        log << "Removed " << left << ", left by an interrupted write\n";
    }
    for (const std::string& old : kept)
    {
        // .<time>.old.<pid>: a write stopped between its two renames.
        const std::size_t tag = old.rfind(".old.");
        const std::string time = old.substr(1, tag - 1);
        const std::string tmp = "." + time + ".tmp." + old.substr(tag + 5);
        const bool hasTmp = fs::is_directory(caseDir/tmp);
        warning("Time " + time + " is missing: a run was stopped between the"
            " two renames of its write, and its only copies are hidden in "
            + old + " (the state it replaced)"
            + (hasTmp ? " and " + tmp + " (the new write, complete)" : "")
            + ". To keep " + (hasTmp ? "the new write: mv " + tmp : "it: mv "
            + old) + " " + time, caseDir.string());
    }
}


void warnUnreadConstantFiles(const fs::path& caseDir)
{
    const std::vector<std::string> read{"fluidProperties", "solidProperties",
        "g", "motion"};
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(caseDir/"constant", ec))
    {
        if (!e.is_regular_file()) continue;
        const std::string name = e.path().filename().string();
        if (std::find(read.begin(), read.end(), name) != read.end()) continue;
        // Copies kept beside (fluidProperties.orig, motion~) are no typos,
        // nor is every short name one letter from g.
        const bool copy = std::any_of(read.begin(), read.end(),
            [&](const std::string& r)
            {
                return name.rfind(r, 0) == 0 && name.size() > r.size()
                    && !std::isalpha(static_cast<unsigned char>(
                           name[r.size()]));
            });
        if (copy) continue;
        std::string meant = name.size() > 2
          ? dictionaryDetail::closest(name, read) : std::string();
        if (name == "dynamicMeshDict" || name == "dynamicMotionSolverDict")
        {
            meant = "motion";
        }
        if (!meant.empty())
        {
            warning("constant/" + name + " is not read: did you mean"
                " constant/" + meant + "? (docs/"
                + (meant == "motion" ? "motion.md" : "solver.md") + ")",
                e.path().string());
        }
    }
}


void checkStartState(const fs::path& caseDir,
                     const std::string& startTimeName,
                     const std::vector<particleBody>& bodies,
                     const timeState& state, const bool solidsAlone,
                     std::ostream& log)
{
    const std::string dir = (caseDir/startTimeName).string();
    const bool restart = state.index != 0;
    for (const particleBody& b : bodies)
    {
        if (b.size() != 0) continue;
        if (restart && b.type() == bodyType::fluid)
        {
            log << "    " << b.name() << " (fluid): no particles left (all"
                   " have left the domain's bounds)\n";
            continue;
        }
        fatalError("Body " + b.name() + " of " + dir + " has no particles"
            " (its fields hold none): generateParticles never writes an"
            " empty body, nor the solvers an empty "
            + bodyTypeName(b.type()) + ", so the directory is damaged");
    }
    if (!restart)
    {
        double named = 0;
        if (parseTimeName(startTimeName, named) && named != 0
         && !fs::exists(caseDir/startTimeName/"uniform/time"))
        {
            warning("Time " + startTimeName + " has no uniform/time: it"
                " starts as a fresh start (hydrostatic density; a solid's"
                " reference lattice is its positions there). Every write of"
                " the solvers has it: if this is one, it was damaged", dir);
        }
        // Another initial state after this one (a case started at -1 with
        // generateParticles' 0/ still there) would be written over when
        // the run reaches its time, and a restart would take it for the
        // solids' reference lattice.
        for (const timeInstant& t : findTimes(caseDir))
        {
            if (t.value <= state.value) continue;
            if (readTimeState(caseDir, t.name).index == 0)
            {
                fatalError("Time " + t.name + " of " + caseDir.string()
                    + " is an initial state too (index 0: no solver wrote"
                    " it), after the start time " + startTimeName + ": the"
                    " run would write over it on reaching it. Move it out"
                    " of the case, or start from it");
            }
        }
        return;
    }

    // A restart continues the state the solver wrote: every body of the
    // initial time, with the fields that carry the state across steps.
    // One missing would silently start again from a default. The initial
    // time is the earliest directory (0/ of generateParticles, unless the
    // case starts elsewhere); when the restart is the earliest left, there
    // is nothing to compare with.
    std::string initial = initialTimeName(caseDir);
    if (initial.empty()) initial = startTimeName;
    std::vector<std::string> initialBodies;
    if (initial != startTimeName)
    {
        for (const std::string& name : bodyNames(caseDir, initial))
        {
            const fs::path props = caseDir/initial/name/"bodyProperties";
            if (fs::is_regular_file(props) && (!solidsAlone
             || dictionary::fromFile(props).getWord("type",
                    {"fluid", "wall", "solid"}) == "solid"))
            {
                initialBodies.push_back(name);
            }
        }
    }
    for (const std::string& name : initialBodies)
    {
        const bool found = std::any_of(bodies.begin(), bodies.end(),
            [&](const particleBody& b) { return b.name() == name; });
        if (!found)
        {
            fatalError("Body " + name + " of " + initial + "/ is missing"
                " from the restart time " + dir + ": every write of the"
                " solvers holds every body, so the directory is damaged");
        }
    }
    // ... and no other: a body the initial time lacks (a directory copied
    // in) would join the run unannounced.
    if (initial != startTimeName)
    {
        for (const particleBody& b : bodies)
        {
            if (solidsAlone && b.type() != bodyType::solid) continue;
            if (std::find(initialBodies.begin(), initialBodies.end(),
                          b.name()) == initialBodies.end())
            {
                fatalError("Body " + b.name() + " of the restart time " + dir
                    + " is not in the initial time " + initial + "/: the"
                      " solvers write the bodies they started with. Remove"
                      " " + dir + "/" + b.name() + ", or add the body to"
                      " system/generateParticlesDict and start afresh");
            }
        }
    }
    for (const particleBody& b : bodies)
    {
        if (solidsAlone && b.type() != bodyType::solid) continue;
        std::vector<std::string> needed{"U"};
        if (b.type() == bodyType::solid)
        {
            if (!solidsAlone) needed.push_back("Umean");
            if (fs::exists(caseDir/initial/b.name()/"clamped"))
            {
                needed.push_back("clamped");
            }
        }
        else
        {
            needed.insert(needed.end(), {"rho", "mass"});
        }
        for (const std::string& field : needed)
        {
            if (!b.hasField(field))
            {
                fatalError("Field " + dir + "/" + b.name() + "/" + field
                    + " is missing: a restart needs it (the solvers write"
                    " it every time), so the directory is damaged");
            }
        }
    }
}

} // End namespace sphvcpm
