/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// particlesToVTK: the particles of a case's time directories as VTK
// PolyData for ParaView, VTK/<body>/<body>_<index>.vtp, with a time series
// VTK/<body>.vtp.series per body (open that one in ParaView).

#include "argList.H"
#include "error.H"
#include "timeSelection.H"
#include "vtkCaseConverter.H"

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
        args.addNote("Writes VTK/<body>/<body>_<index>.vtp (index: the time"
            " index of <time>/uniform/time, 0 without one)\nand"
            " VTK/<body>.vtp.series listing every converted time;"
            " open the .series files in ParaView.");
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

        for (const timeInstant& t : times)
        {
            std::cout << "Time = " << t.name << "\n";
            for (const auto& out : converter.convert(t))
            {
                std::cout << "    " << out.body << ": " << out.nParticles
                          << " particles -> " << out.file.generic_string()
                          << "\n";
            }
            std::cout << std::endl;
        }
        converter.writeSeries();

        std::cout << executionTimeLine() << "\n\nEnd\n" << std::endl;
        return 0;
    });
}
