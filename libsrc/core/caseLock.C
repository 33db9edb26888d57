/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "caseLock.H"
#include "error.H"

#include <cerrno>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace sphvcpm
{

caseLock::caseLock(const std::filesystem::path& caseDir)
{
    const std::filesystem::path file = caseDir/".sphVcpmFsi.lock";
    fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) return;
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0)
    {
        const bool held = errno == EWOULDBLOCK;
        char text[32] = {};
        const ssize_t n = ::pread(fd_, text, sizeof(text) - 1, 0);
        ::close(fd_);
        fd_ = -1;
        if (!held) return;     // a file system without locks
        std::string pid = n > 0 ? std::string(text, std::size_t(n)) : "";
        while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' '))
        {
            pid.pop_back();
        }
        fatalError("Another sphVcpmFsi" + (pid.empty() ? "" : " (process "
            + pid + ")") + " is running in case " + caseDir.string()
            + ": two runs would write the same time directories and tables."
              " Wait for it to end, or stop it (kill -TERM " + (pid.empty()
            ? "<pid>" : pid) + ", or stopAt writeNow in system/controlDict);"
              " -postProcess may run beside it");
    }
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd_, 0) == 0)
    {
        [[maybe_unused]] const ssize_t w =
            ::pwrite(fd_, pid.data(), pid.size(), 0);
    }
}


caseLock::~caseLock()
{
    if (fd_ >= 0) ::close(fd_);   // releases the lock
}

} // End namespace sphvcpm
