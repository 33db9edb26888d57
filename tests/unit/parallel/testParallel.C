/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Host loop primitives against plain loops: serial and OpenMP, sizes from 0
// to a million, equality of the two backends for any thread count, sort
// stability, scan overflow, and the GPU queries on a machine without one.

#include "cudaDevice.H"
#include "deviceBuffer.H"
#include "error.H"
#include "parallel.H"
#include "testRandomData.H"
#include "../testPrecision.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <iostream>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace sphvcpm;

namespace
{

const std::vector<label> sizes =
    {0, 1, 2, 3, 7, 255, 4095, 4096, 4097, 33333, 65537, 1000000, 1000003};

using test::randomIntegers;
using test::randomScalars;

// Sets the OpenMP thread count for a scope.
class threadCount
{
    int saved_;
public:
    explicit threadCount(const int n)
    :
        saved_(openmpThreads())
    {
#ifdef _OPENMP
        omp_set_num_threads(n);
#else
        (void)n;
#endif
    }
    ~threadCount()
    {
#ifdef _OPENMP
        omp_set_num_threads(saved_);
#endif
    }
};

const std::vector<int> threadCounts = {1, 2, 3, 4};


// Functors as physics writes them: raw pointers, const operator().

struct affine
{
    const scalar* x;
    scalar* y;

    SPHVCPM_HD void operator()(const label i) const
    {
        y[i] = 0.5*x[i] + scalar(i);
    }
};

template<class T>
struct readValue
{
    const T* v;

    SPHVCPM_HD T operator()(const label i) const
    {
        return v[i];
    }
};

struct toVector
{
    const scalar* v;
    label n;

