/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "hostMemory.H"

#include <algorithm>
#include <fstream>
#include <string>

namespace sphvcpm
{

namespace
{

// A cgroup v2 file's number; none for "max" or where it cannot be read.
std::optional<std::uint64_t> cgroupValue(const char* file)
{
    std::ifstream is(file);
    std::uint64_t v = 0;
    if (is >> v) return v;
    return std::nullopt;
}

} // End anonymous namespace


std::optional<std::uint64_t> availableMemoryBytes()
{
    std::optional<std::uint64_t> available;
    std::ifstream is("/proc/meminfo");
    std::string key, unit;
    std::uint64_t kB = 0;
    while (is >> key >> kB)
    {
        std::getline(is, unit);
        if (key == "MemAvailable:")
        {
            available = kB*1024;
            break;
        }
    }
    // In a container the cgroup's limit may be below the host's memory.
    const auto limit = cgroupValue("/sys/fs/cgroup/memory.max");
    const auto used = cgroupValue("/sys/fs/cgroup/memory.current");
    if (limit && used)
    {
        const std::uint64_t left = *limit > *used ? *limit - *used : 0;
        available = available ? std::min(*available, left) : left;
    }
    return available;
}

} // End namespace sphvcpm
