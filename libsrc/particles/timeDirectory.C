/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Time directories: finding them, writing one atomically and reading it
// back (the field files themselves are in fieldIO.C).
//
// A write goes to the hidden sibling <case>/.<time>.tmp.<pid>, every file
// and directory is synced, and only then is it renamed to <case>/<time>.
// An existing <time> is swapped out atomically (renameat2 RENAME_EXCHANGE,
// or two renames through .<time>.old.<pid> where the file system lacks it)
// and deleted afterwards. A crash leaves at worst a hidden directory, which
// findTimes never lists.

#include "timeDirectory.H"
#include "formatting.H"
#include "dictionary.H"
#include "error.H"
#include "particleFiles.H"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <iomanip>
#include <limits>
#include <set>
#include <signal.h>
#include <sstream>
#include <unistd.h>

namespace sphvcpm
{

namespace fs = std::filesystem;

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

namespace
{

// Files in a body directory that are not fields: hidden files and editor
// backups.
bool isFieldFileName(const std::string& name)
{
    return !name.empty() && name[0] != '.' && name.back() != '~'
        && name != "bodyProperties";
}


void checkTimeName(const std::string& name)
{
    double t = 0;
    if (!parseTimeName(name, t))
    {
        fatalError("Invalid time name '" + name
            + "': a time directory is named by its time (0, 0.05, 1e-05)");
    }
}


std::string listTimes(const std::vector<timeInstant>& times)
{
    std::string s;
    for (const auto& t : times)
    {
        s += " " + t.name;
    }
    return s.empty() ? std::string(" (none)") : s;
}


void writeBodyProperties(const fs::path& file, const particleBody& body,
                         const std::string& location)
{
    dictionary dict;
    dict.set("type", bodyTypeName(body.type()));
    dict.set<label>("nDimensions", body.nDimensions());
    dict.set<scalar>("dp", body.dp());
    if (body.type() == bodyType::solid && body.hasField("clamped"))
    {
        // Said here so that a lost clamped file is an error, not a solid
        // that runs free.
        dict.set<bool>("clamped", true);
    }
    dict.writeFile(file, location);
    particleFiles::syncPath(file);
}


void writeTimeDict(const fs::path& file, const timeState& state,
                   const std::string& location)
{
    // The entries of OpenFOAM's TimeIO.C writeTimeDict.
    dictionary dict;
    dict.set<double>("beginTime", state.beginTime);
    dict.set<double>("value", state.value);
    dict.set<std::string>("name", state.name);
    dict.set<label>("index", state.index);
    dict.set<double>("deltaT", state.deltaT);
    dict.set<double>("deltaT0", state.deltaT0);
    for (const auto& [key, value] : state.solverValues)
    {
        dict.set<double>(key, value);
    }
    dict.writeFile(file, location);
    particleFiles::syncPath(file);
}


particleBody readBodyProperties(const fs::path& dir)
{
    const fs::path file = dir/"bodyProperties";
    if (!fs::is_regular_file(file))
    {
        fatalIOError(file.string(), 0, "Missing bodyProperties in \""
            + dir.string() + "\": every body directory of a time directory "
            "has one (type, nDimensions, dp)");
    }
    const dictionary dict = dictionary::fromFile(file);
    dict.checkKeywords({"type", "nDimensions", "dp", "clamped"});
    const bodyType type =
        bodyTypeFromName(dict.getWord("type", {"fluid", "wall", "solid"}));
    const label nDim = dict.get<label>("nDimensions");
    if (nDim != 2 && nDim != 3)
    {
        dict.fatalAt("nDimensions", "Keyword 'nDimensions': expected 2 or 3, "
            "found " + std::to_string(nDim));
    }
    const scalar dp = dict.getPositive("dp");
    if (dict.getOrDefault<bool>("clamped", false)
     && !fs::is_regular_file(dir/"clamped"))
    {
        dict.fatalAt("clamped", "Body '" + dir.filename().string() + "' has"
            " clamped particles (clamped yes in its bodyProperties) but no"
            " field file \"" + (dir/"clamped").string() + "\": restore it"
            " (generateParticles writes it), or remove the line for a solid"
            " without clamps");
    }
    return particleBody(dir.filename().string(), type, int(nDim), dp);
}


// A 2D body lies in the plane z = 0 and moves in it: a z in its positions
// or velocities (an edited file) would move particles out of the plane,
// where the 2D kernels do not look. A z at rounding level (files of runs
// whose motion had an origin off the plane) is set to 0.
void checkPlanar(const fs::path& file, particleBody& body,
                 const std::string& name)
{
    if (body.nDimensions() != 2 || (name != "position" && name != "U"))
    {
        return;
    }
    auto check = [&](auto& values, const double scale)
    {
        for (std::size_t i = 0; i < values.size(); ++i)
        {
            const double z = values[i].z;
            const double inPlane = std::hypot(double(values[i].x),
                                              double(values[i].y));
            if (std::fabs(z) <= 1e-6*(scale + inPlane))
            {
                values[i].z = 0;
                continue;
            }
            fatalIOError(file.string(), 0, "Body '" + body.name()
                + "' is 2D (nDimensions 2 in its bodyProperties) but"
                  " value " + std::to_string(i) + " of field '" + name
                + "' has z = " + str(z) + ": a 2D case lies and moves in"
                  " the plane z = 0");
        }
    };
    if (name == "position")
    {
        check(body.position(), body.dp());
    }
    else if (body.kindOf(name) == fieldKind::vectorField)
    {
        check(body.vectorField(name), 1.0);
    }
}


particleBody readBody(const fs::path& dir)
{
    particleBody body = readBodyProperties(dir);

    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(dir))
    {
        const std::string name = e.path().filename().string();
        if (isFieldFileName(name))
        {
            if (!e.is_regular_file())
            {
                fatalIOError(e.path().string(), 0, "\"" + e.path().string()
                    + "\" in body directory \"" + dir.string()
                    + "\" is not a field file");
            }
            files.push_back(name);
        }
    }
    std::sort(files.begin(), files.end());
    for (const char* required : {"position", "id"})
    {
        if (!std::binary_search(files.begin(), files.end(), required))
        {
            fatalIOError((dir/required).string(), 0, "Missing field file '"
                + std::string(required) + "' of body '" + body.name()
                + "': every body has position and id");
        }
    }
    // position first: its list, bounded by the file's size, gives the
    // body's size, against which a uniform list N{v} is then checked
    // (N{v} first would allocate any N it says).
    std::stable_partition(files.begin(), files.end(),
        [](const std::string& f) { return f == "position"; });

