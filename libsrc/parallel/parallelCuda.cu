/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Scan and sort on the GPU through CUB, and the scratch memory they share.
// Only one radix sort is instantiated (uint32 keys): signed keys are sorted
// as unsigned, which keeps this file quick to compile for several targets.
#include "parallelCuda.cuh"

#include <cub/device/device_radix_sort.cuh>
#include <cub/device/device_scan.cuh>

#include <array>
#include <cstdint>
#include <limits>
#include <string>

namespace sphvcpm
{

// * * * * * * * * * * * * * * * * Scratch memory * * * * * * * * * * * * * //

static const int nScratch = 4;

// Raw bytes rather than deviceBuffer<char>: sizes past 2 GiB are allowed.
struct scratchSlot
{
    void* ptr = nullptr;
    std::size_t bytes = 0;

    ~scratchSlot()
    {
        deviceFree(ptr);
    }
};

static std::array<scratchSlot, nScratch>& scratchSlots()
{
    static std::array<scratchSlot, nScratch> slots;
    return slots;
}


void* cudaScratch(const int slot, const std::size_t bytes)
{
    if (slot < 0 || slot >= nScratch)
    {
        fatalError("cudaScratch: no slot " + std::to_string(slot));
    }
    scratchSlot& s = scratchSlots()[slot];
    if (s.bytes < bytes)
    {
        // Grow by half again so that slowly growing sizes settle quickly.
        deviceFree(s.ptr);
        s.ptr = nullptr;
        s.bytes = 0;
        std::size_t grown = bytes + bytes/2;
        try
        {
            s.ptr = deviceAllocate(grown);
        }
        catch (const FatalError&)
        {
            // Near the memory limit: no slack then.
            grown = bytes;
            s.ptr = deviceAllocate(grown);
        }
        s.bytes = grown;
    }
    return s.ptr;
}


void cudaReleaseScratch()
{
    for (scratchSlot& s : scratchSlots())
    {
        deviceFree(s.ptr);
        s.ptr = nullptr;
        s.bytes = 0;
    }
}


// * * * * * * * * * * * * * * * * Functors * * * * * * * * * * * * * * * * //

namespace
{

struct widen
{
    const label* in;

    __device__ long long operator()(const label i) const
    {
        return in[i];
    }
};

template<class K>
struct readKey
{
    const K* keys;

    __device__ K operator()(const label i) const
    {
        return keys[i];
    }
};

struct flipSignBit
{
    std::uint32_t* keys;

    __device__ void operator()(const label i) const
    {
        keys[i] ^= 0x80000000u;
    }
};


// Bits needed to hold key: 0 for key 0.
int significantBits(std::uint32_t key)
{
    int bits = 0;
    while (key)
    {
        ++bits;
        key >>= 1;
    }
    return bits;
}


void radixSort
(
    std::uint32_t* keys,
    label* values,
    const label n,
    const int endBit
)
{
    cub::DoubleBuffer<std::uint32_t> k
    (
        keys,
        static_cast<std::uint32_t*>(cudaScratch(1, n*sizeof(std::uint32_t)))
    );
    cub::DoubleBuffer<label> v
    (
        values,
        static_cast<label*>(cudaScratch(2, n*sizeof(label)))
    );

    std::size_t tempBytes = 0;
    SPHVCPM_CUDA_CHECK
    (
        cub::DeviceRadixSort::SortPairs
        (
            nullptr, tempBytes, k, v, n, 0, endBit
        )
    );
    void* temp = cudaScratch(3, tempBytes);
    SPHVCPM_CUDA_CHECK
    (
        cub::DeviceRadixSort::SortPairs
        (
            temp, tempBytes, k, v, n, 0, endBit
        )
    );

    // CUB leaves the result in whichever half it finished in.
    if (k.Current() != keys)
    {
        SPHVCPM_CUDA_CHECK
        (
            cudaMemcpyAsync
            (
                keys, k.Current(), n*sizeof(std::uint32_t),
                cudaMemcpyDeviceToDevice
            )
        );
    }
    if (v.Current() != values)
    {
        SPHVCPM_CUDA_CHECK
        (
            cudaMemcpyAsync
            (
                values, v.Current(), n*sizeof(label),
                cudaMemcpyDeviceToDevice
            )
        );
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * exclusiveScan  * * * * * * * * * * * * * //

label exclusiveScan(cudaExec, const label* in, label* out, const label n)
{
    if (n <= 0)
    {
        return 0;
    }

    // The total in 64 bits first: a wrapped scan cannot tell its overflow.
    const long long total =
        parallelReduce(cudaExec{}, n, widen{in}, 0LL, sumOp());
    if
    (
        total > std::numeric_limits<label>::max()
     || total < std::numeric_limits<label>::min()
    )
    {
        fatalError
        (
            "exclusiveScan (cuda): the total " + std::to_string(total)
          + " does not fit a 32-bit label"
        );
    }

    std::size_t tempBytes = 0;
    SPHVCPM_CUDA_CHECK
    (
        cub::DeviceScan::ExclusiveSum(nullptr, tempBytes, in, out, n)
    );
    void* temp = cudaScratch(3, tempBytes);
    SPHVCPM_CUDA_CHECK
    (
        cub::DeviceScan::ExclusiveSum(temp, tempBytes, in, out, n)
    );
    SPHVCPM_CUDA_CHECK(cudaGetLastError());
    return label(total);
}


// * * * * * * * * * * * * * * * * * sortByKey  * * * * * * * * * * * * * * //

void sortByKey(cudaExec, std::uint32_t* keys, label* values, const label n)
{
    if (n < 2)
    {
        return;
    }
    const std::uint32_t maxKey = parallelReduce
    (
        cudaExec{}, n, readKey<std::uint32_t>{keys}, 0u, maxOp()
    );
    const int endBit = significantBits(maxKey);
    if (endBit > 0)
    {
        radixSort(keys, values, n, endBit);
    }
}


void sortByKey(cudaExec, label* keys, label* values, const label n)
{
    if (n < 2)
    {
        return;
    }
    std::uint32_t* ukeys = reinterpret_cast<std::uint32_t*>(keys);

    const label minKey = parallelReduce
    (
        cudaExec{}, n, readKey<label>{keys},
        std::numeric_limits<label>::max(), minOp()
    );
    if (minKey >= 0)
    {
        // Non-negative labels order as their unsigned bit patterns.
        sortByKey(cudaExec{}, ukeys, values, n);
        return;
    }
    parallelFor(cudaExec{}, n, flipSignBit{ukeys});
    radixSort(ukeys, values, n, 32);
    parallelFor(cudaExec{}, n, flipSignBit{ukeys});
}

} // End namespace sphvcpm
