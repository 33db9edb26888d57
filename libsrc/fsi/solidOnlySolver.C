/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "solidOnlySolver.H"
#include "argList.H"
#include "dampingZones.H"
#include "dictionary.H"
#include "dimensionSet.H"
#include "error.H"
#include "gravity.H"
#include "parallel.H"
#include "sphModel.H"
#include "startState.H"
#include "stopControl.H"
#include "timeDirectory.H"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>

namespace sphvcpm
{

namespace fs = std::filesystem;

bool solidOnlySolver::applies(const fs::path& caseDir,
                              const std::string& timeName)
{
    // bodyProperties only: a fluid case reads nothing more than before.
    bool solid = false, fluid = false;
    for (const auto& e : fs::directory_iterator(caseDir/timeName))
    {
        const fs::path props = e.path()/"bodyProperties";
        if (!e.is_directory() || !fs::is_regular_file(props)) continue;
        const std::string type = dictionary::fromFile(props)
            .getWord("type", {"fluid", "wall", "solid"});
        solid = solid || type == "solid";
        fluid = fluid || type == "fluid";
    }
    return solid && !fluid;
}


solidOnlySolver::solidOnlySolver
(
    const fs::path& caseDir,
    const std::string& startTimeName,
    std::ostream& log,
    const bool postProcessing
)
:
    caseDir_(caseDir),
    log_(log),
    control_(timeControl::read(caseDir)),
    startTimeName_(startTimeName),
    postProcessing_(postProcessing)
{
    const timeState state = readTimeState(caseDir_, startTimeName_);
    time_ = state.value;
    timeIndex_ = state.index;
    beginTime_ = time_;
    const bool freshStart = state.index == 0;

    if (!postProcessing)
    {
        clearInterruptedWrites(caseDir_, log_);
    }
    warnUnreadConstantFiles(caseDir_);
    log_<< "Reading time " << startTimeName_ << " (solids alone: no fluid"
        << " body)\n";
    const std::vector<particleBody> start =
        readTimeDirectory(caseDir_, startTimeName_);
    checkStartState(caseDir_, startTimeName_, start, state, true, log_);
    nDim_ = start.front().nDimensions();
    for (const particleBody& b : start)
    {
        if (b.type() != bodyType::solid)
        {
            log_<< "    " << b.name() << " (" << bodyTypeName(b.type())
                << "): ignored, no solid-wall contact yet\n";
        }
    }
    // Damping zones act on the fluid: here they are checked and named
    // as unused, never silently ignored.
    if (readDampingZones(caseDir_, nDim_).n > 0)
    {
        warning("constant/dampingZones: the case has no fluid, and damping"
            " zones act on the fluid only: they are not used",
            (caseDir_/"constant"/"dampingZones").string(), 0);
    }
    const vec3 g = readGravity(caseDir_, nDim_);
    solids_ = std::make_unique<solidBodySet>(caseDir_, startTimeName_, start,
                                             freshStart, g, log_);
    motions_ = prescribedMotions(caseDir_, start, nDim_, false, log_);
    if (freshStart)
    {
        motions_.placeSolids(*solids_, time_);
    }
    else
    {
        motions_.checkRestart(caseDir_, startTimeName_, time_, start,
                              *solids_);
    }
    clampMotion_ = motions_.clampMotions(*solids_);
    solidsDeltaT_ = solids_->stableDeltaT();
    deltaT_ = std::min(solidsDeltaT_, control_.maxDeltaT);
    log_<< "    g = (" << g.x << " " << g.y << " " << g.z << ")"
        << gravityDefaultNote(caseDir_, nDim_) << ", " << nDim_
        << "D, time = " << time_ << ", solid deltaT = " << deltaT_
        << " s\n" << std::endl;

    model_.nDimensions = nDim_;
    model_.g = g;
    model_.dp = vGreat;
    for (const solidBody& b : solids_->bodies())
    {
        bodies_.push_back({b.name, bodyType::solid, b.dp});
        model_.dp = std::min(model_.dp, b.dp);
        solidViews_.push_back({b.name, &b.solid->reference(),
                               &b.solid->position});
    }
    control_.dict.setCaseDimensions(nDim_);
    if (!postProcessing)
    {
        functions_ = functionObject::readAll(control_.dict, caseDir_,
            startTimeName_, model_, bodies_, false);
    }
}


void solidOnlySolver::executeFunctions()
{
    const solverSnapshot s = snapshot();
    for (auto& f : functions_)
    {
        f->execute(s);
    }
}


void solidOnlySolver::write()
{
    label maxId = 0;
    std::vector<particleBody> out = solids_->output(nDim_, maxId);
    for (particleBody& o : out) o.setNextId(maxId + 1);

    const timeState state{time_, schedule_->writeName(time_), timeIndex_, deltaT_,
                          deltaT_, beginTime_, {}};
    writeTimeDirectory(caseDir_, state, out,
        writeFormatFromName(control_.writeFormatName),
        control_.writePrecision);
    log_<< "Writing time " << state.name << std::endl;
}


void solidOnlySolver::run()
{
    if (postProcessing_)
    {
        fatalError("solidOnlySolver::run: a solver made for -postProcess"
            " only reads its time");
    }
    schedule_.emplace(control_, time_);
    schedule_->countEarlierWrites(writesUpTo(caseDir_, time_));
    if (time_ >= control_.endTime*(1 - 1e-12))
    {
        log_<< "Time " << time_ << " is at or past endTime "
            << control_.endTime << ": nothing to do\n" << std::endl;
        return;
    }

    for (solidBody& b : solids_->bodies())
    {
        b.solid->computeForces(openmpExec{});
    }
    executeFunctions();

    log_<< threadContentionNote();
    log_<< "Starting time loop\n" << std::endl;
    label stepsRun = 0;
    stopControl stop(control_, *schedule_, caseDir_, log_);
    while (time_ < control_.endTime*(1 - 1e-12))
    {
        // The same write times as the fluid loop.
        const scalar dt = schedule_->limitStep(time_,
            std::min(solidsDeltaT_, control_.maxDeltaT));
        for (std::size_t b = 0; b < solids_->bodies().size(); ++b)
        {
            vcpmSolid& solid = *solids_->bodies()[b].solid;
            vcpmSolidView v = solid.view();
            if (const rigidMotion* m = clampMotion_[b])
            {
                v.clampMove = m->move(time_, time_ + dt);
            }
            vcpmStep(openmpExec{}, v, dt);
        }
        deltaT_ = dt;
        time_ += dt;
        if (schedule_->landed())
        {
            time_ = schedule_->landingTime();
        }
        ++timeIndex_;
        ++stepsRun;

        const std::string bad = solids_->firstNonFinite();
        if (!bad.empty())
        {
            fatalError("The solid blew up at time " + std::to_string(time_)
                + ": " + bad + " has a non-finite position (is maxDeltaT"
                  " above the stable step?)");
        }

        executeFunctions();

        const stopAction action = stop.afterStep(time_);
        const bool atEnd = time_ >= control_.endTime*(1 - 1e-12);
        bool wrote = false;
        if (stopControl::writes(action,
                schedule_->due(time_, timeIndex_) || atEnd))
        {
            write();
            schedule_->written(time_, schedule_->name(time_), caseDir_,
                               startTimeName_);
            wrote = true;
        }
        const bool stopNow = stopControl::stops(action, wrote);
        if (stepsRun % control_.logInterval == 0 || atEnd || stopNow)
        {
            scalar kinetic = 0;
            for (const solidBody& b : solids_->bodies())
            {
                kinetic += b.solid->kineticEnergy();
            }
            log_<< "Time = " << schedule_->name(time_) << "\n"
                << "Step = " << timeIndex_ << "  deltaT = "
                << std::setprecision(4) << deltaT_ << std::setprecision(6)
                << "  kinetic energy = " << kinetic << " J\n"
                << executionTimeLine() << "\n"
                << progress_.line(time_, control_.endTime) << std::endl;
        }
        if (stopNow)
        {
            stop.reportStop(action, time_);
            break;
        }
    }
}

} // End namespace sphvcpm
