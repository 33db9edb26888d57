#include "argList.H"
#include "error.H"
#include "formatting.H"
#include "foamFile.H"
#include "progressEstimate.H"
#include "version.H"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <unistd.h>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sphvcpm
{

namespace
{
const auto wallStart = std::chrono::steady_clock::now();
}

argList::argList(std::string executable, std::string description)
:
    executable_(std::move(executable)),
    description_(std::move(description))
{
    addOption("case", "dir", "specify alternate case directory, default is the cwd");
    addBoolOption("help", "print the usage");
}

void argList::addOption(const std::string& name, const std::string& param,
                        const std::string& usage)
{
    specs_[name] = {param, usage};
}

void argList::addBoolOption(const std::string& name, const std::string& usage)
{
    specs_[name] = {"", usage};
}

void argList::addNote(const std::string& note)
{
    notes_.push_back(note);
}

void argList::printUsage() const
{
    std::cout << "\nUsage: " << executable_ << " [OPTIONS]\n\n"
              << description_ << "\n\noptions:\n";
    auto print = [&](const std::string& name, const optionSpec& spec)
    {
        std::string left = "  -" + name;
        if (!spec.param.empty())
        {
            left += " <" + spec.param + ">";
        }
        std::cout << std::left << std::setw(24) << left;
        if (left.size() >= 24)
        {
            std::cout << "\n" << std::string(24, ' ');
        }
        std::cout << spec.usage << "\n";
    };
    for (const auto& [name, spec] : specs_)
    {
        if (name != "help")
        {
            print(name, spec);
        }
    }
    print("help", specs_.at("help"));
    for (const auto& note : notes_)
    {
        std::cout << "\n" << note << "\n";
    }
    std::cout << std::endl;
}

bool argList::parse(int argc, char** argv)
{
    commandLine_ = executable_;
    for (int i = 1; i < argc; ++i)
    {
        commandLine_ += std::string(" ") + argv[i];
    }

    for (int i = 1; i < argc; ++i)
    {
        std::string arg = argv[i];
        if (arg.size() < 2 || arg[0] != '-')
        {
            printUsage();
            fatalError("Unexpected argument '" + arg + "' to " + executable_
                + ": options start with a single '-' (see -help)");
        }
        std::string name = arg.substr(arg[1] == '-' ? 2 : 1);
        auto spec = specs_.find(name);
        if (spec == specs_.end())
        {
            printUsage();
            fatalError("Invalid option: " + arg);
        }
        if (spec->second.param.empty())
        {
            given_[name] = "";
        }
        else
        {
            if (i + 1 >= argc)
            {
                printUsage();
                fatalError("Option " + arg + " expects <"
                    + spec->second.param + ">");
            }
            given_[name] = argv[++i];
        }
    }

    if (found("help"))
    {
        printUsage();
        return false;
    }

    casePath_ = found("case")
        ? std::filesystem::path(option("case"))
        : std::filesystem::current_path();
    std::error_code ec;
    const auto status = std::filesystem::status(casePath_, ec);
    if (!std::filesystem::is_directory(status))
    {
        // -case system/controlDict, say: not "does not exist".
        fatalError("Case directory " + casePath_.string()
            + (std::filesystem::exists(status)
             ? " (given by -case) exists but is not a directory"
             : " does not exist (given by -case)"));
    }
    casePath_ = std::filesystem::absolute(casePath_).lexically_normal();
    if (casePath_.has_filename() == false)
    {
        casePath_ = casePath_.parent_path();
    }
    // As OpenFOAM's argList, before any dictionary is read, so that
    // #include "$FOAM_CASE/..." and <case> find the case being run (an
    // inherited value may be another case's).
    setenv("FOAM_CASE", casePath_.c_str(), 1);
    setenv("FOAM_CASENAME", casePath_.filename().c_str(), 1);
    return true;
}

bool argList::found(const std::string& name) const
{
    return given_.count(name) > 0;
}

std::string argList::option(const std::string& name) const
{
    auto it = given_.find(name);
    return it == given_.end() ? std::string() : it->second;
}

std::string argList::optionOrDefault(const std::string& name,
                                     const std::string& deflt) const
{
    return found(name) ? option(name) : deflt;
}

void argList::printBanner(const std::string& deviceLine) const
{
    char host[256] = "unknown";
    gethostname(host, sizeof(host) - 1);
    std::time_t now = std::time(nullptr);
    char date[64], clock[64];
    std::strftime(date, sizeof(date), "%b %d %Y", std::localtime(&now));
    std::strftime(clock, sizeof(clock), "%H:%M:%S", std::localtime(&now));
    int threads = 1;
#ifdef _OPENMP
    threads = omp_get_max_threads();
#endif

    writeFoamFileBanner(std::cout);
    std::cout << "Build  : " << SPHVCPM_BUILD
#ifdef SPHVCPM_SINGLE
              << " (single precision)"
#endif
              << "\n"
              << "Exec   : " << commandLine_ << "\n"
              << "Date   : " << date << "\n"
              << "Time   : " << clock << "\n"
              << "Host   : " << host << "\n"
              << "PID    : " << getpid() << "\n"
              << "Case   : " << casePath_.string() << "\n"
              << "nProcs : 1\n"
              << "Threads: " << threads << " (OpenMP)\n"
              << "Device : " << deviceLine << "\n"
              << "// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n"
              << std::endl;
}

std::string threadContentionNote()
{
    int threads = 1, cores = 1;
#ifdef _OPENMP
    threads = omp_get_max_threads();
    cores = omp_get_num_procs();
#endif
    const char* policy = std::getenv("OMP_WAIT_POLICY");
    if (threads < 2 || (policy && std::string(policy) == "passive"))
    {
        return "";
    }
    // Processes running now (/proc/loadavg's "running/total", this one
    // among them), the fewest of a few looks: this process's own threads
    // may still spin from the last parallel loop for a moment.
    int others = 1 << 30;
    for (int look = 0; look < 5; ++look)
    {
        std::ifstream is("/proc/loadavg");
        double avg[3];
        int running = 0;
        char slash;
        if (!(is >> avg[0] >> avg[1] >> avg[2] >> running >> slash))
        {
            return "";
        }
        others = std::min(others, running - 1);
        usleep(20000);
    }
    if (others <= 0 || others + threads <= cores) return "";
    std::ostringstream os;
    os << "Note: " << others << " other process" << (others > 1 ? "es" : "")
       << " running on the " << cores << " cores: with " << threads
       << " threads, which spin where they wait, this run can be several"
       << " times slower (docs/solver.md, Threads). OMP_NUM_THREADS="
       << std::max(1, cores - others) << " or OMP_WAIT_POLICY=passive"
       << " avoid it.\n";
    return os.str();
}


std::string executionTimeLine()
{
    double wall = std::chrono::duration<double>(
        std::chrono::steady_clock::now() - wallStart).count();
    double cpu = double(std::clock())/CLOCKS_PER_SEC;
    std::ostringstream os;
    os << "ExecutionTime = " << std::setprecision(6) << cpu
       << " s  ClockTime = " << std::llround(wall) << " s";
    return os.str();
}

double progressEstimate::secondsLeft(const double dTime, const double dWall,
                                     const double time, const double endTime)
{
    if (!(dTime > 0) || !(dWall >= 0) || !(endTime > time)) return -1;
    return dWall*(endTime - time)/dTime;
}

std::string progressEstimate::durationText(const double seconds)
{
    const long long s = std::llround(seconds);
    std::ostringstream os;
    if (s < 60) os << s << " s";
    else if (s < 3600) os << s/60 << " min " << s%60 << " s";
    else os << s/3600 << " h " << (s%3600)/60 << " min";
    return os.str();
}

std::string progressEstimate::line(const double time, const double endTime)
{
    const double wall = std::chrono::duration<double>(
        std::chrono::steady_clock::now() - wallStart).count();
    const double left = lastWall_ < 0 ? -1
        : secondsLeft(time - lastTime_, wall - lastWall_, time, endTime);
    lastWall_ = wall;
    lastTime_ = time;
    if (left < 0) return "";
    std::ostringstream os;
    os << "Time left = about " << durationText(left) << " to endTime "
       << endTime << "\n";
    return os.str();
}

std::vector<std::string> argList::parseWordList(
    const std::string& text, const std::string& option)
{
    std::string s = text;
    const auto first = s.find_first_not_of(" \t\n");
    const auto last = s.find_last_not_of(" \t\n");
    s = first == std::string::npos ? "" : s.substr(first, last - first + 1);
    if (!s.empty() && s.front() == '(')
    {
        if (s.back() != ')')
        {
            fatalError("Invalid " + option + " '" + text
                + "': missing ')'. Expected a list of names, e.g. "
                + option + " '(name1 name2)'");
        }
        s = s.substr(1, s.size() - 2);
    }

    std::vector<std::string> words;
    std::string word;
    auto flush = [&]()
    {
        if (!word.empty())
        {
            words.push_back(word);
            word.clear();
        }
    };
    for (char c : s)
    {
        if (c == ' ' || c == '\t' || c == '\n' || c == ',')
        {
            flush();
        }
        else if (c == '(' || c == ')' || c == '"' || c == '\''
              || c == ';' || c == '{' || c == '}')
        {
            fatalError("Invalid " + option + " '" + text + "': unexpected '"
                + std::string(1, c) + "'. Expected a list of names, e.g. "
                + option + " '(name1 name2)'");
        }
        else
        {
            word += c;
        }
    }
    flush();
    return words;
}


std::vector<std::string> argList::wordListOption(const std::string& name)
    const
{
    return parseWordList(option(name), "-" + name);
}


double argList::numberOption(const std::string& name, const double deflt)
    const
{
    if (!found(name))
    {
        return deflt;
    }
    // Blanks around the value (a quoted '0.5 ') are allowed.
    const std::string text = option(name);
    const std::size_t first = text.find_first_not_of(" \t");
    const std::size_t last = text.find_last_not_of(" \t");
    double value = 0;
    if (first == std::string::npos
     || !readNumber(text.substr(first, last - first + 1), value))
    {
        fatalError("Option -" + name + " expects a number, not '" + text
            + "'");
    }
    return value;
}


long argList::integerOption(const std::string& name, const long deflt) const
{
    const double value = numberOption(name, double(deflt));
    if (value != std::floor(value) || std::fabs(value) > 1e15)
    {
        fatalError("Option -" + name + " expects a whole number, not '"
            + option(name) + "'");
    }
    return long(value);
}

} // End namespace sphvcpm
