/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// sphVcpmFsi: weakly compressible SPH for free-surface flow between rigid
// walls (elastic VCPM solids join in a later version). Reads the case,
// advances it to endTime and writes time directories and postProcessing/.

#include "argList.H"
#include "error.H"
#include "sphSolver.H"

#include <iostream>

using namespace sphvcpm;

int main(int argc, char* argv[])
{
    return runGuarded([&]()
    {
        argList args("sphVcpmFsi",
            "Weakly compressible SPH solver for free-surface flow with"
            " rigid walls");
        args.addNote("Reads system/{controlDict,sphSchemes},"
            " constant/{fluidProperties,g} and the start time;\nwrites"
            " <time>/<body>/{position,U,rho,p,mass,id} and"
            " postProcessing/<function>/<startTime>/.");
        if (!args.parse(argc, argv))
        {
            return 0;
        }
        args.printBanner();

        sphSolver solver(args.casePath(), std::cout);
        solver.run();

        std::cout << executionTimeLine() << "\n\nEnd\n" << std::endl;
        return 0;
    });
}
