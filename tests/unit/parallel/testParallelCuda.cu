/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Every CUDA primitive against the serial host result on the same data;
// skipped when no GPU is usable. Built with GoogleTest by CMake, or without
// it as the plain program parallelCudaCheck (PASS/FAIL lines, exit status 1
// on failure) on machines that lack GoogleTest:
//
//     nvcc -std=c++17 -DSPHVCPM_PLAIN_CHECK -Ilibsrc/core -Ilibsrc/parallel
//         testParallelCuda.cu <the three sphvcpm libraries> -Xcompiler -fopenmp
//         -o parallelCudaCheck

#include "cudaDevice.H"
#include "deviceBuffer.H"
#include "error.H"
#include "parallel.H"
#include "testRandomData.H"
#include "parallelCuda.cuh"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#ifndef SPHVCPM_PLAIN_CHECK

#include <gtest/gtest.h>

#define SKIP_WITHOUT_GPU()                                                   \
    if (!gpuAvailable())                                                     \
    {                                                                        \
        GTEST_SKIP() << "no usable GPU: " << cudaDeviceInfo().reason;        \
    }

#else

// Just enough of GoogleTest's surface for this file.
namespace check
{

struct testCase
{
    const char* name;
    void (*body)();
};

inline std::vector<testCase>& tests()
{
    static std::vector<testCase> t;
    return t;
}

inline int& failures()
{
    static int n = 0;
    return n;
}

inline bool& skipped()
{
    static bool s = false;
    return s;
}

inline bool add(const char* name, void (*body)())
{
    tests().push_back({name, body});
    return true;
}

// Collects the streamed context; reports a failure when destroyed.
class result
{
    bool ok_;
    std::ostringstream os_;
public:
    result(const bool ok, const char* expr, const char* file, const int line)
    :
        ok_(ok)
    {
        if (!ok_)
        {
            os_ << "    FAIL " << file << ':' << line << ": " << expr;
        }
    }
    ~result()
    {
        if (!ok_)
        {
            ++failures();
            std::cout << os_.str() << std::endl;
        }
    }
    template<class T>
    result& operator<<(const T& t)
    {
        if (!ok_)
        {
            os_ << (os_.tellp() ? " " : "") << t;
        }
        return *this;
    }
};

} // End namespace check

