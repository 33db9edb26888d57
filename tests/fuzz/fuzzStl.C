/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// libFuzzer target: any bytes through the STL parser, then the surface
// repairs, edge analysis, volume and the three-ray inside test on a few
// points. A FatalError is the expected answer to bad input; a crash, a
// sanitizer report, a hang or an unexpected exception is a bug.

#include "error.H"
#include "stlReader.H"
#include "triSurface.H"
#include "triSurfaceInside.H"

#include <cstddef>
#include <cstdint>

using namespace sphvcpm;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data,
                                      std::size_t size)
{
    stlData stl;
    try
    {
        stl = parseSTL(reinterpret_cast<const char*>(data), size, "fuzz.stl");
    }
    catch (const FatalError&)
    {
        return 0;
    }

    // Keep each run short.
    if (stl.nTriangles() > 4096)
    {
        return 0;
    }

    // The first input byte picks a merge distance: none, the default
    // scale of one, or a coarse one that collapses triangles.
    const scalar merge[] = {0, 1e-6, 0.1};
    const triSurface surf(stl.vertices, merge[data[0] % 3]);
    (void)surf.volume();
    (void)surf.nShells();

    const triSurfaceInside test(surf);
    const boundBox b = surf.bounds();
    if (!b.valid())
    {
        return 0;
    }
    // A 5^3 grid over the bounds, and its corners (rays along edges).
    for (int i = 0; i <= 4; ++i)
    {
        for (int j = 0; j <= 4; ++j)
        {
            for (int k = 0; k <= 4; ++k)
            {
                const vec3 p
                {
                    b.min.x + (b.max.x - b.min.x)*scalar(i)/4,
                    b.min.y + (b.max.y - b.min.y)*scalar(j)/4,
                    b.min.z + (b.max.z - b.min.z)*scalar(k)/4
                };
                (void)test.inside(p);
            }
        }
    }
    for (const vec3& p : surf.points())
    {
        (void)test.inside(p);
    }
    return 0;
}
