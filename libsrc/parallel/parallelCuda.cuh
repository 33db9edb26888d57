/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The CUDA backend's templates, for .cu files only: one __global__ launch
// template behind parallelFor, and parallelReduce. A kernel is a physics
// functor instantiated here from the .cu that names it, e.g.
//
//     // continuityCuda.cu
//     #include "parallelCuda.cuh"
//     #include "continuity.H"
//     void continuityCuda(const continuity& k, label n)
//     {
//         parallelFor(cudaExec{}, n, k);
//     }
//
// Functors are copied to the device by value as kernel arguments: they hold
// device pointers and coefficients, nothing that owns memory.
#pragma once

#include "parallelCuda.H"

#include <cuda_runtime.h>
#include <cub/block/block_reduce.cuh>

#include <type_traits>

namespace sphvcpm
{

// FatalError when a CUDA call failed; what names the call in the message.
inline void cudaCheck(const cudaError_t err, const char* what,
                      const char* file = nullptr, const int line = 0)
{
    if (err != cudaSuccess)
    {
        cudaGetLastError();
        cudaFatal(int(err), what, file, line);
    }
}

#define SPHVCPM_CUDA_CHECK(call)                                             \
    ::sphvcpm::cudaCheck((call), #call, __FILE__, __LINE__)


// * * * * * * * * * * * * * * * * parallelFor  * * * * * * * * * * * * * * //

constexpr int launchBlockSize = 256;

// Blocks of 256 threads per SM the launch template asks the compiler to
// fit: a cap of 65536/(256 n) registers per thread. The gathered rates
// (the main kernel) take 128 registers uncapped, a quarter of the SM's
// threads; with 3 blocks (80 registers, a little spilled) they hide more
// latency: the 1.0 M-particle dam break on the H100 ran at 232, 254 and
// 196 M particle-steps/s with 2, 3 and 4 (docs/benchmarks.md).
#ifndef SPHVCPM_CUDA_MIN_BLOCKS
#define SPHVCPM_CUDA_MIN_BLOCKS 3
#endif

// The launch template: one thread per index. The index is formed in 64 bits
// so that n near 2^31 does not overflow.
template<class F>
__global__ void __launch_bounds__(launchBlockSize, SPHVCPM_CUDA_MIN_BLOCKS)
launchKernel(const F f, const label n)
{
    const long long i =
        static_cast<long long>(blockIdx.x)*blockDim.x + threadIdx.x;
    if (i < n)
    {
        f(static_cast<label>(i));
    }
}


// Queued on the default stream; returns at once. A bad launch is reported
// here, a kernel that fails while running at the next synchronising call
// (copies, cudaSynchronize()).
template<class F>
inline void parallelFor(cudaExec, const label n, const F& f)
{
    static_assert
    (
        std::is_trivially_copyable<F>::value,
        "CUDA functors are copied to the device: make them trivially copyable"
    );
    if (n <= 0)
    {
        return;
    }
    const unsigned nBlocks = unsigned((n - 1)/launchBlockSize + 1);
    launchKernel<<<nBlocks, launchBlockSize>>>(f, n);
    cudaCheck(cudaGetLastError(), "parallelFor (kernel launch)");
}


// * * * * * * * * * * * * * * * * parallelReduce * * * * * * * * * * * * * //

namespace detail
{

// A partial result that may be empty, so the operator needs no identity.
template<class T>
struct reducePartial
{
    T value;
    int valid;
};

template<class T, class Op>
struct combinePartial
{
    Op op;

    __device__ reducePartial<T> operator()
    (
        const reducePartial<T>& a,
        const reducePartial<T>& b
    ) const
    {
        if (!a.valid)
        {
            return b;
        }
        if (!b.valid)
        {
            return a;
        }
        return {op(a.value, b.value), 1};
    }
};

// The grid is fixed by n alone (not by the GPU), so a sum is the same to
// the last bit on every run and every card; it differs from the CPU's
// association, so compare CPU and GPU sums with a tolerance.
constexpr int reduceThreads = 256;
constexpr int reduceMaxBlocks = 1024;

template<class T, class Op>
__device__ reducePartial<T> blockCombine
(
    const reducePartial<T>& acc,
    const Op& op
)
{
    using blockReduce = cub::BlockReduce<reducePartial<T>, reduceThreads>;
    __shared__ typename blockReduce::TempStorage temp;
    return blockReduce(temp).Reduce(acc, combinePartial<T, Op>{op});
}

// Pass 1: each thread folds a strided set of indices, each block its threads.
template<class T, class F, class Op>
__global__ void __launch_bounds__(reduceThreads)
reduceKernel(const F f, const Op op, const label n, reducePartial<T>* partial)
{
    reducePartial<T> acc{T(), 0};
    const long long stride = static_cast<long long>(gridDim.x)*blockDim.x;
    for
    (
        long long i = static_cast<long long>(blockIdx.x)*blockDim.x
          + threadIdx.x;
        i < n;
        i += stride
    )
    {
        const T v = f(static_cast<label>(i));
        acc.value = acc.valid ? op(acc.value, v) : v;
        acc.valid = 1;
    }
    const reducePartial<T> r = blockCombine<T>(acc, op);
    if (threadIdx.x == 0)
    {
        partial[blockIdx.x] = r;
    }
}

// Pass 2: one block folds the block results and applies init.
template<class T, class Op>
__global__ void __launch_bounds__(reduceThreads)
reduceFinal
(
    const Op op,
    const T init,
    const reducePartial<T>* partial,
    const int nPartial,
    T* result
)
{
    reducePartial<T> acc{T(), 0};
    for (int b = threadIdx.x; b < nPartial; b += blockDim.x)
    {
        acc = combinePartial<T, Op>{op}(acc, partial[b]);
    }
    const reducePartial<T> r = blockCombine<T>(acc, op);
    if (threadIdx.x == 0)
    {
        *result = r.valid ? op(init, r.value) : init;
    }
}

} // End namespace detail


// op(init, f(0) op ... op f(n-1)); waits for the result.
template<class T, class F, class Op>
inline T parallelReduce(cudaExec, const label n, const F& f, const T init,
                        const Op& op)
{
    static_assert
    (
        std::is_trivially_copyable<F>::value
     && std::is_trivially_copyable<T>::value,
        "CUDA reductions copy functor and value: make them trivially copyable"
    );
    if (n <= 0)
    {
        return init;
    }
    using partialType = detail::reducePartial<T>;

    const label nWanted = (n - 1)/detail::reduceThreads + 1;
    const int nBlocks =
        nWanted < detail::reduceMaxBlocks ? nWanted : detail::reduceMaxBlocks;

    // Block results, then the result, in the scratch slot of the reductions.
    const std::size_t resultOffset =
        ((nBlocks*sizeof(partialType) + 255)/256)*256;
    char* scratch = static_cast<char*>
    (
        cudaScratch(0, resultOffset + sizeof(T))
    );
    partialType* partial = reinterpret_cast<partialType*>(scratch);
    T* result = reinterpret_cast<T*>(scratch + resultOffset);

    detail::reduceKernel<T><<<nBlocks, detail::reduceThreads>>>
    (
        f, op, n, partial
    );
    cudaCheck(cudaGetLastError(), "parallelReduce (kernel launch)");
    detail::reduceFinal<T><<<1, detail::reduceThreads>>>
    (
        op, init, partial, nBlocks, result
    );
    cudaCheck(cudaGetLastError(), "parallelReduce (final kernel launch)");

    T value;
    copyDeviceToHost(&value, result, sizeof(T));
    return value;
}

} // End namespace sphvcpm
