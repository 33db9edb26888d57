/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "timeControl.H"
#include "error.H"
#include "formatting.H"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <unistd.h>

namespace sphvcpm
{

std::string timeControl::textOf(const std::filesystem::path& file)
{
    std::ifstream is(file, std::ios::binary);
    std::ostringstream os;
    if (is) os << is.rdbuf();
    return os.str();
}


timeControl timeControl::read(const std::filesystem::path& caseDir)
{
    const auto file = caseDir/"system/controlDict";
    if (!std::filesystem::exists(file))
    {
        fatalIOError(file.string(), 0,
            "cannot find system/controlDict of the case");
    }
    timeControl tc;
    // Before reading: a change made while it is read is seen later.
    tc.text = textOf(file);
    tc.dict = dictionary::fromFile(file);
    const dictionary& d = tc.dict;
    d.checkKeywords({"application", "startFrom", "startTime", "stopAt",
        "endTime", "deltaT", "adjustTimeStep", "maxCo", "maxDeltaT",
        "minDeltaT", "writeControl", "writeInterval", "purgeWrite",
        "writeFormat", "writePrecision", "writeCompression", "timeFormat",
        "timePrecision", "runTimeModifiable", "logInterval", "device",
        "functions", "libs"});

    // Read though unused, so that a missing ';' after them cannot swallow
    // the entries that follow (OpenFOAM reads them too).
    if (d.found("application")) d.get<std::string>("application");
    if (d.found("libs")) d.get<std::vector<std::string>>("libs");
    tc.runTimeModifiable = d.getOrDefault<bool>("runTimeModifiable", true);

    const std::string from = d.getWordOrDefault("startFrom",
        {"startTime", "latestTime", "firstTime"}, "latestTime");
    tc.startFrom = from == "startTime" ? startFromType::startTime
                 : from == "firstTime" ? startFromType::firstTime
                 : startFromType::latestTime;
    tc.startTime = d.getOrDefault<double>("startTime", 0);
    tc.stopAt = d.getWordOrDefault("stopAt",
        {"endTime", "writeNow", "noWriteNow", "nextWrite"}, "endTime");
    tc.endTime = d.get<double>("endTime");
    if (!(tc.endTime > 0))
    {
        d.fatalAt("endTime", "endTime must be > 0");
    }
    tc.deltaT = d.getPositive("deltaT");
    tc.adjustTimeStep = d.getOrDefault<bool>("adjustTimeStep", true);
    if (tc.deltaT > tc.endTime)
    {
        // minDeltaT defaults to deltaT*1e-6: say what is wrong here rather
        // than through a floor above every step.
        d.fatalAt("deltaT", "deltaT " + str(tc.deltaT) + " s is longer than"
            " endTime " + str(tc.endTime) + " s; deltaT is the first step"
            " (adjustTimeStep yes) or every step (no)");
    }
    constexpr double maxFixedSteps = 1e9;
    if (!tc.adjustTimeStep && tc.endTime/tc.deltaT > maxFixedSteps)
    {
        d.fatalAt("deltaT", "adjustTimeStep no with deltaT " + str(tc.deltaT)
            + " s would take " + str(tc.endTime/tc.deltaT) + " steps to"
            " endTime " + str(tc.endTime) + " s (more than "
            + str(maxFixedSteps) + "): raise deltaT, or set adjustTimeStep"
            " yes for the stable step");
    }
    tc.maxCo = d.getOrDefault<double>("maxCo", 0.2);
    if (!(tc.maxCo > 0 && tc.maxCo <= 1))
    {
        d.fatalAt("maxCo", "maxCo (the CFL number) must be in (0, 1];"
            " 0.2 is the usual SPH value");
    }
    tc.maxDeltaT = d.found("maxDeltaT") ? d.getPositive("maxDeltaT") : 1e30;
    tc.minDeltaT = d.found("minDeltaT") ? d.getPositive("minDeltaT")
                                        : tc.deltaT*1e-6;

    const std::string wc = d.getWordOrDefault("writeControl",
        {"adjustableRunTime", "runTime", "timeStep"}, "adjustableRunTime");
    tc.writeControl = wc == "timeStep" ? writeControlType::timeStep
                    : wc == "runTime" ? writeControlType::runTime
                    : writeControlType::adjustableRunTime;
    tc.writeInterval = d.getPositive("writeInterval");
    if (tc.writeControl == writeControlType::timeStep
     && tc.writeInterval != std::floor(tc.writeInterval))
    {
        d.fatalAt("writeInterval", "writeControl timeStep needs a whole"
            " number of steps as writeInterval");
    }
    if (tc.writeControl == writeControlType::adjustableRunTime
     && tc.writeInterval < tc.minDeltaT)
    {
        // Each write time is landed on, so every step would be shorter
        // than the floor the run is stopped at (runTime writes after the
        // step that passes it: every step, at worst).
        std::ostringstream os;
        os  << "writeInterval " << tc.writeInterval << " s is below minDeltaT "
            << tc.minDeltaT << " s (the smallest time step allowed; by"
            " default deltaT*1e-6)";
        d.fatalAt("writeInterval", os.str());
    }
    tc.purgeWrite = d.getOrDefault<label>("purgeWrite", 0);
    if (tc.purgeWrite < 0)
    {
        d.fatalAt("purgeWrite", "purgeWrite must be >= 0");
    }
    tc.writeFormatName = d.getWordOrDefault("writeFormat",
        {"ascii", "binary"}, "binary");
    if (d.found("writeCompression"))
    {
        const std::string c = d.getWord("writeCompression", {"off", "no",
            "false", "uncompressed", "on", "yes", "true", "compressed"});
        if (c == "on" || c == "yes" || c == "true" || c == "compressed")
        {
            const entry& e = *d.findEntry("writeCompression");
            warning("writeCompression " + c + ": time directories are"
                " written uncompressed (binary writeFormat is the compact"
                " one)", e.file(), e.line());
        }
    }
    tc.writePrecision = d.getOrDefault<label>("writePrecision", 10);
    if (tc.writePrecision < 1 || tc.writePrecision > 17)
    {
        d.fatalAt("writePrecision", "writePrecision must be in [1, 17]");
    }
    if (d.found("timeFormat"))
    {
        tc.format = timeFormatFromName(d.getWord("timeFormat",
            {"general", "fixed", "scientific"}));
    }
    tc.timePrecision = d.getOrDefault<label>("timePrecision", 6);
    if (tc.timePrecision < 1 || tc.timePrecision > 17)
    {
        d.fatalAt("timePrecision", "timePrecision must be in [1, 17]");
    }
    tc.logInterval = d.getOrDefault<label>("logInterval", 100);
    if (tc.logInterval < 1)
    {
        d.fatalAt("logInterval", "logInterval must be >= 1 (steps)");
    }
    tc.device = d.getWordOrDefault("device", {"cpu", "cuda", "auto"}, "cpu");
    return tc;
}

} // End namespace sphvcpm


