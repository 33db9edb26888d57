/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Compiled by the host compiler; the CUDA runtime API is plain C, so nvcc is
// not needed here. SPHVCPM_WITH_CUDART is set by CMake when nvcc was found.
#include "cudaDevice.H"

#include "error.H"

#include <cstdio>
#include <sstream>

#ifdef SPHVCPM_WITH_CUDART
#include <cuda_runtime_api.h>
#endif

namespace sphvcpm
{

std::string gpuInfo::describe() const
{
    if (!available)
    {
        return "none (" + reason + ")";
    }
    char mem[32];
    std::snprintf(mem, sizeof(mem), "%.1f GiB",
                  double(totalMemory)/(1024.0*1024.0*1024.0));
    std::ostringstream os;
    os  << name << " (device " << device << " of " << deviceCount << ", "
        << mem << ", sm_" << major << minor << ", " << multiProcessors
        << " SMs)";
    return os.str();
}


bool gpuAvailable()
{
    static const bool available = cudaDeviceInfo(0).available;
    return available;
}


#ifdef SPHVCPM_WITH_CUDART

static std::string mebibytes(const std::size_t bytes)
{
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.1f MiB", double(bytes)/1048576.0);
    return buf;
}


bool cudaBackendBuilt()
{
    return true;
}


void cudaFatal(const int code, const std::string& what, const char* file,
               const int line)
{
    const cudaError_t err = cudaError_t(code);
    std::ostringstream os;
    os  << "CUDA error in " << what << ": " << cudaGetErrorString(err)
        << " (" << cudaGetErrorName(err) << ", code " << code << ")";
    if (file)
    {
        os  << "\n    at " << file << ':' << line;
    }
    fatalError(os.str());
}


gpuInfo cudaDeviceInfo(const int device)
{
    gpuInfo info;
    info.device = device;

    int count = 0;
    cudaError_t err = cudaGetDeviceCount(&count);
    if (err != cudaSuccess)
    {
        // No driver or no device: not sticky, but clear it all the same.
        cudaGetLastError();
        int driver = 0;
        if (cudaDriverGetVersion(&driver) == cudaSuccess && driver == 0)
        {
            info.reason = "no NVIDIA driver installed";
        }
        else
        {
            info.reason = std::string(cudaGetErrorString(err))
              + " (" + cudaGetErrorName(err) + ")";
        }
        cudaGetLastError();
        return info;
    }
    info.deviceCount = count;
    if (device < 0 || device >= count)
    {
        info.reason = "no CUDA device " + std::to_string(device) + " ("
          + std::to_string(count) + " found)";
        return info;
    }

    cudaDeviceProp prop;
    err = cudaGetDeviceProperties(&prop, device);
    if (err != cudaSuccess)
    {
        cudaGetLastError();
        info.reason = cudaGetErrorString(err);
        return info;
    }
    info.name = prop.name;
    info.totalMemory = prop.totalGlobalMem;
    info.major = prop.major;
    info.minor = prop.minor;
    info.multiProcessors = prop.multiProcessorCount;

    // Only the current device can be asked for free memory.
    int current = 0;
    if (cudaGetDevice(&current) == cudaSuccess && current == device)
    {
        std::size_t freeBytes = 0, totalBytes = 0;
        if (cudaMemGetInfo(&freeBytes, &totalBytes) == cudaSuccess)
        {
            info.freeMemory = freeBytes;
        }
        else
        {
            cudaGetLastError();
        }
    }
    info.available = true;
    return info;
}


void* deviceAllocate(const std::size_t bytes)
{
    if (bytes == 0)
    {
        return nullptr;
    }
    void* ptr = nullptr;
    const cudaError_t err = cudaMalloc(&ptr, bytes);
    if (err != cudaSuccess)
    {
        cudaGetLastError();
        std::string what = "cudaMalloc of " + mebibytes(bytes);
        std::size_t freeBytes = 0, totalBytes = 0;
        if (cudaMemGetInfo(&freeBytes, &totalBytes) == cudaSuccess)
        {
            what += " (" + mebibytes(freeBytes) + " free of "
              + mebibytes(totalBytes) + ")";
        }
        cudaGetLastError();
        cudaFatal(err, what);
    }
    return ptr;
}


void deviceFree(void* ptr) noexcept
{
    if (ptr)
    {
        cudaFree(ptr);
        cudaGetLastError();
    }
}


static void checkCopy(const cudaError_t err, const char* what,
                      const std::size_t bytes)
{
    if (err != cudaSuccess)
    {
        cudaFatal(err, std::string(what) + " of " + mebibytes(bytes));
    }
}


void copyHostToDevice(void* dst, const void* src, const std::size_t bytes)
{
    if (bytes)
    {
        checkCopy(cudaMemcpy(dst, src, bytes, cudaMemcpyHostToDevice),
                  "cudaMemcpy host to device", bytes);
    }
}


void copyDeviceToHost(void* dst, const void* src, const std::size_t bytes)
{
    if (bytes)
    {
        checkCopy(cudaMemcpy(dst, src, bytes, cudaMemcpyDeviceToHost),
                  "cudaMemcpy device to host", bytes);
    }
}


void copyDeviceToDevice(void* dst, const void* src, const std::size_t bytes)
{
    if (bytes)
    {
        checkCopy(cudaMemcpy(dst, src, bytes, cudaMemcpyDeviceToDevice),
                  "cudaMemcpy device to device", bytes);
    }
}


void deviceMemset(void* ptr, const int value, const std::size_t bytes)
{
    if (bytes)
    {
        checkCopy(cudaMemset(ptr, value, bytes), "cudaMemset", bytes);
    }
}


void cudaSynchronize(const char* what)
{
    // Without a GPU nothing can have been queued.
    if (!gpuAvailable())
    {
        return;
    }
    const cudaError_t err = cudaDeviceSynchronize();
    if (err != cudaSuccess)
    {
        cudaFatal(err, what);
    }
}


#else // No CUDA in this build: answer the questions, refuse the memory.

// Why, as configured (CMakeLists.txt).
static const char* const noCuda =
#ifdef SPHVCPM_CUDA_OFF
    "this build has no CUDA backend: it was configured without it"
    " (Allwmake -no-cuda, or -DSPHVCPM_CUDA=OFF); run ./Allwmake without"
    " -no-cuda to build it";
#else
    "this build has no CUDA backend: nvcc was not found when it was"
    " configured (Allwmake looks on the PATH and in /usr/local/cuda/bin)";
#endif

bool cudaBackendBuilt()
{
    return false;
}


void cudaFatal(const int code, const std::string& what, const char* file,
               const int line)
{
    std::ostringstream os;
    os  << "CUDA error in " << what << ": code " << code;
    if (file)
    {
        os  << "\n    at " << file << ':' << line;
    }
    fatalError(os.str());
}


gpuInfo cudaDeviceInfo(const int device)
{
    gpuInfo info;
    info.device = device;
    info.reason = noCuda;
    return info;
}


void* deviceAllocate(const std::size_t bytes)
{
    if (bytes)
    {
        fatalError(std::string("cannot allocate device memory: ") + noCuda);
    }
    return nullptr;
}


void deviceFree(void*) noexcept
{}


static void refuse(const std::size_t bytes)
{
    if (bytes)
    {
        fatalError(std::string("cannot copy device memory: ") + noCuda);
    }
}


void copyHostToDevice(void*, const void*, const std::size_t bytes)
{
    refuse(bytes);
}


void copyDeviceToHost(void*, const void*, const std::size_t bytes)
{
    refuse(bytes);
}


void copyDeviceToDevice(void*, const void*, const std::size_t bytes)
{
    refuse(bytes);
}


void deviceMemset(void*, int, const std::size_t bytes)
{
    refuse(bytes);
}


void cudaSynchronize(const char*)
{}

#endif

} // End namespace sphvcpm
