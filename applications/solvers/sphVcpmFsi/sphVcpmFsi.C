/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// sphVcpmFsi: weakly compressible SPH for free-surface flow between rigid
// walls, or elastic VCPM solids alone when the case has no fluid (the
// coupling of the two joins in a later version). Reads the case, advances
// it to endTime and writes time directories and postProcessing/.

#include "argList.H"
#include "error.H"
#include "solidOnlySolver.H"
#include "fsiSolver.H"

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
            " postProcessing/<function>/<startTime>/.\nA case with solids"
            " and no fluid runs the VCPM solids alone (constant/"
            "solidProperties);\nit writes <time>/<solid>/{position,U,"
            "displacement,stress*,vonMises,...}.");
        if (!args.parse(argc, argv))
        {
            return 0;
        }
        args.printBanner();

        // No fluid: the solids alone, without building any SPH data.
        const std::string startTime = startTimeName(args.casePath(),
            timeControl::read(args.casePath()));
        if (solidOnlySolver::applies(args.casePath(), startTime))
        {
            solidOnlySolver solver(args.casePath(), startTime, std::cout);
            solver.run();
        }
        else
        {
            fsiSolver solver(args.casePath(), std::cout);
            solver.run();
        }

        std::cout << executionTimeLine() << "\n\nEnd\n" << std::endl;
        return 0;
    });
}