    // readField checks each size against the body's; an empty first field
    // would let a later one resize the body, so check that case here.
    label size = -1;
    for (const auto& name : files)
    {
        readField(dir/name, body);
        checkPlanar(dir/name, body, name);
        if (size >= 0 && body.size() != size)
        {
            fatalIOError((dir/name).string(), 0, "Field '" + name + "' has "
                + std::to_string(body.size()) + " values but body '"
                + body.name() + "' has " + std::to_string(size)
                + " particles: all fields of a body must have the same size");
        }
        size = body.size();
    }
    return body;
}


// Swaps two existing paths atomically; false where unsupported.
bool exchangePaths(const fs::path& a, const fs::path& b)
{
#ifdef RENAME_EXCHANGE
    if (::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(),
                    RENAME_EXCHANGE) == 0)
    {
        return true;
    }
#endif
    (void)a;
    (void)b;
    return false;
}


void renameOrFail(const fs::path& from, const fs::path& to)
{
    std::error_code ec;
    fs::rename(from, to, ec);
    if (ec)
    {
        fatalError("Cannot rename \"" + from.string() + "\" to \""
            + to.string() + "\": " + ec.message());
    }
}

} // End anonymous namespace


writeFormat writeFormatFromName(const std::string& name)
{
    if (name == "ascii")
    {
        return writeFormat::ascii;
    }
    if (name == "binary")
    {
        return writeFormat::binary;
    }
    fatalError("Unknown writeFormat '" + name
        + "'\nValid writeFormats are: ascii binary");
}


// * * * * * * * * * * * * * * * Finding times * * * * * * * * * * * * * * //

std::vector<timeInstant> findTimes(const fs::path& caseDir)
{
    std::error_code ec;
    if (!fs::is_directory(caseDir, ec))
    {
        fatalError("Cannot find case directory \"" + caseDir.string() + "\"");
    }
    std::vector<timeInstant> times;
    for (const auto& e : fs::directory_iterator(caseDir))
    {
        const std::string name = e.path().filename().string();
        double t = 0;
        // Hidden: a write in progress or one that was interrupted.
        if (name[0] != '.' && e.is_directory() && parseTimeName(name, t))
        {
            times.push_back({t, name});
        }
    }
    std::sort(times.begin(), times.end(),
        [](const timeInstant& a, const timeInstant& b)
        {
            return a.value < b.value || (a.value == b.value && a.name < b.name);
        });
    return times;
}


std::string initialTimeName(const fs::path& caseDir)
{
    const std::vector<timeInstant> times = findTimes(caseDir);
    return times.empty() ? std::string() : times.front().name;
}


