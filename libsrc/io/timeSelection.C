/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// -time / -latestTime / -noZero selection (see timeSelection.H).

#include "timeSelection.H"
#include "argList.H"
#include "error.H"
#include "formatting.H"

#include <cmath>
#include <limits>

namespace sphvcpm
{

namespace
{

const char* const syntaxHelp =
    "Expected a time (0.1), a range (0:0.5, :0.5, 0.2: or :) or a comma-"
    "separated list of those, e.g. -time '0,0.2:0.4'";

bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

} // End anonymous namespace


void timeSelection::addOptions(argList& args)
{
    args.addOption("time", "ranges",
        "select times: '0.1' (nearest), '0:0.5', ':0.5', '0.2:' or a comma-"
        "separated list of those");
    args.addBoolOption("latestTime", "select the latest time only");
    args.addBoolOption("noZero", "exclude time 0 from the selection");
}


timeSelection::timeSelection(const argList& args)
:
    latestTime_(args.found("latestTime")),
    noZero_(args.found("noZero"))
{
    if (args.found("time"))
    {
        parse(args.option("time"));
    }
}


timeSelection::timeSelection(const std::string& ranges, bool latestTime,
                             bool noZero)
:
    latestTime_(latestTime),
    noZero_(noZero)
{
    if (!ranges.empty())
    {
        parse(ranges);
    }
}


void timeSelection::parse(const std::string& text)
{
    // OpenFOAM lets -latestTime win silently; a user who gave both meant
    // something, so say which to drop.
    if (latestTime_)
    {
        fatalError("Options -time '" + text + "' and -latestTime conflict: "
            "-latestTime selects only the latest time. Give one of them.");
    }
    text_ = text;
    hasRanges_ = true;
    auto bad = [&](const std::string& why)
    {
        fatalError("Invalid -time '" + text + "': " + why + ".\n"
            + syntaxHelp);
    };

    // Blanks around ':' belong to the range ("0 : 0.5"); elsewhere they
    // separate items like commas do.
    std::string s;
    for (std::size_t i = 0; i < text.size(); ++i)
    {
        if (isSpace(text[i]))
        {
            std::size_t j = i;
            while (j < text.size() && isSpace(text[j]))
            {
                ++j;
            }
            const bool nextToColon = (!s.empty() && s.back() == ':')
                || (j < text.size() && text[j] == ':');
            if (!nextToColon)
            {
                s += ',';
            }
            i = j - 1;
        }
        else
        {
            s += text[i] == ';' ? ',' : text[i];
        }
    }

    std::size_t start = 0;
    while (start <= s.size())
    {
        std::size_t end = s.find(',', start);
        if (end == std::string::npos)
        {
            end = s.size();
        }
        const std::string item = s.substr(start, end - start);
        start = end + 1;
        if (item.empty())
        {
            continue;
        }

        const std::size_t colon = item.find(':');
        range r;
        if (colon == std::string::npos)
        {
            if (!readNumber(item, r.lower))
            {
                bad("'" + item + "' is not a time");
            }
            r.upper = r.lower;
            r.exact = true;
            r.text = item;
        }
        else
        {
            if (item.find(':', colon + 1) != std::string::npos)
            {
                bad("'" + item + "' has more than one ':'");
            }
            const std::string lo = item.substr(0, colon);
            const std::string hi = item.substr(colon + 1);
            r.lower = -std::numeric_limits<double>::infinity();
            r.upper = std::numeric_limits<double>::infinity();
            r.exact = false;
            if (!lo.empty() && !readNumber(lo, r.lower))
            {
                bad("'" + lo + "' in '" + item + "' is not a time");
            }
            if (!hi.empty() && !readNumber(hi, r.upper))
            {
                bad("'" + hi + "' in '" + item + "' is not a time");
            }
            if (r.lower > r.upper)
            {
                bad("the range '" + item + "' is empty (" + lo + " > " + hi
                    + ")");
            }
        }
        ranges_.push_back(r);
    }

    if (ranges_.empty())
    {
        bad("no time given");
    }
}


namespace
{

// OpenFOAM's rule: a single value picks the nearest time (the first of
// two as near); times is not empty.
std::size_t nearestIndex(const std::vector<timeInstant>& times, double value)
{
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < times.size(); ++i)
    {
        if
        (
            std::abs(times[i].value - value)
          < std::abs(times[nearest].value - value)
        )
        {
            nearest = i;
        }
    }
    return nearest;
}

} // End anonymous namespace


