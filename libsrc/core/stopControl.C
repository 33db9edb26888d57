/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "stopControl.H"
#include "error.H"
#include "formatting.H"

#include <atomic>
#include <chrono>
#include <cstring>
#include <ctime>
#include <iterator>
#include <ostream>
#include <string>
#include <vector>

#include <unistd.h>

namespace sphvcpm
{

namespace
{

// Lock-free, so safe in a handler, which may run on any thread.
std::atomic<int> stopSignal{0};
std::atomic<long long> firstSignalNs{0};
static_assert(std::atomic<int>::is_always_lock_free
           && std::atomic<long long>::is_always_lock_free);

long long monotonicNs()
{
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);   // async-signal-safe
    return t.tv_sec*1000000000LL + t.tv_nsec;
}

// The signals that ask for a stop: Ctrl-C, kill or a batch system's time
// limit, and the terminal or ssh session of the run closing.
constexpr int stopSignals[] = {SIGINT, SIGTERM, SIGHUP};

// The first signal asks for a stop. One within a second of it (any of the
// three) is taken as the same request delivered twice (timeout signals
// the child, then its process group; a terminal's Ctrl-C reaches every
// process of the job); a later one ends the process at once.
extern "C" void onStopSignal(const int sig)
{
    const long long now = monotonicNs();
    int none = 0;
    if (stopSignal.compare_exchange_strong(none, sig))
    {
        firstSignalNs = now;
        // Said at once (write is async-signal-safe): a step that sub-cycles
        // a stiff solid may take minutes, and a silent Ctrl-C looks lost.
        // A closed terminal's stderr refuses it: nothing to do about that.
        const auto say = [](const char* text)
        {
            const ssize_t written = ::write(STDERR_FILENO, text,
                                            std::strlen(text));
            (void)written;
        };
        say("\n--> Stop requested (");
        say(sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "SIGHUP");
        say("): the step in progress finishes, its state is written and the"
            " run stops; signal again, a second or more from now, to end at"
            " once without writing\n");
        return;
    }
    const long long first = firstSignalNs;   // 0: being set just now
    if (first == 0 || now - first < 1000000000LL) return;
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

// controlDict is looked at once a second at most (a stat and a read per
// step would load a parallel file system's metadata server), and read once
// it is this old (an editor may still be writing it).
constexpr std::chrono::milliseconds checkInterval{1000};
constexpr std::chrono::milliseconds modificationSkew{500};


// Keywords whose entries differ between two controlDicts (numbers by
// value), in the order of b, then those only in a.
std::vector<std::string> changedKeys(const dictionary& a, const dictionary& b)
{
    const auto only = [](const dictionary& d, const std::string& key)
    {
        dictionary one = d;
        for (const std::string& k : d.keys())
        {
            if (k != key) one.remove(k);
        }
        return one;
    };
    std::vector<std::string> changed;
    for (const std::string& k : b.keys())
    {
        if (!a.found(k) || only(a, k) != only(b, k)) changed.push_back(k);
    }
    for (const std::string& k : a.keys())
    {
        if (!b.found(k)) changed.push_back(k);
    }
    return changed;
}

} // End anonymous namespace


stopControl::stopControl(timeControl& control, writeSchedule& schedule,
                         const std::filesystem::path& caseDir,
                         std::ostream& log)
:
    control_(control),
    schedule_(schedule),
    file_(caseDir/"system/controlDict"),
    log_(log)
{
    static_assert(std::size(stopSignals)
               == sizeof previous_/sizeof previous_[0]);
    stopSignal = 0;
    firstSignalNs = 0;
    struct sigaction sa{};
    sa.sa_handler = onStopSignal;
    // The other stop signals wait while the handler runs (they would
    // otherwise race on the first signal's time).
    sigemptyset(&sa.sa_mask);
    for (const int sig : stopSignals) sigaddset(&sa.sa_mask, sig);
    // SA_RESTART: a write to the log that the signal interrupts goes on.
    sa.sa_flags = SA_RESTART;
    // A signal ignored when the run started stays ignored: a background
    // job of a script starts with SIGINT ignored and must not stop on the
    // Ctrl-C meant for the foreground; nohup ignores SIGHUP so that the
    // run outlives its terminal.
    for (std::size_t i = 0; i < std::size(stopSignals); ++i)
    {
        sigaction(stopSignals[i], nullptr, &previous_[i]);
        if (previous_[i].sa_handler != SIG_IGN)
        {
            sigaction(stopSignals[i], &sa, nullptr);
        }
    }
    if (previous_[0].sa_handler == SIG_IGN)   // SIGINT
    {
        // Said, since kill -INT then does nothing and a user waits.
        log_<< "SIGINT (Ctrl-C) is ignored, as it was when the run started"
               " (a script's background job): stop the run with kill -TERM "
            << ::getpid() << ", or stopAt writeNow in system/controlDict\n"
            << std::endl;
    }
}


stopControl::~stopControl()
{
    for (std::size_t i = 0; i < std::size(stopSignals); ++i)
    {
        sigaction(stopSignals[i], &previous_[i], nullptr);
    }
}


stopAction stopControl::afterStep(const double time)
{
    if (stopSignal)
    {
        return stopAction::writeNow;
    }
    const auto now = std::chrono::steady_clock::now();
    if (control_.runTimeModifiable && now >= nextCheck_)
    {
        nextCheck_ = now + checkInterval;
        std::error_code ec;
        const auto modified = std::filesystem::last_write_time(file_, ec);
        if
        (
            !ec && std::filesystem::file_time_type::clock::now() - modified
            >= modificationSkew
        )
        {
            // Told by its text, not its time: two edits within a second
            // have one time on a file system that keeps whole seconds.
            std::string text = timeControl::textOf(file_);
            if (text != control_.text) reread(time, std::move(text));
        }
    }
    if (control_.stopAt == "writeNow") return stopAction::writeNow;
    if (control_.stopAt == "noWriteNow") return stopAction::noWriteNow;
    if (control_.stopAt == "nextWrite") return stopAction::nextWrite;
    return stopAction::none;
}


void stopControl::reread(const double time, std::string text)
{
    timeControl next;
    try
    {
        next = timeControl::read(file_.parent_path().parent_path());
    }
    catch (const FatalError& e)
    {
        // Said once: read again when it changes next.
        control_.text = std::move(text);
        warning("system/controlDict changed at time " + str(time)
            + " but cannot be read; the run goes on with the settings it"
              " has:\n" + e.message(), e.file(), e.line());
        return;
    }

    // What the loops read at every step (or write) applies now.
    const std::vector<std::string> live{"endTime", "stopAt", "deltaT",
        "adjustTimeStep", "maxCo", "maxDeltaT", "minDeltaT", "writeControl",
        "writeInterval", "purgeWrite", "writeFormat", "writePrecision",
        "logInterval", "runTimeModifiable"};
    std::string applied, later;
    for (const std::string& k : changedKeys(control_.dict, next.dict))
    {
        bool isLive = false;
        for (const std::string& l : live) isLive = isLive || l == k;
        std::string& list = isLive ? applied : later;
        list += (list.empty() ? "" : ", ") + k;
    }
    const bool scheduleChanged =
        next.writeControl != control_.writeControl
     || next.writeInterval != control_.writeInterval;
    control_.endTime = next.endTime;
    control_.stopAt = next.stopAt;
    control_.deltaT = next.deltaT;
    control_.adjustTimeStep = next.adjustTimeStep;
    control_.maxCo = next.maxCo;
    control_.maxDeltaT = next.maxDeltaT;
    control_.minDeltaT = next.minDeltaT;
    control_.writeControl = next.writeControl;
    control_.writeInterval = next.writeInterval;
    control_.purgeWrite = next.purgeWrite;
    control_.writeFormatName = next.writeFormatName;
    control_.writePrecision = next.writePrecision;
    control_.logInterval = next.logInterval;
    control_.runTimeModifiable = next.runTimeModifiable;
    control_.text = std::move(next.text);
    // The next change is told against this one.
    control_.dict = std::move(next.dict);
    if (scheduleChanged)
    {
        // A write time of the new interval at this very step is kept.
        schedule_.restart(time, true);
    }

    log_<< "system/controlDict changed at time " << schedule_.name(time);
    if (!applied.empty())
    {
        log_<< ": now endTime " << str(control_.endTime)
            << (time >= control_.endTime*(1 - 1e-12) ? " (reached)" : "")
            << ", stopAt " << control_.stopAt << " (changed: " << applied
            << ")";
    }
    else
    {
        log_<< ": nothing the run uses now";
    }
    if (!later.empty())
    {
        log_<< "; read at the next start: " << later;
    }
    log_<< "\n" << std::endl;
}


int stopControl::caughtSignal()
{
    return stopSignal;
}


void stopControl::raiseCaughtSignal()
{
    if (const int sig = stopSignal)
    {
        std::signal(sig, SIG_DFL);
        std::raise(sig);
    }
}


void stopControl::reportStop(const stopAction action, const double time)
    const
{
    const std::string t = schedule_.name(time);
    if (stopSignal)
    {
        log_<< "Stopped at time " << t << " on " << strsignal(stopSignal)
            << ", time " << schedule_.lastWriteName()
            << " written (startFrom latestTime goes on from it)\n"
            << std::endl;
        return;
    }
    log_<< "Stopped at time " << t << " by stopAt "
        << (action == stopAction::writeNow ? "writeNow"
          : action == stopAction::noWriteNow ? "noWriteNow" : "nextWrite")
        << " in system/controlDict; the latest time written is "
        << schedule_.lastWriteName()
        << " (set stopAt endTime to go on)\n" << std::endl;
}

} // End namespace sphvcpm
