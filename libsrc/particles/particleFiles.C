/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// POSIX file helpers of the particle I/O (see particleFiles.H).

#include "particleFiles.H"
#include "error.H"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace sphvcpm
{
namespace particleFiles
{

namespace
{

// Big enough that a field of millions of particles needs few syscalls.
constexpr std::size_t bufferSize = std::size_t(1) << 22;

std::string errnoText()
{
    return std::strerror(errno);
}

} // End anonymous namespace


std::string readFile(const std::filesystem::path& file)
{
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
    {
        fatalIOError(file.string(), 0, "Cannot open \"" + file.string()
            + "\" for reading: " + errnoText());
    }
    struct stat st;
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))
    {
        ::close(fd);
        fatalIOError(file.string(), 0, "\"" + file.string()
            + "\" is not a regular file");
    }
    std::string content(std::size_t(st.st_size), '\0');
    std::size_t done = 0;
    while (done < content.size())
    {
        const ssize_t n = ::read(fd, content.data() + done,
                                 content.size() - done);
        if (n < 0 && errno == EINTR)
        {
            continue;
        }
        if (n < 0)
        {
            const std::string why = errnoText();
            ::close(fd);
            fatalIOError(file.string(), 0, "Error reading \"" + file.string()
                + "\": " + why);
        }
        if (n == 0)
        {
            // Shrunk while we read it: keep what is there.
            content.resize(done);
            break;
        }
        done += std::size_t(n);
    }
    ::close(fd);
    return content;
}


void syncPath(const std::filesystem::path& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
    {
        fatalIOError(path.string(), 0, "Cannot open \"" + path.string()
            + "\" to sync it: " + errnoText());
    }
    if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS)
    {
        const std::string why = errnoText();
        ::close(fd);
        fatalIOError(path.string(), 0, "Cannot sync \"" + path.string()
            + "\" to disk: " + why);
    }
    ::close(fd);
}


// * * * * * * * * * * * * * * * * outputFile  * * * * * * * * * * * * * * //

outputFile::outputFile(std::filesystem::path file)
:
    file_(std::move(file))
{
    fd_ = ::open(file_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC,
                 0644);
    if (fd_ < 0)
    {
        fail("Cannot open \"" + file_.string() + "\" for writing");
    }
    buffer_.reserve(bufferSize);
}


outputFile::~outputFile()
{
    if (fd_ >= 0)
    {
        ::close(fd_);
    }
}


void outputFile::fail(const std::string& what) const
{
    fatalIOError(file_.string(), 0, what + ": " + errnoText());
}


void outputFile::writeAll(const char* data, std::size_t n)
{
    std::size_t done = 0;
    while (done < n)
    {
        const ssize_t k = ::write(fd_, data + done, n - done);
        if (k < 0 && errno == EINTR)
        {
            continue;
        }
        if (k < 0)
        {
            fail("Error writing \"" + file_.string() + "\"");
        }
        done += std::size_t(k);
    }
}


void outputFile::flush()
{
    writeAll(buffer_.data(), buffer_.size());
    buffer_.clear();
}


void outputFile::write(const char* data, std::size_t n)
{
    if (buffer_.size() + n > bufferSize)
    {
        flush();
    }
    if (n >= bufferSize)
    {
        // Large blocks (binary fields) go straight to the file.
        writeAll(data, n);
        return;
    }
    buffer_.append(data, n);
}


void outputFile::close(bool sync)
{
    flush();
    if (sync && ::fsync(fd_) != 0 && errno != EINVAL && errno != EROFS)
    {
        fail("Cannot sync \"" + file_.string() + "\" to disk");
    }
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0)
    {
        fail("Error closing \"" + file_.string() + "\"");
    }
}

} // End namespace particleFiles
} // End namespace sphvcpm
