#include "error.H"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <new>
#include <set>
#include <sstream>

namespace sphvcpm
{

static std::string composeReport(const std::string& message,
                                 const std::string& file, int line)
{
    // A NUL from a damaged file would cut the report short where it is
    // printed as a C string: shown as \0 instead.
    std::string text;
    for (const char c : message)
    {
        text += c == '\0' ? std::string("\\0") : std::string(1, c);
    }
    std::ostringstream os;
    if (file.empty())
    {
        os << "\n--> SPHVCPM FATAL ERROR:\n" << text << "\n";
    }
    else
    {
        os << "\n--> SPHVCPM FATAL IO ERROR:\n" << text << "\n\nfile: "
           << file;
        if (line > 0)
        {
            os << " at line " << line;
        }
        os << ".\n";
    }
    return os.str();
}

FatalError::FatalError(const std::string& message, const std::string& file,
                       int line, const std::string& keyword)
:
    std::runtime_error(composeReport(message, file, line)),
    message_(message),
    file_(file),
    line_(line),
    keyword_(keyword)
{}

std::string FatalError::report() const
{
    return what();
}

void fatalError(const std::string& message)
{
    throw FatalError(message);
}

void fatalIOError(const std::string& file, int line,
                  const std::string& message, const std::string& keyword)
{
    throw FatalError(message, file.empty() ? "<unknown>" : file, line,
                     keyword);
}

namespace
{
std::atomic<bool> warnOnce{false};
std::atomic<int> quietDepth{0};
std::mutex warnedMutex;
std::set<std::string> warned;
}

quietWarnings::quietWarnings()
{
    ++quietDepth;
}

quietWarnings::~quietWarnings()
{
    --quietDepth;
}

void warnOnlyOnce(const bool once)
{
    const std::lock_guard<std::mutex> lock(warnedMutex);
    warned.clear();
    warnOnce = once;
}

void warning(const std::string& message, const std::string& file, int line)
{
    if (quietDepth > 0)
    {
        return;
    }
    if (warnOnce)
    {
        const std::lock_guard<std::mutex> lock(warnedMutex);
        if (!warned.insert(file + ":" + std::to_string(line) + ":"
                           + message).second)
        {
            return;
        }
    }
    // What was logged before comes first in a log of both streams.
    std::cout.flush();
    std::cerr << "\n--> SPHVCPM Warning :\n" << message << "\n";
    if (!file.empty())
    {
        std::cerr << "file: " << file;
        if (line > 0)
        {
            std::cerr << " at line " << line;
        }
        std::cerr << ".\n";
    }
    std::cerr << std::endl;
}

int runGuarded(const std::function<int()>& body)
{
    // Past a file-size limit (ulimit -f) a write then fails with EFBIG,
    // which the writers report naming the file, instead of the signal
    // killing the process without a word.
    std::signal(SIGXFSZ, SIG_IGN);
    try
    {
        const int status = body();
        // A log that lost lines (a full disk under a redirected standard
        // output) is no clean end, though the time directories stand.
        errno = 0;
        std::cout.flush();
        if (!std::cout)
        {
            std::cerr << "\n--> SPHVCPM FATAL ERROR:\nThe log (standard"
                " output) could not be written in full"
                << (errno ? std::string(": ") + std::strerror(errno) : "")
                << ". What the run wrote to its time directories and"
                   " tables stands; the log lacks lines\n\nSPHVCPM exiting\n"
                << std::endl;
            return 1;
        }
        return status;
    }
    catch (const FatalError& err)
    {
        std::cout.flush();
        std::cerr << err.report() << "\nSPHVCPM exiting\n" << std::endl;
    }
    catch (const std::bad_alloc&)
    {
        std::cout.flush();
        std::cerr << "\n--> SPHVCPM FATAL ERROR:\nOut of memory: the case"
                     " needs more memory than this machine gives (fewer"
                     " particles, a coarser dp or a smaller domain need"
                     " less)\n\nSPHVCPM exiting\n" << std::endl;
    }
    catch (const std::exception& err)
    {
        std::cout.flush();
        std::cerr << "\n--> SPHVCPM FATAL ERROR:\n" << err.what()
                  << "\n\nSPHVCPM exiting\n" << std::endl;
    }
    return 1;
}

std::string fileProblem(const std::string& path)
{
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (std::filesystem::is_regular_file(status)) return "";
    if (!std::filesystem::exists(status)) return "does not exist";
    if (std::filesystem::is_directory(status))
    {
        return "is a directory, not a file";
    }
    return "is not a regular file";
}


} // End namespace sphvcpm
