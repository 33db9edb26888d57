/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "functionObject.H"
#include "functionObjects.H"
#include "dictionaryParser.H"
#include "error.H"
#include "formatting.H"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sphvcpm
{

namespace
{

const std::vector<std::string> writeControls
{
    "timeStep", "runTime", "adjustableRunTime"
};

const std::vector<std::string> types
{
    "probes", "freeSurfaceGauges", "forces", "energy", "surgeFront",
    "solidPoints"
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructor  * * * * * * * * * * * * * * //

functionObject::functionObject(std::string name, const dictionary& dict,
    const std::filesystem::path& caseDir, const std::string& startTimeName)
:
    name_(std::move(name)),
    dict_(dict),
    directory_(caseDir/"postProcessing"/name_/startTimeName),
    writeControl_
    (
        dict.getWordOrDefault("writeControl", writeControls, "timeStep")
    ),
    writeInterval_(1)
{
    if (dict.found("writeInterval"))
    {
        writeInterval_ = dict.getPositive("writeInterval");
    }
    // NaN: nothing sampled yet (any finite value could be a real time).
    nextSampleTime_ = std::numeric_limits<scalar>::quiet_NaN();
}


// * * * * * * * * * * * * * * * Member functions * * * * * * * * * * * * * //

void functionObject::checkWriteInterval() const
{
    if
    (
        writeControl_ == "timeStep"
     && (writeInterval_ != std::floor(writeInterval_)
      || writeInterval_ > std::numeric_limits<label>::max())
    )
    {
        dict_.fatalAt("writeInterval", "Function object '" + name_
            + "': writeInterval of writeControl timeStep"
            + (dict_.found("writeControl") ? "" : " (the default)")
            + " is a number of time steps (a whole number >= 1), found "
            + str(double(writeInterval_)));
    }
}


bool functionObject::due(const double time, const label timeIndex) const
{
    if (std::isnan(nextSampleTime_))
    {
        return true;
    }
    return writeControl_ == "timeStep"
        ? timeIndex % label(writeInterval_) == 0
        : time >= nextSampleTime_
                  - functionObjects::timeTolerance*writeInterval_;
}


void functionObject::execute(const solverSnapshot& s)
{
    if (!due(s.time, s.timeIndex))
    {
        return;
    }
    const bool timeStep = writeControl_ == "timeStep";

    sample(s);

    if (timeStep)
    {
        nextSampleTime_ = s.time;   // only marks "sampled"
    }
    else
    {
        // The next multiple of the interval strictly after this sample
        // (the tolerance keeps a time a rounding error short of a multiple
        // from being sampled again at that multiple).
        nextSampleTime_ =
            (
                std::floor
                (
                    s.time/writeInterval_ + functionObjects::timeTolerance
                )
              + 1
            )*writeInterval_;
    }
}


std::ofstream& functionObject::output(const std::string& file)
{
    for (auto& f : files_)
    {
        if (f.first == file)
        {
            return *f.second;
        }
    }

    // Opened on the first sample, so a run that stops during set-up leaves
    // no empty tables. A restart at the same start time rewrites the same
    // times, hence truncation.
    std::error_code ec;
    std::filesystem::create_directories(directory_, ec);
    if (ec)
    {
        fatalError("Function object '" + name_ + "': cannot create the"
            " directory " + directory_.string() + ": " + ec.message());
    }
    const auto path = directory_/file;
    auto os = std::make_unique<std::ofstream>(path, std::ios::trunc);
    if (!*os)
    {
        fatalError("Function object '" + name_ + "': cannot open "
            + path.string() + " for writing");
    }
    os->precision(10);
    files_.emplace_back(file, std::move(os));
    return *files_.back().second;
}


// * * * * * * * * * * * * * * * * * Selector * * * * * * * * * * * * * * * //

std::vector<std::string> functionObject::selectEntries(
    const dictionary& controlDict, const std::vector<std::string>& only)
{
    const entry* functions = controlDict.findEntry("functions");
    if (!functions)
    {
        if (!only.empty())
        {
            fatalError("No functions {} in " + controlDict.name()
                + ": function object '" + only.front() + "' is not there");
        }
        return {};
    }
    if (!functions->isDict())
    {
        fatalIOError(functions->file(), functions->line(),
            "'functions' must be a dictionary of function objects:"
            " functions { <name> { type <type>; ... } }", "functions");
    }
    const dictionary& fns = functions->dict();
    for (const std::string& name : only)
    {
        if (!fns.findEntry(name))
        {
            const std::string near =
                dictionaryDetail::closest(name, fns.keys());
            fatalIOError(functions->file(), functions->line(),
                "Function object '" + name + "' is not in functions {};"
                " its entries are " + str(fns.keys())
                + (near.empty() ? "" : " (did you mean '" + near + "'?)"),
                name);
        }
    }

    // In the order of functions {}; each entry looked at is a directory
    // name under postProcessing and a sub-dictionary.
    std::vector<std::string> selected;
    for (const std::string& name : fns.keys())
    {
        const bool named =
            std::find(only.begin(), only.end(), name) != only.end();
        if (!only.empty() && !named)
        {
            continue;
        }
        const entry& e = *fns.findEntry(name);
        if (!e.isDict())
        {
            fatalIOError(e.file(), e.line(), "Function object '" + name
                + "' in " + fns.name() + " is not a sub-dictionary: expected "
                + name + " { type <type>; ... } with type one of "
                + str(types), name);
        }
        if
        (
            name.empty() || name == "." || name == ".."
         || name.find_first_of("/\\") != std::string::npos
        )
        {
            fatalIOError(e.file(), e.line(), "Function object name '" + name
                + "' cannot be a directory name under postProcessing", name);
        }
        if (named || e.dict().getOrDefault<bool>("enabled", true))
        {
            selected.push_back(name);
        }
    }
    return selected;
}


std::vector<std::unique_ptr<functionObject>> functionObject::readAll(
    const dictionary& controlDict, const std::filesystem::path& caseDir,
    const std::string& startTimeName, const sphModel& model,
    const std::vector<bodyInfo>& bodies, const bool hasFluid,
    const std::vector<std::string>& only)
{
    std::vector<std::unique_ptr<functionObject>> all;
    for (const std::string& name : selectEntries(controlDict, only))
    {
        const dictionary& dict =
            controlDict.subDict("functions").subDict(name);
        const std::string type = dict.get<std::string>("type");
        if
        (
            !hasFluid && type != "solidPoints"
         && std::find(types.begin(), types.end(), type) != types.end()
        )
        {
            dict.fatalAt("type", "Function object '" + name + "' (type "
                + type + ") samples the fluid, and this case has no fluid"
                " body (the solids run alone): remove it or set enabled"
                " false. Only solidPoints samples solids alone");
        }

        using namespace functionObjects;
        if (type == "probes")
        {
            all.push_back(std::make_unique<probes>
                (name, dict, caseDir, startTimeName, model, bodies));
        }
        else if (type == "freeSurfaceGauges")
        {
            all.push_back(std::make_unique<freeSurfaceGauges>
                (name, dict, caseDir, startTimeName, model, bodies));
        }
        else if (type == "forces")
        {
            all.push_back(std::make_unique<forces>
                (name, dict, caseDir, startTimeName, bodies,
                 model.nDimensions));
        }
        else if (type == "energy")
        {
            all.push_back(std::make_unique<energy>
                (name, dict, caseDir, startTimeName, model.nDimensions));
        }
        else if (type == "surgeFront")
        {
            all.push_back(std::make_unique<surgeFront>
                (name, dict, caseDir, startTimeName, model.nDimensions));
        }
        else if (type == "solidPoints")
        {
            all.push_back(std::make_unique<solidPoints>
                (name, dict, caseDir, startTimeName, model, bodies));
        }
        else
        {
            dict.fatalAt("type", "Function object '" + name
                + "': unknown type '" + type + "'. Valid types are: "
                + str(types));
        }
        // After the type's own keyword check: a misspelt writeControl is
        // named as such, not as a writeInterval of the default.
        all.back()->checkWriteInterval();
    }
    return all;
}

} // End namespace sphvcpm
