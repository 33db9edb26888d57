/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// sphVcpmFsi: weakly compressible SPH for free-surface flow between rigid
// walls, coupled to elastic VCPM solids, or the solids alone when the case
// has no fluid. Reads the case, advances it to endTime on the CPU or the
// GPU and writes time directories and postProcessing/.

#include "argList.H"
#include "cudaDevice.H"
#include "error.H"
#include "solidOnlySolver.H"
#include "stopControl.H"
#include "fsiSolver.H"

#include <cstdlib>
#include <iostream>

using namespace sphvcpm;

int main(int argc, char* argv[])
{
    return runGuarded([&]()
    {
        argList args("sphVcpmFsi",
            "Weakly compressible SPH for free-surface flow between rigid"
            " walls, coupled to elastic VCPM solids (or the solids alone)");
        args.addNote("Reads system/{controlDict,sphSchemes},"
            " constant/{fluidProperties,g} and the start time;\nwrites"
            " <time>/<body>/{position,U,rho,p,mass,id} and"
            " postProcessing/<function>/<startTime>/.\nA case with solids"
            " and no fluid runs the VCPM solids alone (constant/"
            "solidProperties);\nit writes <time>/<solid>/{position,U,"
            "displacement,stress*,vonMises,...}.");
        args.addOption("device", "cpu|cuda|auto",
            "where to run (overrides $SPHVCPM_DEVICE and controlDict's"
            " device)");
        args.addBoolOption("timers", "time the phases of the step and"
            " print them in the run summary (on the GPU each phase then"
            " waits for the last)");
        if (!args.parse(argc, argv))
        {
            return 0;
        }
        const timeControl control = timeControl::read(args.casePath());
        // -device, else $SPHVCPM_DEVICE (so that a tutorial's Allrun runs
        // on the GPU unchanged: SPHVCPM_DEVICE=cuda ./Allrun), else
        // controlDict's device: empty here, so that the solver's errors
        // name controlDict's line.
        const char* fromEnvironment = std::getenv("SPHVCPM_DEVICE");
        const std::string asked = args.optionOrDefault("device",
            fromEnvironment ? std::string(fromEnvironment) : "");
        const std::string device = asked.empty() ? control.device : asked;
        args.printBanner((device == "cuda" || device == "auto") && gpuAvailable()
            ? cudaDeviceInfo().describe() : "cpu");

        // No fluid: the solids alone, without building any SPH data.
        const std::string startTime = startTimeName(args.casePath(), control);
        if (solidOnlySolver::applies(args.casePath(), startTime))
        {
            if (device != "cpu" && device != "cuda" && device != "auto")
            {
                fatalError("device " + device + ": expected cpu, cuda or"
                    " auto (from -device, $SPHVCPM_DEVICE or the device"
                    " entry of system/controlDict)");
            }
            if (device == "cuda")
            {
                std::cout << "The case has no fluid: its solids run alone,"
                    " on the CPU\n" << std::endl;
            }
            solidOnlySolver solver(args.casePath(), startTime, std::cout);
            solver.run();
        }
        else
        {
            fsiSolver solver(args.casePath(), std::cout, asked);
            if (args.found("timers")) solver.enableTimers();
            solver.run();
        }

        std::cout << executionTimeLine() << "\n\nEnd\n" << std::endl;
        stopControl::raiseCaughtSignal();
        return 0;
    });
}