std::vector<timeInstant> timeSelection::eligible(
    const std::vector<timeInstant>& times) const
{
    std::vector<timeInstant> result;
    for (const auto& t : times)
    {
        if (!(noZero_ && t.value == 0))
        {
            result.push_back(t);
        }
    }
    return result;
}


std::vector<timeInstant> timeSelection::select(
    const std::vector<timeInstant>& times) const
{
    const std::vector<timeInstant> candidates = eligible(times);
    if (candidates.empty())
    {
        return candidates;
    }
    if (latestTime_)
    {
        return {candidates.back()};
    }
    if (!hasRanges_)
    {
        return candidates;
    }

    std::vector<bool> selected(candidates.size(), false);
    for (const auto& r : ranges_)
    {
        if (r.exact)
        {
            selected[nearestIndex(candidates, r.lower)] = true;
        }
        else
        {
            for (std::size_t i = 0; i < candidates.size(); ++i)
            {
                const double v = candidates[i].value;
                if (r.lower <= v && v <= r.upper)
                {
                    selected[i] = true;
                }
            }
        }
    }

    std::vector<timeInstant> result;
    for (std::size_t i = 0; i < candidates.size(); ++i)
    {
        if (selected[i])
        {
            result.push_back(candidates[i]);
        }
    }
    return result;
}


std::vector<timeInstant> timeSelection::selectOrFail(
    const std::filesystem::path& caseDir,
    const std::vector<timeInstant>& times) const
{
    if (times.empty())
    {
        fatalError("No time directories in case " + caseDir.string()
            + ": nothing to read (a case holds 0/ or other <time>/"
              " directories of particle fields): run generateParticles"
              " first to write 0/, and sphVcpmFsi for the later times");
    }
    std::vector<timeInstant> result = select(times);
    if (result.empty())
    {
        std::string list;
        for (const auto& t : times)
        {
            list += " " + t.name;
        }
        fatalError("No time of case " + caseDir.string()
            + " is selected by " + describe() + ".\nThe case has times:"
            + list);
    }
    return result;
}


std::vector<timeInstant> timeSelection::selectCase(
    const std::filesystem::path& caseDir) const
{
    return selectOrFail(caseDir, findTimes(caseDir));
}


std::vector<std::string> timeSelection::nearestNotes(
    const std::vector<timeInstant>& times) const
{
    std::vector<std::string> notes;
    const std::vector<timeInstant> candidates = eligible(times);
    if (latestTime_ || candidates.empty())
    {
        return notes;
    }
    for (const auto& r : ranges_)
    {
        if (!r.exact)
        {
            continue;
        }
        const timeInstant& t = candidates[nearestIndex(candidates, r.lower)];
        if (t.value != r.lower)
        {
            notes.push_back("-time " + r.text + ": the nearest time written"
                " is " + t.name);
        }
    }
    return notes;
}


std::string timeSelection::describe() const
{
    std::string s;
    if (hasRanges_)
    {
        s += "-time '" + text_ + "'";
    }
    if (latestTime_)
    {
        s += std::string(s.empty() ? "" : " ") + "-latestTime";
    }
    if (noZero_)
    {
        s += std::string(s.empty() ? "" : " ") + "-noZero";
    }
    return s.empty() ? std::string("the default (all times)") : s;
}

} // End namespace sphvcpm
