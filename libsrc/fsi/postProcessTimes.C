/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "postProcessTimes.H"
#include "dictionary.H"
#include "error.H"
#include "fsiSolver.H"
#include "functionObject.H"
#include "solidOnlySolver.H"

#include <memory>
#include <ostream>
#include <streambuf>

namespace sphvcpm
{

namespace fs = std::filesystem;

namespace
{

// Drops what it is given: the solvers' set-up logs, one per time read.
struct discardBuffer : std::streambuf
{
    int overflow(const int c) override { return traits_type::not_eof(c); }
};

} // End anonymous namespace


void postProcessTimes(const fs::path& caseDir,
                      const std::vector<timeInstant>& times,
                      const postProcessSettings& settings, std::ostream& log)
{
    // As OpenFOAM's -dict, a relative path is the case's.
    const fs::path dictFile = settings.dictFile.empty()
        ? caseDir/"system/controlDict"
        : settings.dictFile.is_absolute() ? settings.dictFile
        : caseDir/settings.dictFile;
    if (!fs::is_regular_file(dictFile))
    {
        fatalError("-dict " + settings.dictFile.string() + ": there is no"
            " file " + dictFile.string() + " (a relative path is taken from"
            " the case directory)");
    }
    dictionary functionsDict = dictionary::fromFile(dictFile);
    if (!functionsDict.findEntry("functions"))
    {
        fatalError(dictFile.string() + " has no functions {} to evaluate"
            + (settings.dictFile.empty() ? std::string(": add the function"
               " objects there, or give a file holding them with -dict")
               : std::string()));
    }

    // Before any time is read: the entries, where they write, and the
    // times (a solver write has uniform/time; one without it past the
    // case's first time would be read as an initial state).
    const std::vector<std::string> names =
        functionObject::selectEntries(functionsDict, settings.functions);
    if (names.empty())
    {
        fatalError("functions {} of " + dictFile.string() + " has no"
            " enabled entry to evaluate (-func NAME evaluates one with"
            " enabled false)");
    }
    for (const std::string& name : names)
    {
        const fs::path dir = caseDir/"postProcessing"/name/times.front().name;
        std::error_code ec;
        if (!settings.overwrite && fs::is_directory(dir)
         && !fs::is_empty(dir, ec))
        {
            fatalError("Function object '" + name + "': " + dir.string()
                + " already holds tables (a run's own, maybe, sampled at"
                " every step): give -overwrite to write over them, or"
                " remove them");
        }
    }
    const std::string firstName = findTimes(caseDir).front().name;
    for (const timeInstant& t : times)
    {
        if (t.name != firstName
         && !fs::is_regular_file(caseDir/t.name/"uniform"/"time"))
        {
            fatalError("Time " + t.name + " of " + caseDir.string() + " has"
                " no uniform/time: it cannot be told from an initial state,"
                " and would be read as one. Leave it out (-time)");
        }
    }

    // Each time repeats the case's warnings: give each once.
    warnOnlyOnce(true);
    discardBuffer discard;
    std::ostream quiet(&discard);

    std::vector<std::unique_ptr<functionObject>> functions;
    const auto sampleAll = [&](const solverSnapshot& s, const bool hasFluid)
    {
        if (functions.empty())
        {
            functionsDict.setCaseDimensions(s.model.nDimensions);
            functions = functionObject::readAll(functionsDict, caseDir,
                times.front().name, s.model, s.bodies, hasFluid, names);
        }
        for (const auto& f : functions)
        {
            f->sample(s);
        }
    };

    for (const timeInstant& t : times)
    {
        log << "Time = " << t.name << std::endl;
        if (solidOnlySolver::applies(caseDir, t.name))
        {
            const solidOnlySolver solver(caseDir, t.name, quiet, true);
            sampleAll(solver.snapshot(), false);
        }
        else
        {
            const fsiSolver solver(caseDir, quiet, "cpu", t.name);
            // Particles beyond the domain's bounds are removed as the
            // solver reads them; the run sampled them once more, before its
            // next step removed them.
            for (const bodyInfo& b : solver.bodies())
            {
                if (b.nRemoved > 0)
                {
                    log << "    " << b.name << ": " << b.nRemoved
                        << " particles beyond the domain left out\n";
                }
            }
            sampleAll(solver.snapshot(), true);
        }
    }
    warnOnlyOnce(false);

    log << "\n";
    for (const auto& f : functions)
    {
        log << "Function object " << f->name() << ": "
            << f->directory().generic_string() << "\n";
    }
    log << std::endl;
}

} // End namespace sphvcpm