namespace sphvcpm
{

namespace
{

// k*writeInterval in binary can be an ulp off the decimal time it means
// (3*0.05 = 0.15000000000000002), which uniform/time and ParaView would
// then show: the double nearest to its 15-digit decimal instead.
double decimalTime(const double t)
{
    if (!std::isfinite(t)) return t;
    char text[32];
    std::snprintf(text, sizeof text, "%.15g", t);
    return std::strtod(text, nullptr);
}

} // End anonymous namespace


writeSchedule::writeSchedule(const timeControl& control,
                             const double startTime)
:
    control_(control),
    precision_(control.timePrecision),
    lastName_(timeName(startTime, control.format, control.timePrecision)),
    lastTime_(startTime)
{
    restart(startTime);
}


void writeSchedule::restart(const double startTime, const bool atTimeToo)
{
    const timeControl& control = control_;
    nextIndex_ = atTimeToo
      ? std::ceil(startTime/control.writeInterval - 1e-9)
      : std::floor(startTime/control.writeInterval + 1e-9) + 1;
    next_ = decimalTime(nextIndex_*control.writeInterval);
    if (!std::isfinite(next_))
    {
        // startTime/writeInterval overflows (runTime with a subnormal
        // interval): a write after each step, as written() goes on.
        next_ = startTime
              + std::max(control.writeInterval, 2e-12*std::abs(startTime));
    }
}


namespace
{

// t has reached target, to round-off (either sign).
bool reached(const double t, const double target)
{
    return t >= target - 1e-12*std::abs(target);
}

} // End anonymous namespace


double writeSchedule::limitStep(const double time, double dt)
{
    landed_ = false;
    double target = control_.endTime;
    if (control_.writeControl == writeControlType::adjustableRunTime)
    {
        target = std::min(target, next_);
    }
    const double remaining = target - time;
    if (remaining <= dt*(1 + 1e-9))
    {
        dt = remaining;
        landed_ = true;
    }
    else if (remaining < 2*dt)
    {
        dt = 0.5*remaining;    // two even steps rather than a sliver
    }
    return dt;
}


double writeSchedule::landingTime() const
{
    return control_.writeControl == writeControlType::adjustableRunTime
      ? std::min(control_.endTime, next_) : control_.endTime;
}


bool writeSchedule::due(const double time, const label timeIndex) const
{
    switch (control_.writeControl)
    {
        case writeControlType::timeStep:
            return timeIndex % label(control_.writeInterval) == 0;
        case writeControlType::runTime:
            return reached(time, next_);
        default:
            return landed_ && reached(time, next_);
    }
}


void writeSchedule::written(const double time, const std::string& name,
                            const std::filesystem::path& caseDir,
                            const std::string& startTimeName)
{
    // The k-th write time as k*writeInterval: a sum of intervals would
    // drift (a run from -1 by 0.1 would name its zero -1.38778e-16). Past
    // several write times at once (runTime with an interval below the
    // step), straight to the next one after `time`.
    const double interval = control_.writeInterval;
    if (reached(time, next_))
    {
        nextIndex_ = std::max(nextIndex_ + 1,
                              std::floor(time/interval + 1e-9) + 1);
        next_ = decimalTime(nextIndex_*interval);
    }
    if (reached(time, next_))
    {
        // Round-off at a write time: the one after.
        nextIndex_ += 1;
        next_ = decimalTime(nextIndex_*interval);
    }
    if (!std::isfinite(next_) || reached(time, next_))
    {
        // An interval below the round-off of the time (the index no longer
        // counts in ones, or overflows): the write after the next step.
        next_ = time + std::max(interval, 2e-12*std::abs(time));
        nextIndex_ = next_/interval;
    }
    lastName_ = name;
    lastTime_ = time;
    if (control_.purgeWrite > 0 && name != startTimeName)
    {
        if (writtenNames_.empty() || writtenNames_.back() != name)
        {
            writtenNames_.push_back(name);
        }
        while (label(writtenNames_.size()) > control_.purgeWrite)
        {
            // Renamed out of sight first, so that a run killed while it is
            // deleted leaves no half time directory (the next start
            // removes what is left: removeInterruptedWrites).
            const std::string& purged = writtenNames_.front();
            const auto hidden = caseDir/("." + purged + ".purge."
                + std::to_string(::getpid()));
            std::error_code ec;
            std::filesystem::rename(caseDir/purged, hidden, ec);
            std::filesystem::remove_all(ec ? caseDir/purged : hidden);
            writtenNames_.erase(writtenNames_.begin());
        }
    }
}



std::string writeSchedule::name(const double t) const
{
    return timeName(t, control_.format, precision_);
}


std::string writeSchedule::writeName(const double t)
{
    // Written again at the same time (the last good state of a run that
    // blew up right after a write): the same directory.
    if (t == lastTime_)
    {
        return lastName_;
    }
    // Names that read as the same number ("0.0" and "0.00") repeat too.
    const auto same = [](const std::string& a, const std::string& b)
    {
        double x = 0, y = 0;
        return a == b
            || (parseTimeName(a, x) && parseTimeName(b, y) && x == y);
    };
    // Nor may it read as nearer the previous write than t ("0.0001" for
    // 5e-05 after 0, in fixed format), or the next write would repeat it.
    const auto unclear = [&](const std::string& n)
    {
        double x = 0;
        return same(n, lastName_) || !parseTimeName(n, x)
            || !(std::abs(x - t) < 0.5*std::abs(t - lastTime_));
    };
    const int before = precision_;
    std::string n = name(t);
    while (unclear(n) && precision_ < 17)
    {
        ++precision_;
        n = name(t);
    }
    if (precision_ != before)
    {
        std::ostringstream os;
        os  << "Increased the timePrecision from " << before << " to "
            << precision_ << " to distinguish the time names of "
            << std::setprecision(17) << t << " and the write before it ("
            << lastName_ << ")";
        warning(os.str());
    }
    return n;
}

} // End namespace sphvcpm
