/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "parallel.H"

#include "error.H"

#include <cstring>
#include <limits>
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sphvcpm
{

// Below this size threads cost more than they save.
static const label minParallelSize = 1 << 15;

int openmpThreads()
{
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}


// * * * * * * * * * * * * * * * * exclusiveScan  * * * * * * * * * * * * * //

static label checkedTotal(const std::int64_t total, const char* backend)
{
    if
    (
        total > std::numeric_limits<label>::max()
     || total < std::numeric_limits<label>::min()
    )
    {
        fatalError
        (
            std::string("exclusiveScan (") + backend + "): the total "
          + std::to_string(total) + " does not fit a 32-bit label"
        );
    }
    return label(total);
}


// Scans [begin, end) starting from offset; returns the running sum at end.
// Reads in[i] before writing out[i], so in == out works.
static std::int64_t scanRange(const label* in, label* out, label begin,
                              const label end, std::int64_t offset)
{
    for (; begin < end; ++begin)
    {
        const label v = in[begin];
        out[begin] = label(offset);
        offset += v;
    }
    return offset;
}


label exclusiveScan(serialExec, const label* in, label* out, const label n)
{
    return checkedTotal(scanRange(in, out, 0, n, 0), "serial");
}


label exclusiveScan(openmpExec, const label* in, label* out, const label n)
{
    const int nChunks = openmpThreads();
    if (n < minParallelSize || nChunks < 2)
    {
        return checkedTotal(scanRange(in, out, 0, n, 0), "openmp");
    }

    // Pass 1: chunk sums; serial prefix over chunks; pass 2: local scans.
    std::vector<std::int64_t> offset(nChunks + 1, 0);
    const label chunk = (n - 1)/nChunks + 1;

#ifdef _OPENMP
    #pragma omp parallel for schedule(static)
#endif
    for (int c = 0; c < nChunks; ++c)
    {
        const label begin = std::min(n, c*chunk);
        const label end = std::min(n, begin + chunk);
        std::int64_t sum = 0;
        for (label i = begin; i < end; ++i)
        {
            sum += in[i];
        }
        offset[c + 1] = sum;
    }
    for (int c = 0; c < nChunks; ++c)
    {
        offset[c + 1] += offset[c];
    }
    const label total = checkedTotal(offset[nChunks], "openmp");

#ifdef _OPENMP
    #pragma omp parallel for schedule(static)
#endif
    for (int c = 0; c < nChunks; ++c)
    {
        const label begin = std::min(n, c*chunk);
        const label end = std::min(n, begin + chunk);
        scanRange(in, out, begin, end, offset[c]);
    }
    return total;
}


// * * * * * * * * * * * * * * * * * sortByKey  * * * * * * * * * * * * * * //

// LSD radix sort by bytes over nChunks contiguous chunks. Each chunk counts
// its digits, the offsets are laid out digit-major then chunk-major, and each
// chunk scatters its elements in order: stable, and the same result for any
// number of chunks.
static void radixSort(std::uint32_t* keys, label* values, const label n,
                      const int nChunks)
{
    if (n < 2)
    {
        return;
    }

    std::vector<std::uint32_t> keyTmp(n);
    std::vector<label> valueTmp(n);
    std::uint32_t* srcK = keys;
    label* srcV = values;
    std::uint32_t* dstK = keyTmp.data();
    label* dstV = valueTmp.data();

    const label chunk = (n - 1)/nChunks + 1;
    std::vector<label> count(std::size_t(nChunks)*256);

    // body(counts of chunk c, begin, end) for every chunk, side by side.
    const auto forEachChunk = [&](const auto& body)
    {
#ifdef _OPENMP
        #pragma omp parallel for schedule(static) if (nChunks > 1)
#endif
        for (int c = 0; c < nChunks; ++c)
        {
            const label begin = std::min(n, c*chunk);
            body(count.data() + std::size_t(c)*256, begin,
                 std::min(n, begin + chunk));
        }
    };

    for (int shift = 0; shift < 32; shift += 8)
    {
        std::fill(count.begin(), count.end(), 0);

        forEachChunk([&](label* cc, const label begin, const label end)
        {
            for (label i = begin; i < end; ++i)
            {
                ++cc[(srcK[i] >> shift) & 0xff];
            }
        });

        // Turn the counts into start offsets; a byte shared by all keys
        // leaves the order as it is, so the pass is skipped.
        label running = 0;
        bool trivial = false;
        for (int d = 0; d < 256 && !trivial; ++d)
        {
            label digitTotal = 0;
            for (int c = 0; c < nChunks; ++c)
            {
                label& cc = count[std::size_t(c)*256 + d];
                const label m = cc;
                cc = running;
                running += m;
                digitTotal += m;
            }
            trivial = (digitTotal == n);
        }
        if (trivial)
        {
            continue;
        }

        forEachChunk([&](label* cc, const label begin, const label end)
        {
            for (label i = begin; i < end; ++i)
            {
                const label pos = cc[(srcK[i] >> shift) & 0xff]++;
                dstK[pos] = srcK[i];
                dstV[pos] = srcV[i];
            }
        });
        std::swap(srcK, dstK);
        std::swap(srcV, dstV);
    }

    if (srcK != keys)
    {
        std::memcpy(keys, srcK, std::size_t(n)*sizeof(std::uint32_t));
        std::memcpy(values, srcV, std::size_t(n)*sizeof(label));
    }
}


// Signed keys sort as unsigned once the sign bit is flipped; int32_t and
// uint32_t may alias each other, so this is done in place.
static void flipSignBits(label* keys, const label n)
{
    std::uint32_t* k = reinterpret_cast<std::uint32_t*>(keys);
    for (label i = 0; i < n; ++i)
    {
        k[i] ^= 0x80000000u;
    }
}


static int sortChunks(const label n)
{
    return n < minParallelSize ? 1 : openmpThreads();
}


void sortByKey(serialExec, std::uint32_t* keys, label* values, const label n)
{
    radixSort(keys, values, n, 1);
}


void sortByKey(serialExec, label* keys, label* values, const label n)
{
    flipSignBits(keys, n);
    radixSort(reinterpret_cast<std::uint32_t*>(keys), values, n, 1);
    flipSignBits(keys, n);
}


void sortByKey(openmpExec, std::uint32_t* keys, label* values, const label n)
{
    radixSort(keys, values, n, sortChunks(n));
}


void sortByKey(openmpExec, label* keys, label* values, const label n)
{
    flipSignBits(keys, n);
    radixSort
    (
        reinterpret_cast<std::uint32_t*>(keys), values, n, sortChunks(n)
    );
    flipSignBits(keys, n);
}

} // End namespace sphvcpm