#define TEST(suite, name)                                                    \
    static void suite##_##name();                                            \
    static const bool suite##_##name##_added =                               \
        check::add(#suite "." #name, suite##_##name);                        \
    static void suite##_##name()

#define SPHVCPM_CHECK(cond, text)                                            \
    check::result((cond), text, __FILE__, __LINE__)
#define EXPECT_TRUE(c) SPHVCPM_CHECK(bool(c), #c)
#define EXPECT_FALSE(c) SPHVCPM_CHECK(!bool(c), "!" #c)
#define EXPECT_EQ(a, b) SPHVCPM_CHECK((a) == (b), #a " == " #b)
#define EXPECT_GT(a, b) SPHVCPM_CHECK((a) > (b), #a " > " #b)
#define EXPECT_NEAR(a, b, tol)                                               \
    SPHVCPM_CHECK(std::abs((a) - (b)) <= (tol), "|" #a " - " #b "| <= " #tol)
#define EXPECT_THROW(stmt, exc)                                              \
    {                                                                        \
        bool thrown_ = false;                                                \
        try { stmt; } catch (const exc&) { thrown_ = true; } catch (...) {}  \
        SPHVCPM_CHECK(thrown_, #stmt " throws " #exc);                       \
    }
#define EXPECT_NO_THROW(stmt)                                                \
    {                                                                        \
        bool thrown_ = false;                                                \
        try { stmt; } catch (...) { thrown_ = true; }                        \
        SPHVCPM_CHECK(!thrown_, #stmt " does not throw");                    \
    }
#define SKIP_WITHOUT_GPU()                                                   \
    if (!gpuAvailable())                                                     \
    {                                                                        \
        check::skipped() = true;                                             \
        return;                                                              \
    }

int main()
{
    int failed = 0, skipped = 0;
    for (const check::testCase& t : check::tests())
    {
        const int before = check::failures();
        check::skipped() = false;
        try
        {
            t.body();
        }
        catch (const std::exception& e)
        {
            ++check::failures();
            std::cout << "    FAIL exception: " << e.what() << std::endl;
        }
        const bool ok = check::failures() == before;
        failed += !ok;
        skipped += check::skipped();
        std::cout << (!ok ? "FAIL " : check::skipped() ? "SKIP " : "PASS ")
            << t.name << std::endl;
    }
    std::cout << check::tests().size() << " tests, " << failed
        << " failed, " << skipped << " skipped" << std::endl;
    return failed ? 1 : 0;
}

#endif


using namespace sphvcpm;

namespace
{

const std::vector<label> sizes =
    {0, 1, 2, 3, 7, 255, 256, 257, 4097, 65537, 262145, 1000000, 1000003};

using test::randomIntegers;
using test::randomScalars;

// First index where a and b differ, -1 when equal.
template<class T>
long long firstDifference(const std::vector<T>& a, const std::vector<T>& b)
{
    if (a.size() != b.size())
    {
        return 0;
    }
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        if (!(a[i] == b[i]))
        {
            return (long long)i;
        }
    }
    return -1;
}


// Functors as physics writes them, compiled for host and device alike.

struct indexHash
{
    label* y;

    SPHVCPM_HD void operator()(const label i) const
    {
        // Kept below 2^31: signed overflow is undefined and host and
        // device compilers resolve it differently.
        y[i] = ((i % 7919)*31) % 1000 - 500;
    }
};

struct crossMagnitude
{
    const vec3* a;
    const vec3* b;
    scalar* y;

    SPHVCPM_HD void operator()(const label i) const
    {
        y[i] = mag(cross(a[i], b[i])) + 0.5*dot(a[i], b[i]);
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

struct readVector
{
    const vec3* v;

    SPHVCPM_HD vec3 operator()(const label i) const
    {
        return v[i];
    }
};

std::vector<vec3> randomVectors(const label n, const unsigned seed)
{
    const std::vector<scalar> s = randomScalars(3*n, seed);
    std::vector<vec3> v(n);
    for (label i = 0; i < n; ++i)
    {
        v[i] = {s[3*i], s[3*i + 1], s[3*i + 2]};
    }
    return v;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Device  * * * * * * * * * * * * * * * * //

TEST(cudaParallel, deviceInfo)
{
    SKIP_WITHOUT_GPU();
    const gpuInfo info = cudaDeviceInfo();
    std::cout << "Device : " << info.describe() << std::endl;
    EXPECT_TRUE(info.available);
    EXPECT_TRUE(cudaBackendBuilt());
    EXPECT_FALSE(info.name.empty());
    EXPECT_GT(info.totalMemory, 0u);
    EXPECT_GT(info.multiProcessors, 0);
}


TEST(cudaParallel, deviceBuffer)
{
    SKIP_WITHOUT_GPU();
    const std::vector<scalar> host = randomScalars(1001, 11);
    deviceBuffer<scalar> a(host);
    EXPECT_EQ(a.size(), 1001);
    EXPECT_EQ(firstDifference(a.toHost(), host), -1);

    deviceBuffer<scalar> b(std::move(a));
    EXPECT_TRUE(a.empty());
    EXPECT_EQ(firstDifference(b.toHost(), host), -1);

    b.zero();
    EXPECT_EQ(firstDifference(b.toHost(), std::vector<scalar>(1001, 0.0)), -1);

    std::vector<scalar> part(10);
    b.copyFromHost(host.data(), 10);
    b.copyToHost(part.data(), 10);
    EXPECT_EQ(firstDifference(part, std::vector<scalar>(host.begin(),
                                                        host.begin() + 10)),
              -1);
    EXPECT_THROW(b.copyToHost(part.data(), 1002), FatalError);

    b = deviceBuffer<scalar>(5);
    EXPECT_EQ(b.size(), 5);
}


TEST(cudaParallel, errorsAreFatalErrors)
{
    SKIP_WITHOUT_GPU();
    bool named = false;
    try
    {
        cudaCheck(cudaErrorInvalidValue, "a test call");
    }
    catch (const FatalError& err)
    {
        const std::string msg = err.message();
        named = msg.find("a test call") != std::string::npos
            && msg.find("cudaErrorInvalidValue") != std::string::npos;
    }
    EXPECT_TRUE(named);

    // A petabyte: refused with the sizes in the message, device still usable.
    std::string msg;
    try
    {
        deviceAllocate(std::size_t(1) << 50);
    }
    catch (const FatalError& err)
    {
        msg = err.message();
    }
    std::cout << "    out-of-memory message: " << msg << std::endl;
    EXPECT_TRUE(msg.find("cudaMalloc") != std::string::npos);
    EXPECT_TRUE(msg.find("free of") != std::string::npos);
    EXPECT_NO_THROW(cudaSynchronize());
    deviceBuffer<label> after(std::vector<label>{4, 5, 6});
    EXPECT_EQ(after.toHost()[2], 6);
}


// * * * * * * * * * * * * * * * * parallelFor  * * * * * * * * * * * * * * //

TEST(cudaParallel, parallelFor)
{
    SKIP_WITHOUT_GPU();
    for (const label n : sizes)
    {
        std::vector<label> ref(n);
        parallelFor(serialExec{}, n, indexHash{ref.data()});
        deviceBuffer<label> y(n);
        parallelFor(cudaExec{}, n, indexHash{y.data()});
        EXPECT_EQ(firstDifference(y.toHost(), ref), -1) << "n = " << n;

        const std::vector<vec3> a = randomVectors(n, 12), b = randomVectors(n, 13);
        std::vector<scalar> yRef(n);
        parallelFor(serialExec{}, n, crossMagnitude{a.data(), b.data(), yRef.data()});
        deviceBuffer<vec3> da(a), db(b);
        deviceBuffer<scalar> dy(n);
        parallelFor(cudaExec{}, n, crossMagnitude{da.data(), db.data(), dy.data()});
        const std::vector<scalar> yGpu = dy.toHost();
        scalar worst = 0;
        for (label i = 0; i < n; ++i)
        {
            worst = std::max(worst, std::abs(yGpu[i] - yRef[i]));
        }
        // Contractions into FMA may differ in the last bits.
        EXPECT_TRUE(worst <= 1e-14) << "n = " << n << ", worst " << worst;
    }
    EXPECT_NO_THROW(cudaSynchronize("parallelFor test"));
}


// * * * * * * * * * * * * * * * * parallelReduce * * * * * * * * * * * * * //

TEST(cudaParallel, parallelReduce)
{
    SKIP_WITHOUT_GPU();
    const scalar big = std::numeric_limits<scalar>::max();
    for (const label n : sizes)
    {
        const std::vector<scalar> v = randomScalars(n, 14);
        deviceBuffer<scalar> dv(v);
        const readValue<scalar> fh{v.data()}, fd{dv.data()};

        scalar absSum = 0;
        for (const scalar x : v)
        {
            absSum += std::abs(x);
        }
        const scalar cpu = parallelReduce(serialExec{}, n, fh, 0.25, sumOp());
        const scalar gpu = parallelReduce(cudaExec{}, n, fd, 0.25, sumOp());
        EXPECT_NEAR(gpu, cpu, 1e-13*absSum + 1e-300) << "n = " << n;

        // Same n, same grid, same tree: the same bits on every run.
        const scalar again = parallelReduce(cudaExec{}, n, fd, 0.25, sumOp());
        EXPECT_TRUE(std::memcmp(&gpu, &again, sizeof(scalar)) == 0)
            << "n = " << n;

        EXPECT_EQ
        (
            parallelReduce(cudaExec{}, n, fd, big, minOp()),
            parallelReduce(serialExec{}, n, fh, big, minOp())
        ) << "min, n = " << n;
        EXPECT_EQ
        (
            parallelReduce(cudaExec{}, n, fd, -big, maxOp()),
            parallelReduce(serialExec{}, n, fh, -big, maxOp())
        ) << "max, n = " << n;

        const std::vector<label> l = randomIntegers<label>(n, -1000, 1000, 15);
        deviceBuffer<label> dl(l);
        EXPECT_EQ
        (
            parallelReduce(cudaExec{}, n, readValue<label>{dl.data()}, label(3), sumOp()),
            parallelReduce(serialExec{}, n, readValue<label>{l.data()}, label(3), sumOp())
        ) << "label sum, n = " << n;

        const std::vector<vec3> w = randomVectors(n, 16);
        deviceBuffer<vec3> dw(w);
        const vec3 zero{0, 0, 0};
        const vec3 vc = parallelReduce(serialExec{}, n, readVector{w.data()}, zero, sumOp());
        const vec3 vg = parallelReduce(cudaExec{}, n, readVector{dw.data()}, zero, sumOp());
        EXPECT_NEAR(vg.x, vc.x, 1e-13*n + 1e-300) << "n = " << n;
        EXPECT_NEAR(vg.z, vc.z, 1e-13*n + 1e-300) << "n = " << n;
    }
}


// * * * * * * * * * * * * * * * * exclusiveScan  * * * * * * * * * * * * * //

TEST(cudaParallel, exclusiveScan)
{
    SKIP_WITHOUT_GPU();
    for (const label n : sizes)
    {
        const std::vector<label> in = randomIntegers<label>(n, 0, 40, 17);
        std::vector<label> ref(n);
        const label total = exclusiveScan(serialExec{}, in.data(), ref.data(), n);

        deviceBuffer<label> din(in), dout(n);
        EXPECT_EQ(exclusiveScan(cudaExec{}, din.data(), dout.data(), n), total)
            << "n = " << n;
        EXPECT_EQ(firstDifference(dout.toHost(), ref), -1) << "n = " << n;

        // In place, as for turning counts into offsets.
        EXPECT_EQ(exclusiveScan(cudaExec{}, din.data(), din.data(), n), total)
            << "in place, n = " << n;
        EXPECT_EQ(firstDifference(din.toHost(), ref), -1)
            << "in place, n = " << n;
    }

    deviceBuffer<label> huge(std::vector<label>(3, 1000000000));
    deviceBuffer<label> hugeOut(3);
    EXPECT_THROW
    (
        exclusiveScan(cudaExec{}, huge.data(), hugeOut.data(), 3),
        FatalError
    );
}


// * * * * * * * * * * * * * * * * * sortByKey  * * * * * * * * * * * * * * //

namespace
{

template<class K>
void compareSort(const std::vector<K>& keys, const char* what)
{
    const label n = label(keys.size());
    std::vector<label> values(n);
    std::iota(values.begin(), values.end(), 0);

    std::vector<K> refKeys(keys);
    std::vector<label> refValues(values);
    sortByKey(serialExec{}, refKeys.data(), refValues.data(), n);

    deviceBuffer<K> dk(keys);
    deviceBuffer<label> dv(values);
    sortByKey(cudaExec{}, dk.data(), dv.data(), n);
    EXPECT_EQ(firstDifference(dk.toHost(), refKeys), -1)
        << what << " keys, n = " << n;
    // Values are original positions: equal keys must keep their order.
    EXPECT_EQ(firstDifference(dv.toHost(), refValues), -1)
        << what << " values, n = " << n;
}

} // End anonymous namespace


TEST(cudaParallel, sortByKey)
{
    SKIP_WITHOUT_GPU();
    using u32 = std::uint32_t;
    const label lmax = std::numeric_limits<label>::max();
    const label lmin = std::numeric_limits<label>::min();

    for (const label n : sizes)
    {
        compareSort(randomIntegers<u32>(n, 0, 49, 18), "cells");
        compareSort(randomIntegers<u32>(n, 0, 0xffffffffu, 19), "uint32");
        compareSort(randomIntegers<label>(n, 0, 100000, 20), "label >= 0");
        compareSort(randomIntegers<label>(n, -1000, 1000, 21), "signed");
        compareSort(randomIntegers<label>(n, lmin, lmax, 22), "label");
        compareSort(std::vector<u32>(n, 0u), "all zero");
        compareSort(std::vector<u32>(n, 42u), "all equal");
    }
    compareSort(std::vector<label>{lmax, 0, lmin, -1, lmax, lmin}, "extremes");

    // Scratch memory given back is taken again on the next call.
    cudaReleaseScratch();
    compareSort(randomIntegers<u32>(100000, 0, 999, 25), "after release");
}


// * * * * * * * * * * * * * * * * * Timings  * * * * * * * * * * * * * * * //
// For the record only, nothing asserted: the cost of the primitives at the
// size of a 3D dam break (1.2 M particles).

namespace
{

template<class Body>
float milliseconds(const Body& body, const int repeats)
{
    body();
    cudaEvent_t start, stop;
    cudaCheck(cudaEventCreate(&start), "cudaEventCreate");
    cudaCheck(cudaEventCreate(&stop), "cudaEventCreate");
    cudaCheck(cudaEventRecord(start), "cudaEventRecord");
    for (int r = 0; r < repeats; ++r)
    {
        body();
    }
    cudaCheck(cudaEventRecord(stop), "cudaEventRecord");
    cudaCheck(cudaEventSynchronize(stop), "cudaEventSynchronize");
    float ms = 0;
    cudaCheck(cudaEventElapsedTime(&ms, start, stop), "cudaEventElapsedTime");
    cudaEventDestroy(start);
    cudaEventDestroy(stop);
    return ms/repeats;
}

} // End anonymous namespace


// A benchmark, not a test: it prints the times of the primitives and
// asserts nothing, so it is disabled; run it by hand with
//   test_parallelCuda --gtest_filter='cudaParallel.*timings'
//                     --gtest_also_run_disabled_tests
TEST(cudaParallel, DISABLED_timings)
{
    SKIP_WITHOUT_GPU();
    const label n = 1200000;
    const std::vector<std::uint32_t> cells =
        randomIntegers<std::uint32_t>(n, 0, 200000, 23);
    deviceBuffer<std::uint32_t> keys0(cells), keys(n);
    deviceBuffer<label> values(n), counts(n), offsets(n);
    counts.zero();
    deviceBuffer<scalar> v(randomScalars(n, 24));

    const float sortMs = milliseconds
    (
        [&]()
        {
            copyDeviceToDevice(keys.data(), keys0.data(), n*sizeof(std::uint32_t));
            sortByKey(cudaExec{}, keys.data(), values.data(), n);
        },
        20
    );
    const float copyMs = milliseconds
    (
        [&]()
        {
            copyDeviceToDevice(keys.data(), keys0.data(), n*sizeof(std::uint32_t));
        },
        20
    );
    const float scanMs = milliseconds
    (
        [&]()
        {
            exclusiveScan(cudaExec{}, counts.data(), offsets.data(), n);
        },
        20
    );
    const float reduceMs = milliseconds
    (
        [&]()
        {
            parallelReduce(cudaExec{}, n, readValue<scalar>{v.data()}, 0.0, sumOp());
        },
        20
    );
    std::cout << "    n = " << n << ": sortByKey (18-bit cell keys) "
        << sortMs - copyMs << " ms, exclusiveScan " << scanMs
        << " ms, parallelReduce (sum) " << reduceMs << " ms" << std::endl;
}
