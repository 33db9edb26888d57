/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// sphVcpmFsi: weakly compressible SPH for free-surface flow between rigid
// walls, coupled to elastic VCPM solids, or the solids alone when the case
// has no fluid. Reads the case, advances it to endTime on the CPU or the
// GPU and writes time directories and postProcessing/; with -postProcess
// it only evaluates the function objects on the times already written.

#include "argList.H"
#include "caseLock.H"
#include "cudaDevice.H"
#include "error.H"
#include "solidOnlySolver.H"
#include "stopControl.H"
#include "fsiSolver.H"
#include "postProcessTimes.H"
#include "timeSelection.H"

#include <cstdlib>
#include <iostream>

using namespace sphvcpm;

namespace
{

// sphVcpmFsi -postProcess: the function objects on the written times.
int postProcess(const argList& args)
{
    if (args.found("device") || args.found("timers"))
    {
        fatalError("-postProcess runs on the CPU and times nothing: leave"
            " out -device and -timers");
    }
    postProcessSettings settings;
    settings.dictFile = args.option("dict");
    settings.functions = args.wordListOption("funcs");
    if (args.found("funcs") && settings.functions.empty())
    {
        fatalError("-funcs '" + args.option("funcs") + "' names no function"
            " object: leave it out to evaluate every enabled one");
    }
    if (args.found("func"))
    {
        settings.functions.push_back(args.option("func"));
    }
    settings.overwrite = args.found("overwrite");
    args.printBanner();

    const timeSelection selection(args);
    const std::vector<timeInstant> all = findTimes(args.casePath());
    const std::vector<timeInstant> times =
        selection.selectOrFail(args.casePath(), all);
    for (const auto& note : selection.nearestNotes(all))
    {
        std::cout << note << "\n";
    }
    postProcessTimes(args.casePath(), times, settings, std::cout);

    std::cout << executionTimeLine() << "\n\nEnd\n" << std::endl;
    return 0;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    return runGuarded([&]()
    {
        argList args("sphVcpmFsi",
            "Weakly compressible SPH for free-surface flow between rigid"
            " walls, coupled to elastic VCPM solids (or the solids alone)");
        args.addNote("Reads system/{controlDict,sphSchemes}, constant/"
            "{fluidProperties,solidProperties,g,motion,dampingZones}\n"
            "(solidProperties with solids, motion and dampingZones where"
            " present) and the start time;\nwrites"
            " <time>/<body>/{position,U,rho,p,mass,id} and"
            " postProcessing/<function>/<startTime>/.\nA case with solids"
            " and no fluid runs the VCPM solids alone;\nit writes"
            " <time>/<solid>/{position,U,displacement,stress*,vonMises,...}.");
        args.addOption("device", "cpu|cuda|auto",
            "where to run (overrides $SPHVCPM_DEVICE and controlDict's"
            " device)");
        args.addBoolOption("timers", "time the phases of the step and"
            " print them in the run summary (on the GPU each phase then"
            " waits for the last)");
        args.addBoolOption("postProcess", "do not solve: evaluate the"
            " function objects on the written times (-time, -latestTime,"
            " -noZero choose them)");
        args.addOption("func", "name", "with -postProcess: only this entry"
            " of functions {} (also with enabled false)");
        args.addOption("funcs", "list", "with -postProcess: only these"
            " entries, e.g. '(probe1 gauges)'");
        args.addOption("dict", "file", "with -postProcess: read functions {}"
            " from this file (relative to the case) instead of"
            " system/controlDict");
        args.addBoolOption("overwrite", "with -postProcess: write over the"
            " tables of postProcessing/<name>/<first time>/");
        timeSelection::addOptions(args);
        args.addNote("-postProcess writes postProcessing/<name>/<first time"
            " evaluated>/, each time sampled once.");
        if (!args.parse(argc, argv))
        {
            return 0;
        }
        if (args.found("postProcess"))
        {
            return postProcess(args);
        }
        for (const char* only : {"func", "funcs", "dict", "overwrite",
                                 "time", "latestTime", "noZero"})
        {
            if (args.found(only))
            {
                fatalError("-" + std::string(only) + " is an option of"
                    " -postProcess, which was not given");
            }
        }
        // The solver reads controlDict again and gives its warnings, after
        // the banner.
        const timeControl control = [&]
        {
            const quietWarnings quiet;
            return timeControl::read(args.casePath());
        }();
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
        const caseLock lock(args.casePath());

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
