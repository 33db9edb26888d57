/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// particlesToVTK: the particles of a case's time directories as VTK
// PolyData for ParaView, VTK/<body>/<body>_<index>.vtp, with a time series
// VTK/<body>.vtp.series per body (open that one in ParaView); with
// -freeSurface also the fluid's free surface (libsrc/sph/freeSurface.H).

#include "argList.H"
#include "error.H"
#include "formatting.H"
#include "freeSurface.H"
#include "sphModel.H"
#include "timeSelection.H"
#include "vtkCaseConverter.H"

#include <filesystem>
#include <iostream>

using namespace sphvcpm;

int main(int argc, char* argv[])
{
    return runGuarded([&]()
    {
        argList args("particlesToVTK",
            "Convert the particles of time directories to VTK PolyData"
            " (.vtp) and ParaView time series (.vtp.series)");
        timeSelection::addOptions(args);
        args.addOption("fields", "list",
            "only write these fields, e.g. '(rho U)' (position and id are"
            " always written)");
        args.addBoolOption("freeSurface",
            "also write the fluid's free surface: the surface (3D) or"
            " outline (2D) where the fluid fraction is -surfaceLevel,"
            " with p, U and rho on it");
        args.addOption("surfaceLevel", "value",
            "fluid fraction at the free surface, in (0, 1) (default 0.5:"
            " the fluid's edge); implies -freeSurface");
        args.addOption("surfaceRefine", "n",
            "free-surface grid spacing dp/n (default 2 in 2D, 1 in 3D);"
            " implies -freeSurface");
        args.addNote("Writes VTK/<body>/<body>_<index>.vtp (index: the time"
            " index of <time>/uniform/time, 0 without one)\nand"
            " VTK/<body>.vtp.series listing every converted time;"
            " open the .series files in ParaView.\nThe free surface goes"
            " to VTK/freeSurface/freeSurface_<index>.vtp and"
            " VTK/freeSurface.vtp.series.");
        if (!args.parse(argc, argv))
        {
            return 0;
        }
        args.printBanner();

        vtkCaseConverter converter(args.casePath());
        const timeSelection selection(args);
        const std::vector<timeInstant> times =
            selection.selectOrFail(args.casePath(), converter.times());
        // -time 0.7 takes the nearest time, as OpenFOAM: say which.
        for (const auto& note : selection.nearestNotes(converter.times()))
        {
            std::cout << note << "\n";
        }
        if (args.found("fields"))
        {
            converter.restrictFields(args.wordListOption("fields"), times);
        }

        const bool surface = args.found("freeSurface")
            || args.found("surfaceLevel") || args.found("surfaceRefine");
        freeSurfaceSettings settings;
        settings.level = args.numberOption("surfaceLevel", settings.level);
        const long refine = args.integerOption("surfaceRefine",
                                               settings.refine);
        if (args.found("surfaceRefine") && (refine < 1 || refine > 16))
        {
            fatalError("Option -surfaceRefine expects a whole number from 1"
                " to 16, not '" + args.option("surfaceRefine") + "'");
        }
        settings.refine = int(refine);
        checkFreeSurfaceSettings(settings);
        // What the surface needs, before any time is converted.
        for (const char* file : {"system/sphSchemes",
                                 "constant/fluidProperties"})
        {
            if (surface && !std::filesystem::is_regular_file(
                    args.casePath()/file))
            {
                fatalError("-freeSurface takes the solver's kernel and h"
                    " from the case's system/sphSchemes and"
                    " constant/fluidProperties, and there is no "
                    + (args.casePath()/file).string());
            }
        }
        bool modelRead = false;
        sphModel model;

        // A time that fails leaves the series of the times converted
        // before it, so that ParaView opens them.
        try
        {
            for (const timeInstant& t : times)
            {
                std::cout << "Time = " << t.name << "\n";
                std::vector<particleBody> bodies;
                for (const auto& out : converter.convert(t, &bodies))
                {
                    std::cout << "    " << out.body << ": " << out.nParticles
                              << " particles -> " << out.file.generic_string()
                              << "\n";
                }
                if (surface)
                {
                    std::vector<const particleBody*> fluids;
                    for (const particleBody& b : bodies)
                    {
                        if (b.type() == bodyType::fluid)
                        {
                            fluids.push_back(&b);
                        }
                    }
                    if (!fluids.empty() && !modelRead)
                    {
                        // The solver's kernel and h (system/sphSchemes).
                        model = readSphModel(args.casePath(),
                            fluids.front()->nDimensions(),
                            fluids.front()->dp());
                        modelRead = true;
                    }
                    const freeSurface fs = fluids.empty() ? freeSurface()
                        : fluidFreeSurface(fluids, model.kernel, model.h,
                                           settings);
                    const auto file = converter.writeMesh("freeSurface", t,
                                                          fs.mesh);
                    const bool planar = fs.mesh.nodesPerCell == 2;
                    std::cout << "    freeSurface: " << fs.mesh.nCells()
                        << (planar ? " segments" : " triangles") << " -> "
                        << file.generic_string() << "\n";
                    if (fluids.empty() || !(fs.particleVolume > 0))
                    {
                        std::cout << "        no fluid particles\n";
                    }
                    else
                    {
                        std::cout << "        encloses " << str(fs.enclosed)
                            << (planar ? " m^2" : " m^3")
                            << " (the particles' "
                            << str(fs.particleVolume) << ", "
                            << str(100*(fs.enclosed/fs.particleVolume - 1), 3)
                            << " %)\n";
                    }
                }
                std::cout << std::endl;
            }
        }
        catch (...)
        {
            converter.writeSeries();
            throw;
        }
        converter.writeSeries();

        std::cout << executionTimeLine() << "\n\nEnd\n" << std::endl;
        return 0;
    });
}