std::vector<std::string> writesUpTo(const fs::path& caseDir, const double t)
{
    const std::vector<timeInstant> times = findTimes(caseDir);
    std::vector<std::string> names;
    for (std::size_t i = 1; i < times.size(); ++i)
    {
        if (times[i].value <= t + 1e-12*std::max(1.0, std::abs(t)))
        {
            names.push_back(times[i].name);
        }
    }
    return names;
}


// * * * * * * * * * * * * * * * * * Writing * * * * * * * * * * * * * * * //

void writeTimeDirectory(const fs::path& caseDir, const timeState& state,
                        const std::vector<particleBody>& bodies,
                        writeFormat format, int precision)
{
    checkTimeName(state.name);
    std::set<std::string> names;
    for (const auto& body : bodies)
    {
        if (!names.insert(body.name()).second)
        {
            fatalError("Two bodies are called '" + body.name()
                + "': body names must be unique in a time directory");
        }
    }

    std::error_code ec;
    fs::create_directories(caseDir, ec);
    if (ec)
    {
        fatalError("Cannot create case directory \"" + caseDir.string()
            + "\": " + ec.message());
    }
    const std::string pid = std::to_string(::getpid());
    const fs::path target = caseDir/state.name;
    const fs::path tmp = caseDir/("." + state.name + ".tmp." + pid);
    // Left by an earlier run that had our pid and was killed.
    fs::remove_all(tmp, ec);

    try
    {
        fs::create_directory(tmp);
        for (const auto& body : bodies)
        {
            const fs::path dir = tmp/body.name();
            const std::string location = state.name + "/" + body.name();
            fs::create_directory(dir);
            writeBodyProperties(dir/"bodyProperties", body, location);
            for (const auto& field : body.fieldNames())
            {
                writeField(dir/field, body, field, format, precision,
                           location);
            }
            particleFiles::syncPath(dir);
        }
        fs::create_directory(tmp/"uniform");
        writeTimeDict(tmp/"uniform"/"time", state, state.name + "/uniform");
        particleFiles::syncPath(tmp/"uniform");
        particleFiles::syncPath(tmp);

        if (fs::exists(target))
        {
            if (exchangePaths(tmp, target))
            {
                // tmp now holds the old directory: the write is done, and
                // what cannot be removed now the next start removes.
                particleFiles::syncPath(caseDir);
                fs::remove_all(tmp, ec);
                return;
            }
            const fs::path old = caseDir/("." + state.name + ".old." + pid);
            fs::remove_all(old);
            renameOrFail(target, old);
            try
            {
                renameOrFail(tmp, target);
            }
            catch (...)
            {
                fs::rename(old, target, ec);
                throw;
            }
            particleFiles::syncPath(caseDir);
            fs::remove_all(old, ec);
        }
        else
        {
            renameOrFail(tmp, target);
            particleFiles::syncPath(caseDir);
        }
    }
    catch (const fs::filesystem_error& err)
    {
        fs::remove_all(tmp, ec);
        fatalError("Cannot write time directory \"" + target.string()
            + "\": " + err.what());
    }
    catch (...)
    {
        fs::remove_all(tmp, ec);
        throw;
    }
}


// * * * * * * * * * * * * * * * * * Reading * * * * * * * * * * * * * * * //

std::vector<std::string> removeInterruptedWrites(const fs::path& caseDir,
    std::vector<std::string>* kept)
{
    std::vector<std::string> removed;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(caseDir, ec))
    {
        const std::string name = e.path().filename().string();
        // .<time>.tmp.<pid>, .<time>.old.<pid> (writeTimeDirectory) or
        // .<time>.purge.<pid> (purgeWrite), <time> a time name.
        std::size_t tag = name.rfind(".tmp.");
        if (tag == std::string::npos) tag = name.rfind(".old.");
        std::size_t tagLength = 5;
        if (tag == std::string::npos)
        {
            tag = name.rfind(".purge.");
            tagLength = 7;
        }
        double t = 0;
        if
        (
            name.size() < 2 || name[0] != '.' || tag == std::string::npos
         || tag < 2 || !e.is_directory(ec)
         || !parseTimeName(name.substr(1, tag - 1), t)
        )
        {
            continue;
        }
        const std::string pid = name.substr(tag + tagLength);
        if (pid.empty()
         || pid.find_first_not_of("0123456789") != std::string::npos)
        {
            continue;
        }
        // Not a process id (beyond pid_t): not the writer's name.
        long id = 0;
        const auto [end, err] =
            std::from_chars(pid.data(), pid.data() + pid.size(), id);
        if (err != std::errc() || id <= 0
         || id > long(std::numeric_limits<pid_t>::max()))
        {
            continue;
        }
        // A live writer (kill 0 succeeds, or is refused to us) keeps it.
        if (::kill(pid_t(id), 0) == 0 || errno == EPERM)
        {
            continue;
        }
        // So does a missing <time> with a .old beside: a write stopped
        // between its two renames (target to .old, .tmp to target) left
        // the time's only copies there. A .tmp alone is a write that never
        // got its name; a .purge was being deleted.
        const std::string time = name.substr(1, tag - 1);
        const std::string kind = name.substr(tag + 1, tagLength - 2);
        if (kind != "purge" && !fs::is_directory(caseDir/time, ec)
         && (kind == "old"
          || fs::is_directory(caseDir/("." + time + ".old." + pid), ec)))
        {
            if (kind == "old" && kept) kept->push_back(name);
            continue;
        }
        fs::remove_all(e.path(), ec);
        removed.push_back(name);
    }
    std::sort(removed.begin(), removed.end());
    if (kept) std::sort(kept->begin(), kept->end());
    return removed;
}