    SPHVCPM_HD vec3 operator()(const label i) const
    {
        return {v[i], v[n - 1 - i], 1.0};
    }
};

// Plain index-order fold: the reference.
template<class T, class F, class Op>
T referenceReduce(const label n, const F& f, T init, const Op& op)
{
    for (label i = 0; i < n; ++i)
    {
        init = op(init, T(f(i)));
    }
    return init;
}

template<class K>
void referenceSort(std::vector<K>& keys, std::vector<label>& values)
{
    std::vector<label> order(keys.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort
    (
        order.begin(), order.end(),
        [&](label a, label b) { return keys[a] < keys[b]; }
    );
    std::vector<K> k(keys.size());
    std::vector<label> v(keys.size());
    for (std::size_t i = 0; i < order.size(); ++i)
    {
        k[i] = keys[order[i]];
        v[i] = values[order[i]];
    }
    keys.swap(k);
    values.swap(v);
}

bool bitwiseEqual(const scalar a, const scalar b)
{
    return std::memcmp(&a, &b, sizeof(scalar)) == 0;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * parallelFor  * * * * * * * * * * * * * * //

TEST(parallelFor, matchesLoop)
{
    for (const label n : sizes)
    {
        const std::vector<scalar> x = randomScalars(n, 1);
        std::vector<scalar> ref(n), ys(n, -1), yo(n, -1);
        for (label i = 0; i < n; ++i)
        {
            ref[i] = 0.5*x[i] + scalar(i);
        }
        parallelFor(serialExec{}, n, affine{x.data(), ys.data()});
        EXPECT_EQ(ys, ref) << "serial, n = " << n;
        for (const int nt : threadCounts)
        {
            threadCount t(nt);
            std::fill(yo.begin(), yo.end(), -1);
            parallelFor(openmpExec{}, n, affine{x.data(), yo.data()});
            EXPECT_EQ(yo, ref) << "openmp, " << nt << " threads, n = " << n;
        }
    }
}


TEST(parallelFor, negativeCountDoesNothing)
{
    scalar y = 7;
    parallelFor(serialExec{}, -3, affine{nullptr, &y});
    parallelFor(openmpExec{}, -3, affine{nullptr, &y});
    EXPECT_EQ(y, 7);
}


// * * * * * * * * * * * * * * * * parallelReduce * * * * * * * * * * * * * //

TEST(parallelReduce, scalarSumMinMax)
{
    for (const label n : sizes)
    {
        const std::vector<scalar> v = randomScalars(n, 2);
        const readValue<scalar> f{v.data()};

        scalar absSum = 0;
        for (const scalar x : v)
        {
            absSum += std::abs(x);
        }

        const scalar ref = referenceReduce(n, f, 0.25, sumOp());
        const scalar s = parallelReduce(serialExec{}, n, f, 0.25, sumOp());
        EXPECT_NEAR(s, ref, 1e-14*absSum + 1e-300) << "n = " << n;

        const scalar big = std::numeric_limits<scalar>::max();
        const scalar refMin = referenceReduce(n, f, big, minOp());
        const scalar refMax = referenceReduce(n, f, -big, maxOp());
        EXPECT_EQ(parallelReduce(serialExec{}, n, f, big, minOp()), refMin);
        EXPECT_EQ(parallelReduce(serialExec{}, n, f, -big, maxOp()), refMax);

        // The blocked fold makes OpenMP equal serial to the last bit.
        for (const int nt : threadCounts)
        {
            threadCount t(nt);
            const scalar so =
                parallelReduce(openmpExec{}, n, f, 0.25, sumOp());
            EXPECT_TRUE(bitwiseEqual(so, s))
                << nt << " threads, n = " << n << ": " << so << " vs " << s;
            EXPECT_EQ(parallelReduce(openmpExec{}, n, f, big, minOp()), refMin);
            EXPECT_EQ(parallelReduce(openmpExec{}, n, f, -big, maxOp()), refMax);
        }
    }
}


TEST(parallelReduce, emptyGivesInit)
{
    const readValue<scalar> f{nullptr};
    EXPECT_EQ(parallelReduce(serialExec{}, 0, f, 3.5, sumOp()), 3.5);
    EXPECT_EQ(parallelReduce(openmpExec{}, 0, f, 3.5, minOp()), 3.5);
    EXPECT_EQ(parallelReduce(openmpExec{}, -1, f, -2.0, maxOp()), -2.0);
}


TEST(parallelReduce, labelsAreExact)
{
    for (const label n : sizes)
    {
        const std::vector<label> v = randomIntegers<label>(n, -1000, 1000, 3);
        const readValue<label> f{v.data()};
        const label ref = referenceReduce(n, f, label(5), sumOp());
        EXPECT_EQ(parallelReduce(serialExec{}, n, f, label(5), sumOp()), ref);
        EXPECT_EQ(parallelReduce(openmpExec{}, n, f, label(5), sumOp()), ref);
        const label lo = referenceReduce(n, f, label(2000), minOp());
        EXPECT_EQ(parallelReduce(openmpExec{}, n, f, label(2000), minOp()), lo);
    }
}


TEST(parallelReduce, vectorSum)
{
    const label n = 100001;
    const std::vector<scalar> v = randomScalars(n, 4);
    const toVector f{v.data(), n};
    const vec3 zero{0, 0, 0};
    const vec3 ref = referenceReduce(n, f, zero, sumOp());
    const vec3 s = parallelReduce(serialExec{}, n, f, zero, sumOp());
    const vec3 o = parallelReduce(openmpExec{}, n, f, zero, sumOp());
    // Sums of 1e5 values of order 1 in another order: float keeps about
    // 7 digits of the partial sums.
    EXPECT_NEAR(s.x, ref.x, test::tol(1e-9, 1e-3));
    EXPECT_NEAR(s.y, ref.y, test::tol(1e-9, 1e-3));
    EXPECT_EQ(s.z, scalar(n));
    EXPECT_EQ(o, s);
}


// * * * * * * * * * * * * * * * * exclusiveScan  * * * * * * * * * * * * * //

TEST(exclusiveScan, matchesLoop)
{
    for (const label n : sizes)
    {
        const std::vector<label> in = randomIntegers<label>(n, 0, 40, 5);
        std::vector<label> ref(n);
        label total = 0;
        for (label i = 0; i < n; ++i)
        {
            ref[i] = total;
            total += in[i];
        }

        std::vector<label> out(n, -1);
        EXPECT_EQ(exclusiveScan(serialExec{}, in.data(), out.data(), n), total);
        EXPECT_EQ(out, ref) << "serial, n = " << n;

        for (const int nt : threadCounts)
        {
            threadCount t(nt);
            std::fill(out.begin(), out.end(), -1);
            EXPECT_EQ
            (
                exclusiveScan(openmpExec{}, in.data(), out.data(), n), total
            );
            EXPECT_EQ(out, ref) << "openmp, " << nt << " threads, n = " << n;

            // In place: a count array becomes the offset array.
            std::vector<label> io(in);
            EXPECT_EQ
            (
                exclusiveScan(openmpExec{}, io.data(), io.data(), n), total
            );
            EXPECT_EQ(io, ref) << "in place, n = " << n;
        }
    }
}


TEST(exclusiveScan, negativeValues)
{
    const label n = 70001;
    const std::vector<label> in = randomIntegers<label>(n, -9, 9, 6);
    std::vector<label> ref(n), out(n);
    label total = 0;
    for (label i = 0; i < n; ++i)
    {
        ref[i] = total;
        total += in[i];
    }
    EXPECT_EQ(exclusiveScan(openmpExec{}, in.data(), out.data(), n), total);
    EXPECT_EQ(out, ref);
}


TEST(exclusiveScan, overflowIsFatal)
{
    const std::vector<label> in = {1000000000, 1000000000, 1000000000};
    std::vector<label> out(3);
    EXPECT_THROW(exclusiveScan(serialExec{}, in.data(), out.data(), 3),
                 FatalError);

    std::vector<label> big(100000, 30000);
    std::vector<label> bigOut(big.size());
    EXPECT_THROW
    (
        exclusiveScan(openmpExec{}, big.data(), bigOut.data(), label(big.size())),
        FatalError
    );
}


// * * * * * * * * * * * * * * * * * sortByKey  * * * * * * * * * * * * * * //

namespace
{

template<class K, class Exec>
void checkSort(const Exec& exec, std::vector<K> keys, const char* what)
{
    const label n = label(keys.size());
    std::vector<label> values(n);
    std::iota(values.begin(), values.end(), 0);

    std::vector<K> refKeys(keys);
    std::vector<label> refValues(values);
    referenceSort(refKeys, refValues);

    sortByKey(exec, keys.data(), values.data(), n);
    EXPECT_EQ(keys, refKeys) << what << ", n = " << n;
    // Values are the original positions: equal keys keep their order.
    EXPECT_EQ(values, refValues) << what << ", n = " << n;
}

template<class Exec>
void checkAllSorts(const Exec& exec)
{
    using u32 = std::uint32_t;
    const label lmax = std::numeric_limits<label>::max();
    const label lmin = std::numeric_limits<label>::min();

    for (const label n : sizes)
    {
        // Cell indices: few distinct keys, many ties.
        checkSort(exec, randomIntegers<u32>(n, 0, 49, 7), "cells");
        checkSort(exec, randomIntegers<u32>(n, 0, 0xffffffffu, 8), "uint32");
        checkSort(exec, randomIntegers<label>(n, -1000, 1000, 9), "signed");
        checkSort(exec, randomIntegers<label>(n, lmin, lmax, 10), "label");
        checkSort(exec, std::vector<u32>(n, 42u), "equal keys");

        std::vector<label> sorted(n);
        std::iota(sorted.begin(), sorted.end(), -n/2);
        checkSort(exec, sorted, "sorted");
        std::reverse(sorted.begin(), sorted.end());
        checkSort(exec, sorted, "reversed");
    }
}

} // End anonymous namespace


TEST(sortByKey, serialStable)
{
    checkAllSorts(serialExec{});
}


TEST(sortByKey, openmpStable)
{
    for (const int nt : {2, 3})
    {
        threadCount t(nt);
        checkAllSorts(openmpExec{});
    }
}


TEST(sortByKey, extremeKeys)
{
    const label lmax = std::numeric_limits<label>::max();
    const label lmin = std::numeric_limits<label>::min();
    checkSort(serialExec{}, std::vector<label>{lmax, 0, lmin, -1, lmax, lmin},
              "extremes");
    checkSort(openmpExec{}, std::vector<std::uint32_t>{0xffffffffu, 0, 1u},
              "extremes");
}


// * * * * * * * * * * * * * * * * * GPU queries  * * * * * * * * * * * * * //

TEST(cudaDevice, askingIsSafeEverywhere)
{
    gpuInfo info;
    EXPECT_NO_THROW(info = cudaDeviceInfo());
    EXPECT_EQ(info.available, gpuAvailable());
    std::cout << "Device : " << info.describe() << std::endl;

    EXPECT_NO_THROW(cudaDeviceInfo(12345));
    EXPECT_FALSE(cudaDeviceInfo(12345).available);

    // Empty buffers never touch the device.
    deviceBuffer<scalar> empty;
    EXPECT_TRUE(empty.empty());
    deviceBuffer<label> none(0);
    EXPECT_EQ(none.size(), 0);

    if (info.available)
    {
        EXPECT_FALSE(info.name.empty());
        EXPECT_GT(info.totalMemory, 0u);
        const std::vector<label> host = {1, 2, 3};
        deviceBuffer<label> buf(host);
        EXPECT_EQ(buf.toHost(), host);
    }
    else
    {
        EXPECT_FALSE(info.reason.empty());
        EXPECT_THROW(deviceBuffer<scalar> buf(10), FatalError);
        EXPECT_NO_THROW(cudaSynchronize());
    }
}