std::vector<std::string> bodyNames(const fs::path& caseDir,
                                   const std::string& timeName)
{
    const fs::path dir = caseDir/timeName;
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
    {
        fatalError("Cannot find time directory \"" + dir.string()
            + "\"\nTimes in the case:" + listTimes(findTimes(caseDir)));
    }
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
    {
        const std::string name = e.path().filename().string();
        if (name[0] != '.' && name != "uniform" && e.is_directory())
        {
            names.push_back(name);
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}


std::vector<particleBody> readTimeDirectory(const fs::path& caseDir,
                                            const std::string& timeName)
{
    const fs::path dir = caseDir/timeName;
    const std::vector<std::string> names = bodyNames(caseDir, timeName);
    std::vector<particleBody> bodies;
    bodies.reserve(names.size());
    for (const auto& name : names)
    {
        bodies.push_back(readBody(dir/name));
    }
    return bodies;
}


timeState readTimeState(const fs::path& caseDir, const std::string& timeName)
{
    const fs::path dir = caseDir/timeName;
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
    {
        fatalError("Cannot find time directory \"" + dir.string()
            + "\"\nTimes in the case:" + listTimes(findTimes(caseDir)));
    }
    timeState state;
    state.name = timeName;
    const fs::path file = dir/"uniform"/"time";
    if (!fs::exists(file))
    {
        if (!parseTimeName(timeName, state.value))
        {
            fatalError("Time directory \"" + dir.string() + "\" has no "
                "uniform/time and its name '" + timeName
                + "' is not a time");
        }
        return state;
    }

    const dictionary dict = dictionary::fromFile(file);
    state.value = dict.get<double>("value");
    state.index = dict.get<label>("index");
    state.deltaT = dict.get<double>("deltaT");
    state.deltaT0 = dict.getOrDefault<double>("deltaT0", state.deltaT);
    state.beginTime = dict.getOrDefault<double>("beginTime", 0);
    for (const std::string& key : dict.keys())
    {
        if (key != "value" && key != "name" && key != "index"
         && key != "deltaT" && key != "deltaT0" && key != "beginTime")
        {
            state.solverValues.emplace_back(key, dict.get<double>(key));
        }
    }
    const auto check = [&dict](const char* key, double v, bool nonNegative)
    {
        if (!std::isfinite(v) || (nonNegative && v < 0))
        {
            dict.fatalAt(key, "Keyword '" + std::string(key)
                + "': expected a finite" + (nonNegative ? " non-negative" : "")
                + " number");
        }
    };
    check("value", state.value, false);
    // The name is the value printed in some format and precision; any
    // other value is a copied or edited directory, whose state would be
    // restarted at the wrong time.
    double named = 0;
    if (parseTimeName(timeName, named))
    {
        bool matches = false;
        for (const timeFormat f :
             {timeFormat::general, timeFormat::fixed, timeFormat::scientific})
        {
            for (int p = 1; p <= 17 && !matches; ++p)
            {
                matches = sphvcpm::timeName(state.value, f, p) == timeName;
            }
        }
        if (!matches)
        {
            std::ostringstream os;
            os  << std::setprecision(17) << "Keyword 'value': the time "
                << state.value << " is not the time of its directory '"
                << timeName << "' (copied or edited?): rename the directory"
                   " or correct the value";
            dict.fatalAt("value", os.str());
        }
    }
    check("beginTime", state.beginTime, false);
    check("deltaT", state.deltaT, true);
    check("deltaT0", state.deltaT0, true);
    if (state.index < 0)
    {
        dict.fatalAt("index", "Keyword 'index': expected a time-step index "
            ">= 0, found " + std::to_string(state.index));
    }
    return state;
}

} // End namespace sphvcpm
