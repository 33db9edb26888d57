/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "fsiSolverSteps.H"
#include "latticeMembers.H"
#include "argList.H"
#include "error.H"
#include "fluidInteractions.H"
#include "gravity.H"
#include "pairRates.H"
#include "pointLocator.H"
#include "startState.H"
#include "stopControl.H"
#include "parallel.H"
#include "withKernel.H"

#include <algorithm>
#include <functional>
#include <chrono>
#include <future>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>

namespace sphvcpm
{

namespace fs = std::filesystem;

namespace
{

// The settings at which timeScheme verlet was found stable
// (docs/solver.md, Time schemes): beyond them density diffusion grows
// between its Euler steps.
constexpr int verletTestedSteps = 40;
constexpr double verletTestedMaxCo = 0.2;
constexpr double verletTestedDelta = 0.1;

const std::string verletTestedLimits = "verletSteps <= "
    + std::to_string(verletTestedSteps) + ", maxCo <= "
    + str(verletTestedMaxCo) + " (adjustTimeStep yes) and delta <= "
    + str(verletTestedDelta);

// The lightest solids, as a fraction of the fluid's density, found at rest
// in still water (docs/fsi.md, "Light solids"): a plate at 0.25 drifted into
// a growing oscillation under the symplectic scheme, one at 0.2 under
// Verlet; 0.3 and 0.25 held (2D, 10 mm, 2.5 s).
constexpr double lightestSymplectic = 0.3;
constexpr double lightestVerlet = 0.25;

void warnLightSolids(const solidBodySet& solids, const sphModel& model)
{
    const bool verlet = model.timeScheme == timeSchemeType::verlet;
    const double lightest = verlet ? lightestVerlet : lightestSymplectic;
    for (const solidBody& b : solids.bodies())
    {
        const scalar ratio = b.solid->material().rho/model.rho0;
        if (ratio >= lightest) continue;
        warning("Solid " + b.name + " is " + str(ratio, 3) + " times the"
            " fluid's density (" + str(b.solid->material().rho) + " against "
            + str(model.rho0) + " kg/m^3). Under timeScheme "
            + (verlet ? "verlet" : "symplectic") + " a plate lighter than "
            + str(lightest) + " times the fluid's density drifted into a"
              " growing oscillation in still water (docs/fsi.md, \"Light"
              " solids\"; measured in 2D at one resolution"
            + (verlet ? "" : "; timeScheme verlet held at 0.25") + "):"
              " watch the solid's forces and motion for growth");
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Construction * * * * * * * * * * * * * * //

fsiSolver::fsiSolver(const fs::path& caseDir, std::ostream& log,
                     const std::string& device,
                     const std::string& postProcessTime)
:
    caseDir_(caseDir),
    log_(log),
    control_(timeControl::read(caseDir)),
    postProcessTime_(postProcessTime)
{
    std::string chosen = device.empty() ? control_.device : device;
    if (chosen == "auto")
    {
        // The GPU when there is one, the CPU otherwise (asked for: no error).
        chosen = gpuAvailable() ? "cuda" : "cpu";
        log_<< "device auto: running on the " << (chosen == "cuda"
            ? "GPU" : "CPU (" + (cudaBackendBuilt()
                ? cudaDeviceInfo().reason : std::string("no CUDA backend"))
              + ")") << "\n" << std::endl;
    }
    if (chosen == "cuda" && !gpuAvailable())
    {
        const std::string why = cudaDeviceInfo().reason;
        const std::string what = "device cuda was asked for, but no GPU can"
            " be used: " + why + ". Run on the CPU with -device cpu (or"
            " device cpu; in system/controlDict), or let -device auto fall"
            " back to it";
        if (device.empty())
        {
            fatalIOError((caseDir/"system/controlDict").string(),
                control_.dict.lookupEntry("device").line(), what, "device");
        }
        fatalError(what);
    }
    else if (chosen != "cpu" && chosen != "cuda")
    {
        fatalError("device " + chosen + ": expected cpu, cuda or auto (from"
            " -device,"
            " $SPHVCPM_DEVICE or the device entry of system/controlDict)");
    }
    readStartTime();
    setSoundSpeed();
    eos_ = taitEquationOfState(model_.rho0, model_.c0, model_.gamma);
    if (freshStart_ && model_.hydrostaticStart)
    {
        setHydrostaticDensity();
    }
    setDomain(chosen == "cuda");

    std::vector<std::string> dampingLog;    // one line per zone
    model_.damping = readDampingZones(caseDir_, model_.nDimensions,
                                      &dampingLog);
    log_<< "Fluid model\n"
        << "    kernel " << kernelName(model_.kernel)
        << ", h = " << model_.hOverDp << " dp = " << model_.h << " m"
        << ", cells of 2h/" << model_.cellDivisor << "\n"
        << "    Tait EOS: rho0 = " << model_.rho0 << " kg/m^3, c0 = "
        << model_.c0 << " m/s, gamma = " << model_.gamma << "\n"
        << "    density diffusion "
        << densityDiffusionName(model_.densityDiffusion)
        << " (delta " << model_.delta << ")\n"
        << "    viscosity " << viscosityName(model_.viscosity);
    if (model_.viscosity == viscosityType::laminar)
    {
        log_<< " (nu " << model_.nu << " m^2/s)";
    }
    else
    {
        log_<< " (alpha " << model_.alpha << ")";
    }
    log_<< ", turbulence " << (model_.sps ? "SPS" : "off") << "\n"
        << "    shifting " << shiftingName(model_.shifting)
        << ", walls: Adami extrapolated pressure, contact push "
        << (model_.contact > 0 ? str(model_.contact) + " within "
                                 + str(boundaryContact::kappa)
                                 + " (dp + dp_b)/2"
                               : std::string("off")) << "\n"
        << "    damping zones"
        << (dampingLog.empty() ? " none" : ":") << "\n";
    for (const std::string& line : dampingLog)
    {
        log_<< "        " << line << "\n";
    }
    log_<< "    time scheme " << timeSchemeName(model_.timeScheme)
        << (model_.timeScheme == timeSchemeType::verlet
            ? " (one force pass a step; an Euler step every "
              + std::to_string(model_.verletSteps) + " steps and after"
              " each write)"
            : std::string(" (two force passes a step)")) << "\n";
    if (!control_.adjustTimeStep && postProcessTime_.empty())
    {
        // A fixed step beyond the acoustic limit blows up within a few
        // steps, whatever the flow: say so before the run.
        const double acoustic = control_.maxCo*model_.h/model_.c0;
        if (control_.deltaT > acoustic)
        {
            const entry& deltaT = control_.dict.lookupEntry("deltaT");
            warning("adjustTimeStep no with deltaT " + str(control_.deltaT)
                + " s, above the acoustic limit maxCo h/c0 = "
                + str(acoustic) + " s (maxCo " + str(control_.maxCo) + ", h "
                + str(model_.h) + " m, c0 " + str(model_.c0) + " m/s): the"
                " run is likely to blow up. Lower deltaT or set"
                " adjustTimeStep yes", deltaT.file(), deltaT.line());
        }
    }
    if (model_.timeScheme == timeSchemeType::verlet
     && postProcessTime_.empty())
    {
        // The leapfrog centres density diffusion, which then grows between
        // the Euler steps by about 2 delta maxCo a step (docs/solver.md).
        const bool adaptive = control_.adjustTimeStep;
        if (model_.verletSteps > verletTestedSteps || !adaptive
         || control_.maxCo > verletTestedMaxCo
         || (model_.densityDiffusion != densityDiffusionType::none
          && model_.delta > verletTestedDelta))
        {
            warning("timeScheme verlet was found stable with "
                + verletTestedLimits + ";"
                " this case has verletSteps " + std::to_string(
                model_.verletSteps) + ", maxCo " + str(control_.maxCo)
                + (adaptive ? "" : " (adjustTimeStep no)") + " and delta "
                + str(model_.delta) + ". Beyond them density diffusion grows"
                " between the Euler steps: in a small dam break verletSteps"
                " 60, delta 0.2, and maxCo 0.4 even with verletSteps 20 each"
                " blew up. Use timeScheme symplectic for larger steps",
                (caseDir_/"system/sphSchemes").string());
        }
    }
    if (coupling_ && hasWalls_)
    {
        log_<< "    solid-wall contact: hard, at a gap of dp_s/2 to the nearest"
            << " wall particle's surface\n";
    }
    if (coupling_)
    {
        reportSubCycling();
    }
    log_
        << "    g = " << str(model_.g)
        << gravityDefaultNote(caseDir_, model_.nDimensions) << "\n"
        << "    domain " << str(grid_.origin) << " "
        << grid_.nx << " x " << grid_.ny << " x " << grid_.nz
        << " cells of " << grid_.cellSize << " m\n"
        << "    " << particles_.bytesPerParticle() + sizeof(std::uint8_t)
        << " bytes per particle and "
        << 3*sizeof(label) << " per cell\n" << std::endl;

    control_.dict.setCaseDimensions(model_.nDimensions);
    if (postProcessTime_.empty())
    {
        functions_ = functionObject::readAll(control_.dict, caseDir_,
            startTimeName_, model_, bodies_);
    }

    hostParticleStore store = hostStore();
    sortOn(store);
    parallelFor(openmpExec{}, particles_.size(),
        pressureOp{particles_.view(), eos_});
    updateWallsOn(store);
    wallsFreshIndex_ = timeIndex_;

    if (chosen == "cuda")
    {
        // The particles move to the GPU once; they come back for writes,
        // function objects and diagnoses.
        startGpu();
        log_<< "Device: " << cudaDeviceInfo().describe() << "\n"
            << std::endl;
    }
}


fsiSolver::~fsiSolver() = default;


std::string startTimeName(const fs::path& caseDir,
                          const timeControl& control)
{
    const auto times = findTimes(caseDir);
    const std::string controlFile = (caseDir/"system/controlDict").string();
    if (times.empty())
    {
        fatalError("No time directory in " + caseDir.string()
            + ": run generateParticles first to write 0/");
    }
    switch (control.startFrom)
    {
        case startFromType::latestTime:
            return times.back().name;
        case startFromType::firstTime:
            return times.front().name;
        case startFromType::startTime:
            break;
    }
    auto it = std::find_if(times.begin(), times.end(),
        [&](const timeInstant& t)
        {
            return std::fabs(t.value - control.startTime)
                <= 1e-12*std::max(1.0, std::fabs(t.value));
        });
    if (it == times.end())
    {
        std::string list;
        for (const auto& t : times) list += " " + t.name;
        fatalIOError(controlFile,
            control.dict.lookupEntry("startTime").line(),
            "startTime " + str(control.startTime)
            + " has no time directory; the case has:" + list,
            "startTime");
    }
    return it->name;
}


void fsiSolver::blownUpStart(const std::string& timeFile) const
{
    const std::string message = "Time " + startTimeName_ + " is the state a"
        " blown-up run stopped at (blowUp in " + timeFile + "): it may be"
        " bad already";
    if (!postProcessTime_.empty())
    {
        return;
    }
    if (control_.startFrom != startFromType::startTime)
    {
        fatalIOError(timeFile, 0, message + ". The run does not go on from"
            " it: remove " + startTimeName_ + "/ to go on from the write"
            " before it, or name it in system/controlDict (startFrom"
            " startTime; startTime " + startTimeName_ + ";) to try anyway",
            "blowUp");
    }
    warning(message + "; started from it as system/controlDict asks"
        " (startFrom startTime)", timeFile);
}


void fsiSolver::readStartTime()
{
    startTimeName_ = postProcessTime_.empty()
        ? startTimeName(caseDir_, control_) : postProcessTime_;

    const timeState state = readTimeState(caseDir_, startTimeName_);
    // Index 0: the initial state (generateParticles), not a solver write.
    freshStart_ = state.index == 0;
    restartC0_ = state.solverValue("c0", 0);
    // The one value this solver keeps in uniform/time: an edited or
    // misspelt one would be passed over and c0 derived afresh.
    const std::string timeFile =
        (caseDir_/startTimeName_/"uniform"/"time").string();
    for (const auto& [key, value] : state.solverValues)
    {
        if (key == "blowUp")
        {
            blownUpStart(timeFile);
            continue;
        }
        if (key != "c0")
        {
            fatalIOError(timeFile, 0, "Unknown keyword '" + key + "' in "
                + timeFile + ": the solver writes only c0 and blowUp there"
                  " besides the time (value, name, index, deltaT, deltaT0,"
                  " beginTime)", key);
        }
        if (!(value > 0))
        {
            fatalIOError(timeFile, 0, "Keyword 'c0' in " + timeFile
                + ": the speed of sound the run started with must be > 0,"
                  " found " + str(value), "c0");
        }
    }
    time_ = state.value;
    timeIndex_ = state.index;
    beginTime_ = time_;
    deltaT_ = control_.deltaT;
    deltaT0_ = state.deltaT > 0 ? state.deltaT : control_.deltaT;

    if (postProcessTime_.empty())
    {
        // (Post-processing leaves them: the solver may be writing now.)
        clearInterruptedWrites(caseDir_, log_);
    }
    warnUnreadConstantFiles(caseDir_);
    log_<< "Reading time " << startTimeName_ << "\n";
    std::vector<particleBody> bodies =
        readTimeDirectory(caseDir_, startTimeName_);
    checkStartState(caseDir_, startTimeName_, bodies, state, false, log_);

    int nDim = 0;
    scalar dp = 0;
    label nTotal = 0;
    for (const particleBody& b : bodies)
    {
        if (b.type() == bodyType::fluid && dp == 0)
        {
            dp = b.dp();
        }
        if (nDim != 0 && b.nDimensions() != nDim)
        {
            fatalError("Bodies of time " + startTimeName_ + " disagree on"
                " nDimensions (" + b.name() + " has "
                + std::to_string(b.nDimensions()) + ")");
        }
        nDim = b.nDimensions();
        nTotal += b.size();
    }
    if (dp == 0)
    {
        fatalError("Time " + startTimeName_ + " of " + caseDir_.string()
            + " has no fluid body: sphVcpmFsi needs one");
    }
    if (bodies.size() > 250)
    {
        fatalError("More than 250 bodies are not supported");
    }
    for (const particleBody& b : bodies)
    {
        if (b.type() == bodyType::solid)
        {
            // Multi-resolution: dp_s = dp_f/r (docs/fsi.md, The coupling).
            const scalar r = dp/b.dp();
            const scalar rInt = std::round(r);
            if (rInt < 1 || rInt > 4 || std::fabs(r - rInt) > 1e-6*r)
            {
                fatalError("Solid " + b.name() + " has dp " + str(b.dp())
                    + " but the fluid has dp " + str(dp) + ": a solid's"
                      " spacing must be the fluid's divided by 1, 2, 3 or"
                      " 4 (its ratio is " + str(r) + ")");
            }
        }
        else if (std::fabs(b.dp() - dp) > 1e-9*dp)
        {
            fatalError("Body " + b.name() + " has dp " + str(b.dp())
                + " but the fluid has dp " + str(dp) + ": fluid and wall"
                  " particles must share one spacing");
        }
    }

    model_ = readSphModel(caseDir_, nDim, dp);

    particles_.resize(nTotal, model_.sps,
                      model_.shifting != shiftingType::none,
                      model_.timeScheme == timeSchemeType::verlet);
    solids_ = std::make_unique<solidBodySet>(caseDir_, startTimeName_, bodies,
                                             freshStart_, model_.g, log_);
    warnLightSolids(*solids_, model_);
    motions_ = prescribedMotions(caseDir_, bodies, nDim, true, log_);
    if (freshStart_)
    {
        motions_.placeSolids(*solids_, time_);
        motions_.checkWavemakerDepths(bodies, model_.g, dp);
    }
    else
    {
        motions_.checkRestart(caseDir_, startTimeName_, time_, bodies,
                              *solids_);
    }
    if (!solids_->empty())
    {
        coupling_ = std::make_unique<fluidSolidCoupling>(*solids_);
        coupling_->setClampMotions(motions_.clampMotions(*solids_));
        particles_.link.assign(nTotal, -1);
        for (const solidBody& b : solids_->bodies())
        {
            solidViews_.push_back({b.name, &b.solid->reference(),
                &b.solid->position,
                coupling_->index(solidViews_.size(), 0)});
        }
        // A restart: the mean velocity the fluid saw when it was written.
        std::size_t solid = 0;
        for (const particleBody& body : bodies)
        {
            if (body.type() != bodyType::solid) continue;
            if (body.hasField("Umean"))
            {
                const std::vector<vec3>& u = body.vectorField("Umean");
                for (label i = 0; i < body.size(); ++i)
                {
                    coupling_->meanVelocity[coupling_->index(solid, i)] = u[i];
                }
            }
            ++solid;
        }
    }
    label nextSolid = 0;   // the solids' order in the coupling arrays
    const scalar defaultMass = model_.rho0*std::pow(dp, nDim);
    const scalar massTolerance =
        std::max(1e-3, 5*std::pow(10.0, -control_.writePrecision));
    label k = 0;
    for (std::size_t b = 0; b < bodies.size(); ++b)
    {
        const particleBody& body = bodies[b];
        bodies_.push_back({body.name(), body.type(), body.dp(), 0});
        hasWalls_ |= body.type() == bodyType::wall;
        const label n = body.size();
        const auto& x = body.position();
        const auto& ids = body.id();
        const bool hasU = body.hasField("U");
        const bool hasRho = body.hasField("rho");
        const bool hasMass = body.hasField("mass");
        if (body.type() == bodyType::solid)
        {
            // A moving wall to the fluid, with the fluid-side mass
            // rho0_f dp_s^d (docs/fsi.md, The coupling).
            const scalar fluidSideMass =
                model_.rho0*std::pow(body.dp(), nDim);
            for (label i = 0; i < n; ++i, ++k, ++nextSolid)
            {
                particles_.position[k] = coupling_->position[nextSolid];
                particles_.velocity[k] = coupling_->meanVelocity[nextSolid];
                particles_.rho[k] = model_.rho0;
                particles_.mass[k] = fluidSideMass;
                particles_.kind[k] = solidKind;
                particles_.body[k] = std::uint8_t(b);
                particles_.id[k] = ids[i];
                particles_.link[k] = nextSolid;
            }
            continue;
        }
        for (label i = 0; i < n; ++i, ++k)
        {
            particles_.position[k] = x[i];
            particles_.velocity[k] =
                hasU ? body.vectorField("U")[i] : vec3{0, 0, 0};
            particles_.rho[k] =
                hasRho ? body.scalarField("rho")[i] : model_.rho0;
            particles_.mass[k] =
                hasMass ? body.scalarField("mass")[i] : defaultMass;
            particles_.kind[k] =
                body.type() == bodyType::fluid ? fluidKind : wallKind;
            particles_.body[k] = std::uint8_t(b);
            particles_.id[k] = ids[i];
            if (!(particles_.rho[k] > 0) || !(particles_.mass[k] > 0))
            {
                fatalError("Body " + body.name() + " of time "
                    + startTimeName_ + ": particle id "
                    + std::to_string(ids[i]) + " has a non-positive"
                    " density or mass");
            }
            // Every fluid and wall particle carries rho0 dp^d: a mass of
            // another density (a wall given its material's rho, rho0
            // changed since generateParticles) would make walls push as
            // if denser, or a second fluid the equation of state undoes.
            // Those are off by per cents; ascii masses carry the rounding
            // of their digits.
            if (std::fabs(particles_.mass[k] - defaultMass)
                > massTolerance*defaultMass)
            {
                fatalError("Body " + body.name() + " of time "
                    + startTimeName_ + ": particle id "
                    + std::to_string(ids[i]) + " has mass "
                    + str(particles_.mass[k]) + ", a density of "
                    + str(particles_.mass[k]/defaultMass*model_.rho0)
                    + " kg/m^3"
                    " over dp^" + std::to_string(nDim) + ", but rho0 of"
                    " constant/fluidProperties is " + str(model_.rho0)
                    + ": fluid and wall particles all carry the fluid's"
                    " density (one fluid phase; a rigid wall's material does"
                    " not enter). Run generateParticles again after changing"
                    " rho0, without rho in fluid or wall bodies");
            }
        }
        log_<< "    " << body.name() << " (" << bodyTypeName(body.type())
            << "): " << n << " particles\n";
    }
    if (coupling_ && hasWalls_) coupling_->useContact();
    log_<< "    dp = " << dp << " m, " << nDim << "D, time = " << time_
        << "\n" << std::endl;
    if (postProcessTime_.empty())
    {
        checkWallThickness(bodies);
    }
    placeMovingWalls();
    if (postProcessTime_.empty())
    {
        checkClampsFollowWalls();
    }
}


void fsiSolver::checkClampsFollowWalls() const
{
    if (!wallsMove_ || !solids_) return;
    const std::vector<const rigidMotion*> clampMotion =
        motions_.clampMotions(*solids_);
    const auto& solids = solids_->bodies();
    scalar reach = 0;
    for (const solidBody& s : solids) reach = std::max(reach, s.dp);
    for (std::size_t b = 0; b < bodies_.size(); ++b)
    {
        const rigidMotion* wallMotion = motions_.of(b);
        if (bodies_[b].type != bodyType::wall || !wallMotion) continue;
        std::vector<vec3> wall;
        for (label i = 0; i < particles_.size(); ++i)
        {
            if (particles_.body[i] == b)
            {
                wall.push_back(toVec3(particles_.position[i]));
            }
        }
        // Touching: within a spacing of the wall's particles, about where
        // generateParticles puts a solid's clamped root beside a wall.
        const pointLocator near(std::move(wall), bodies_[b].dp + reach);
        for (std::size_t k = 0; k < solids.size(); ++k)
        {
            if (clampMotion[k] == wallMotion) continue;
            const vcpmSolid& solid = *solids[k].solid;
            label nNear = 0;
            for (label i = 0; i < solid.size(); ++i)
            {
                const vec3 x = toVec3(solid.position[i]);
                if (solid.clamped()[i]
                 && near.nearestWithinCell(x) < bodies_[b].dp + solids[k].dp)
                {
                    ++nNear;
                }
            }
            if (nNear == 0) continue;
            warning("Solid '" + solids[k].name + "' is clamped next to wall '"
                + bodies_[b].name + "' (" + std::to_string(nNear)
                + " clamped particles within a spacing of it), which moves"
                " by constant/motion while the clamp "
                + (clampMotion[k] ? "follows another motion"
                   : "stays where it is (the solid is in no motion)")
                + ": the wall will move through the solid's root. To carry"
                " the clamp with the wall, name " + solids[k].name
                + " among the bodies of " + bodies_[b].name + "'s motion"
                " (bodies (" + bodies_[b].name + " " + solids[k].name
                + ");)", (caseDir_/"constant/motion").string());
        }
    }
}


void fsiSolver::placeMovingWalls()
{
    wallMoves_.assign(bodies_.size(), bodyMove::none());
    wallTime_ = time_;
    for (std::size_t b = 0; b < bodies_.size(); ++b)
    {
        if (bodies_[b].type != bodyType::wall || !motions_.of(b)) continue;
        wallsMove_ = true;
        wallMoves_[b] = motions_.move(b, time_, time_);
        // A fresh case is generated in the reference configuration; a
        // restart's walls are already where their motion puts them.
        const rigidTransform T = motions_.of(b)->transform(time_);
        scalar moved = 0;
        std::vector<vec3> placed;
        for (label i = 0; i < particles_.size(); ++i)
        {
            if (particles_.body[i] != b) continue;
            point& x = particles_.position[i];
            if (freshStart_)
            {
                const point to = T.apply(x);
                moved = std::max(moved, mag(toVec3(to - x)));
                x = to;
                placed.push_back(toVec3(x));
            }
            particles_.velocity[i] = T.velocityAtPosition(x);
        }
        if (moved > 0)
        {
            checkStartOverlap("Wall " + bodies_[b].name, bodies_[b].dp,
                              std::move(placed), moved);
        }
    }
    if (!freshStart_ || !solids_) return;
    // Solids that their clamp's motion placed (prescribedMotions::
    // placeSolids), rigidly, as a whole.
    for (const solidBody& s : solids_->bodies())
    {
        scalar moved = 0;
        std::vector<vec3> placed;
        for (label i = 0; i < s.solid->size(); ++i)
        {
            moved = std::max(moved, mag(toVec3(s.solid->position[i]
                                             - s.solid->reference()[i])));
            placed.push_back(toVec3(s.solid->position[i]));
        }
        if (moved > 0)
        {
            checkStartOverlap("Solid " + s.name, s.dp, std::move(placed),
                              moved);
        }
    }
}


void fsiSolver::checkWallThickness(const std::vector<particleBody>& bodies)
{
    const scalar support = 2*model_.h;
    // The layers that fill the support of fluid touching a body of dp.
    auto layersNeeded = [&](const scalar dp)
    {
        return label(std::ceil(support/dp - 1e-6));
    };
    auto warnThin = [&](const particleBody& body, const label layers,
                        const vec3& at)
    {
        const label needed = layersNeeded(body.dp());
        const std::string where = std::to_string(layers) + " layers ("
            + str(layers*body.dp()) + " m) thick near " + str(at)
            + ", thinner than the kernel's support 2h = " + str(support)
            + " m (hOverDp " + str(model_.hOverDp) + ")";
        if (body.type() == bodyType::solid)
        {
            // A thin plate is what the solid is; its load converges with
            // the fluid's resolution all the same (docs/fsi.md).
            log_<< "    solid " << body.name() << ": " << where << ": fluid"
                << " on both its sides interacts across it at this"
                << " resolution\n";
            return;
        }
        warning("Wall '" + body.name() + "' has a member only " + where
            + ": fluid beside it sees too little wall, so its wall pressure"
            " is low and particles can pass through it (and fluid on both"
            " sides of a thin wall interacts across it). Give it at least "
            + std::to_string(needed) + " layers (layers "
            + std::to_string(needed) + " of a container or surface), or"
            " lower hOverDp", (caseDir_/"system/sphSchemes").string());
    };

    // The points measured for a body: a solid's reference lattice (a
    // restart reads it deformed), a wall's positions.
    std::size_t solid = 0;
    std::vector<std::size_t> solidIndex(bodies.size(), 0);
    for (std::size_t b = 0; b < bodies.size(); ++b)
    {
        if (bodies[b].type() == bodyType::solid) solidIndex[b] = solid++;
    }
    auto pointsOf = [&](const std::size_t b)
    {
        const particleBody& body = bodies[b];
        return toVectors(body.type() == bodyType::solid
            ? solids_->bodies()[solidIndex[b]].solid->reference()
            : body.position());
    };

    // Walls that stay put, share a spacing and lie on one lattice are
    // measured together: a wall resting on another (a beach on the floor)
    // is as thick as both. A wall on a shifted lattice (its own
    // latticeOrigin) forms a group of its own, so it does not keep the
    // others from being measured together; a moving wall, and a solid, are
    // measured on their own.
    auto joins = [&](const std::size_t b)
    {
        return bodies[b].type() == bodyType::wall && !motions_.of(b);
    };
    std::vector<std::vector<std::size_t>> groups;
    // A node of each group's lattice; whether others may join it (a static
    // wall on one lattice).
    std::vector<vec3> groupOrigin;
    std::vector<bool> groupOpen;
    for (std::size_t b = 0; b < bodies.size(); ++b)
    {
        const particleBody& body = bodies[b];
        if (body.type() == bodyType::fluid || body.size() == 0
         || layersNeeded(body.dp()) < 2)
        {
            continue;
        }
        const std::vector<vec3> x = pointsOf(b);
        const bool open = joins(b) && onOneLattice(x, body.dp());
        std::size_t g = groups.size();
        for (std::size_t i = 0; open && i < groups.size(); ++i)
        {
            if (groupOpen[i] && bodies[groups[i].front()].dp() == body.dp()
             && onLatticeThrough(x, groupOrigin[i], body.dp()))
            {
                g = i;
                break;
            }
        }
        if (g < groups.size())
        {
            groups[g].push_back(b);
            continue;
        }
        groups.push_back({b});
        groupOrigin.push_back(x.front());
        groupOpen.push_back(open);
    }

    // Measures the bodies of a group as one (all on one lattice, by the
    // grouping) and warns for each body with a member that is too thin.
    for (const std::vector<std::size_t>& group : groups)
    {
        std::vector<vec3> points;
        std::vector<label> owner;
        for (std::size_t i = 0; i < group.size(); ++i)
        {
            const std::vector<vec3> x = pointsOf(group[i]);
            points.insert(points.end(), x.begin(), x.end());
            owner.insert(owner.end(), x.size(), label(i));
        }
        const particleBody& front = bodies[group.front()];
        const scalar dp = front.dp();
        if (!onOneLattice(points, dp))
        {
            log_<< "    " << bodyTypeName(front.type()) << " "
                << front.name() << ": not on one lattice (turned by its"
                << " motion, or from elsewhere): its thickness is not"
                << " measured\n";
            continue;
        }
        const std::vector<latticeMembers> thin = findThinMembersByOwner(
            points, owner, label(group.size()), dp, model_.nDimensions,
            layersNeeded(dp), true);
        for (std::size_t i = 0; i < group.size(); ++i)
        {
            if (thin[i].thinnestLayers >= 0)
            {
                warnThin(bodies[group[i]], thin[i].thinnestLayers,
                         points[thin[i].where]);
            }
        }
    }
}


void fsiSolver::checkStartOverlap(const std::string& what, const scalar dpWall,
                                  std::vector<vec3> placed,
                                  const scalar distance)
{
    // The fluid was generated around the body's reference position: a
    // motion already under way at the start time puts the body into it,
    // which then bursts out (Mach above 1 in a piston flume). The gap is
    // at most the largest spacing, the locator's reach.
    scalar reach = dpWall;
    for (const bodyInfo& b : bodies_) reach = std::max(reach, b.dp);
    const pointLocator body(std::move(placed), reach);
    label nClose = 0;
    scalar nearest = vGreat;
    std::string fluidName;
    for (label i = 0; i < particles_.size(); ++i)
    {
        if (particles_.kind[i] != fluidKind) continue;
        const scalar gap = 0.5*(bodies_[particles_.body[i]].dp + dpWall);
        const scalar d = body.nearestWithinCell(toVec3(particles_.position[i]));
        // generateParticles keeps the fluid at the gap or beyond.
        if (d < 0.9*gap)
        {
            ++nClose;
            nearest = std::min(nearest, d);
            fluidName = bodies_[particles_.body[i]].name;
        }
    }
    if (nClose > 0)
    {
        warning(what + " is moved " + str(distance)
            + " m by its motion at the start time " + str(time_) + " (from"
            " where generateParticles put it), into the fluid: "
            + std::to_string(nClose) + " particles of " + fluidName
            + " lie closer to it than the contact gap (the nearest "
            + str(nearest) + " m). They will burst out at the first steps."
            " Start the motion at its reference position (0 at the start"
            " time), or generate the particles where it starts",
            (caseDir_/"constant/motion").string());
    }
}


void fsiSolver::setSoundSpeed()
{
    // Fluid height H along gravity and the largest initial speed.
    const scalar gMag = mag(model_.g);
    const vec3 up = gMag > 0 ? (-1/gMag)*model_.g : vec3{0, 0, 0};
    scalar lo = std::numeric_limits<scalar>::max(), hi = -lo, u2 = 0;
    label fastest = -1;
    for (label i = 0; i < particles_.size(); ++i)
    {
        if (particles_.kind[i] != fluidKind) continue;
        const scalar z = dot(toPoint(up), particles_.position[i]);
        lo = std::min(lo, z);
        hi = std::max(hi, z);
        if (magSqr(particles_.velocity[i]) > u2)
        {
            u2 = magSqr(particles_.velocity[i]);
            fastest = i;
        }
    }
    // No fluid particle (all left the domain before this restart): no
    // height, and nothing for the checks below to weigh.
    fluidHeight_ = gMag > 0 && hi >= lo ? hi - lo + model_.dp : 0;

    const std::string file = (caseDir_/"constant/fluidProperties").string();
    const bool speedGiven = model_.speedSystem > 0;
    const scalar speedSystem = speedGiven
      ? model_.speedSystem : std::sqrt(gMag*fluidHeight_);
    if (model_.coefSound > 0 && restartC0_ > 0)
    {
        // The c0 of the run's start: a restart must not re-derive it from
        // the scene as it is now.
        model_.c0 = restartC0_;
    }
    else if (model_.coefSound > 0)
    {
        model_.c0 = model_.coefSound*std::max(speedSystem, std::sqrt(u2));
        if (std::sqrt(u2) > speedSystem)
        {
            // One damaged velocity can set it (and so every step): say
            // which particle does.
            log_<< "c0 = coefSound x " << std::sqrt(u2) << " m/s, the"
                << " initial speed of " << describeParticle(fastest)
                << ", above the scene's " << speedSystem << " m/s\n";
        }
        if (!(model_.c0 > 0))
        {
            fatalIOError(file, 0, "coefSound needs gravity or an initial"
                " velocity to set c0; give c0 instead", "coefSound");
        }
    }

    if (!postProcessTime_.empty())
    {
        return;   // the run weighed c0 against the scene; nothing runs here
    }

    // Weak compressibility needs c0 >= 10 U; the largest speed expected is
    // the case's speedSystem, else the free-fall speed over the fluid
    // height, or the initial speed if larger. A restart with the c0 it ran
    // with weighs the flow as read (and speedSystem): the scene was weighed
    // at the run's start, and its height now (a tilted tank) says nothing
    // new. A c0 changed since is weighed against the scene again.
    const bool sameC0 = !freshStart_ && restartC0_ > 0
                     && model_.c0 == restartC0_;
    const scalar uScene = speedGiven ? model_.speedSystem
      : sameC0 ? 0 : std::sqrt(2*gMag*fluidHeight_);
    // The moving walls and clamps drive the fluid at their own speed (a
    // stroke in mm read as m is one 1000 times too fast).
    scalar uWalls = 0;
    std::size_t fastestBody = 0;
    double fastestTime = 0;
    forEachMovedCorner([&](std::size_t b, double t, const point& x)
    {
        const scalar u =
            mag(motions_.of(b)->transform(t).velocityAtPosition(x));
        if (u <= uWalls) return;
        uWalls = u;
        fastestBody = b;
        fastestTime = t;
    });
    const std::string walls = uWalls > 0
      ? "the bodies of motion " + motions_.nameOf(fastestBody)
        + " (constant/motion, lengths in m) move at up to "
        + str(uWalls, 4) + " m/s (body " + bodies_[fastestBody].name
        + ", time " + str(fastestTime, 4) + " s)"
      : "";
    const scalar uExpected = std::max({uScene, std::sqrt(u2), uWalls});
    const scalar c0Min = 10*uExpected;
    if (model_.c0 < 3*uExpected)
    {
        const std::string reaches = uWalls == uExpected ? walls
          : uScene < std::sqrt(u2)
          ? "the fluid moves at up to " + str(uExpected) + " m/s"
          : speedGiven
          ? "the fluid reaches about " + str(uExpected) + " m/s (speedSystem)"
          : "the fluid (height " + str(fluidHeight_) + " m) reaches about "
            + str(uExpected) + " m/s";
        fatalIOError(file, 0, "the speed of sound c0 = " + str(model_.c0)
            + " m/s is far too low for this scene: " + reaches + ", so c0"
            " must be at least 10 times that, " + str(c0Min) + " m/s"
            " (density errors grow as (U/c0)^2)", "c0");
    }
    if (model_.c0 < c0Min)
    {
        warning("The speed of sound c0 = " + str(model_.c0) + " m/s is below "
            + str(c0Min) + " m/s, 10 times the speed expected in this scene"
            " (" + (uWalls == uExpected ? walls : str(uExpected) + " m/s")
            + "): expect density errors of about "
            + str(100*uExpected*uExpected/(model_.c0*model_.c0), 2) + " %",
            file);
    }
}


void fsiSolver::setHydrostaticDensity()
{
    // rho = rho0 (1 + rho0 |g| (top - z)/B)^(1/gamma) below the top of each
    // fluid body (its highest particle + dp/2), so that a still fluid
    // starts at rest instead of settling through pressure waves.
    const scalar gMag = mag(model_.g);
    if (gMag == 0) return;
    const vec3 up = (-1/gMag)*model_.g;
    std::vector<scalar> top(bodies_.size(), -vGreat);
    for (label i = 0; i < particles_.size(); ++i)
    {
        if (particles_.kind[i] != fluidKind) continue;
        scalar& t = top[particles_.body[i]];
        t = std::max(t, scalar(dot(toPoint(up), particles_.position[i]))
                        + scalar(0.5)*model_.dp);
    }
    for (label i = 0; i < particles_.size(); ++i)
    {
        if (particles_.kind[i] != fluidKind) continue;
        const scalar depth =
            top[particles_.body[i]]
          - scalar(dot(toPoint(up), particles_.position[i]));
        particles_.rho[i] = eos_.density(model_.rho0*gMag*depth);
    }
    log_<< "Initial fluid density: hydrostatic below the top of each fluid"
        << " body\n" << std::endl;
}


namespace
{

void grow(point& lo, point& hi, const point& x)
{
    for (int d = 0; d < 3; ++d)
    {
        lo[d] = std::min(lo[d], x[d]);
        hi[d] = std::max(hi[d], x[d]);
    }
}

} // End anonymous namespace


void fsiSolver::forEachMovedCorner(const std::function<void(std::size_t b,
    double t, const point& x)>& f) const
{
    for (std::size_t b = 0; b < bodies_.size(); ++b)
    {
        if (!motions_.of(b)) continue;
        point blo{vGreat, vGreat, vGreat}, bhi = -blo;
        for (label i = 0; i < particles_.size(); ++i)
        {
            if (particles_.body[i] != b) continue;
            grow(blo, bhi, particles_.position[i]);
        }
        if (blo.x > bhi.x) continue;    // no particle left
        const int nSamples = 2000;
        for (int k = 0; k <= nSamples; ++k)
        {
            const double t = time_
              + (control_.endTime - time_)*double(k)/nSamples;
            const bodyMove m = motions_.move(b, time_, t);
            for (int c = 0; c < 8; ++c)
            {
                const point corner{c & 1 ? bhi.x : blo.x,
                    c & 2 ? bhi.y : blo.y, c & 4 ? bhi.z : blo.z};
                f(b, t, m.moved(corner));
            }
        }
    }
}


void fsiSolver::growByMotions(point& lo, point& hi)
{
    // Moving bodies: their box wherever their motion takes them up to
    // endTime.
    forEachMovedCorner([&](std::size_t, double, const point& x)
    {
        grow(lo, hi, x);
    });
}


void fsiSolver::checkMotionsInDomain()
{
    // endTime raised while the run goes on: the domain was sized for the
    // motions up to the old one, and cannot grow now.
    motionsCheckedUntil_ = control_.endTime;
    if (motions_.empty() || model_.userDomain) return;
    if (gpu_) gpuToHost();
    point lo{vGreat, vGreat, vGreat}, hi = -lo;
    growByMotions(lo, hi);
    for (int d = 0; d < model_.nDimensions; ++d)
    {
        if (lo[d] < model_.domainMin[d] || hi[d] > model_.domainMax[d])
        {
            warning("With endTime " + str(control_.endTime) + " the moving"
                " bodies leave the domain " + str(model_.domainMin) + " to "
                + str(model_.domainMax) + ", which was sized for their"
                " motion up to endTime " + str(domainEndTime_) + " when the run"
                " started: the run stops when a wall particle leaves it. To"
                " go on past that, stop the run (stopAt writeNow) and start"
                " it again from its latest time, which sizes the domain"
                " anew");
            return;
        }
    }
}


void fsiSolver::setDomain(const bool onGpu)
{
    point lo, hi;
    if (model_.userDomain)
    {
        lo = toPoint(model_.domainMin);
        hi = toPoint(model_.domainMax);
    }
    else
    {
        // Bounding box of all particles with a margin; against gravity the
        // box doubles, so that splashes are not lost.
        lo = point{vGreat, vGreat, vGreat};
        hi = -lo;
        for (const point& x : particles_.position) grow(lo, hi, x);
        growByMotions(lo, hi);
        const scalar gMag = mag(model_.g);
        for (int d = 0; d < model_.nDimensions; ++d)
        {
            const scalar size = hi[d] - lo[d];
            const scalar margin = 0.1*size + 2*model_.h;
            lo[d] -= margin;
            hi[d] += margin;
            if (gMag > 0 && model_.g[d] < -0.5*gMag)
            {
                hi[d] += size;
            }
            else if (gMag > 0 && model_.g[d] > 0.5*gMag)
            {
                lo[d] -= size;
            }
        }
    }
    if (model_.cellDivisor == 0)
    {
        model_.cellDivisor = defaultCellDivisor(lo, hi, 2*model_.h,
            model_.nDimensions, particles_.size(), onGpu);
    }
    grid_ = makeCellGrid(lo, hi, 2*model_.h, model_.cellDivisor,
                         model_.nDimensions);
    model_.domainMin = toVec3(lo);
    model_.domainMax = toVec3(hi);
    domainEndTime_ = motionsCheckedUntil_ = control_.endTime;
}


// * * * * * * * * * * * * * * * * * * Steps  * * * * * * * * * * * * * * * //

hostParticleStore fsiSolver::hostStore()
{
    return {particles_, cells_, nearFluid_, viscTerm_};
}


void fsiSolver::reportSubCycling()
{
    // The fluid's acoustic step at rest, the usual step of a run: how many
    // solid steps each one holds. Thousands make a run crawl, most often
    // from a wrong E or rho (a unit slip), so say so before it starts.
    const double fluidDt = control_.adjustTimeStep
      ? std::min(double(control_.maxCo*model_.h/model_.c0),
                 control_.maxDeltaT)
      : control_.deltaT;
    constexpr double manySubSteps = 1000;
    for (const solidBody& b : solids_->bodies())
    {
        const double n = std::ceil(fluidDt/b.stableDeltaT);
        log_<< "    solid " << b.name << ": about " << n
            << " sub-steps of " << b.stableDeltaT << " s per fluid step of "
            << fluidDt << " s\n";
        if (n > manySubSteps)
        {
            warning("Solid '" + b.name + "' needs about " + str(n)
                + " sub-steps in each fluid step (its stable step "
                + str(b.stableDeltaT) + " s against the fluid's "
                + str(fluidDt) + " s): the run will be slow. Check its E,"
                " nu and rho in constant/solidProperties",
                (caseDir_/"constant/solidProperties").string());
        }
    }
}


double fsiSolver::chooseDeltaT(const scalar maxAcc2, const scalar maxVisc,
                               const scalar maxVel2)
{
    // The largest fluid speed of the run, for its Mach number (summary).
    if (maxVel2 > maxSpeed2_)
    {
        maxSpeed2_ = maxVel2;
        maxSpeedTime_ = time_;
    }

    // The step is bookkeeping (double); the limits come from the physics.
    double dt = control_.deltaT;
    if (control_.adjustTimeStep)
    {
        // Force and acoustic-viscous limits (DualSPHysics; docs/solver.md,
        // Equations, time step).
        const scalar h = model_.h;
        const scalar maxAcc = std::sqrt(maxAcc2);
        const scalar dtForce = maxAcc > 0
          ? std::sqrt(h/maxAcc) : std::numeric_limits<scalar>::max();
        const scalar speed = std::max(model_.c0, 10*std::sqrt(maxVel2));
        const scalar dtAcoustic = h/(speed + h*maxVisc);
        dt = control_.maxCo*std::min(dtForce, dtAcoustic);
        if (model_.viscosity == viscosityType::laminar && model_.nu > 0)
        {
            dt = std::min(dt, 0.125*h*h/double(model_.nu));
        }
        dt = std::min(dt, control_.maxDeltaT);
    }

    // Land on write times (adjustableRunTime) and on endTime.
    dt = schedule_->limitStep(time_, dt);
    return dt;
}


void fsiSolver::step()
{
    if (gpu_)
    {
        stepGpu();
        return;
    }
    hostParticleStore store = hostStore();
    stepOn(store);
}


// * * * * * * * * * * * * * * * * * Blow-up  * * * * * * * * * * * * * * * //

std::string fsiSolver::describeParticle(const label i) const
{
    std::ostringstream os;
    os << "id " << particles_.id[i] << " of body "
       << bodies_[particles_.body[i]].name << " at "
       << str(particles_.position[i]);
    return os.str();
}


void fsiSolver::blowUp(const label particle, const std::string& what,
                       const bool undoPredictor, const bool undoCorrector,
                       const scalar dt)
{
    reportRemoved();
    std::ostringstream msg;
    msg << "The run blew up at time " << str(time_, 10) << " (step "
        << timeIndex_ + 1 << "): particle " << describeParticle(particle)
        << " (velocity " << str(particles_.velocity[particle])
        << ", density " << str(particles_.rho[particle]) << ") has "
        << what << ".\n";

    // Back to the state at the start of the step: v^n and rho^n were kept
    // by the predictor; x^n = x - dt/2 (v^n + v^{n+1}) after the
    // corrector (shifting excepted), x - dt/2 v^n after the predictor.
    particleView v = particles_.view();
    if (undoCorrector && model_.timeScheme == timeSchemeType::verlet)
    {
        // The Verlet update kept v^n and rho^n; x^n = x - dt v^n - dt^2/2 a^n.
        for (label i = 0; i < v.n; ++i)
        {
            if (v.kind[i] != fluidKind) continue;
            v.position[i] -= dt*v.velocityPrevious[i]
                + (0.5*dt*dt)*(v.acceleration[i] + model_.g);
            v.velocity[i] = v.velocityPrevious[i];
            v.rho[i] = v.rhoPrevious[i];
        }
    }
    else if (undoPredictor)
    {
        for (label i = 0; i < v.n; ++i)
        {
            if (v.kind[i] != fluidKind) continue;
            point x = v.position[i] - (0.5*dt)*v.velocity0[i];
            if (undoCorrector)
            {
                x -= (0.5*dt)*v.velocity[i];
            }
            v.position[i] = x;
            v.velocity[i] = v.velocity0[i];
            v.rho[i] = v.rho0[i];
        }
    }
    if (coupling_ && undoPredictor)
    {
        coupling_->restoreStepStart();
        hostStore().putSolids(*coupling_);
    }
    if (wallsMove_ && wallTime_ != time_)
    {
        hostParticleStore store = hostStore();
        moveWallsOn(store, time_);
    }
    // Only a finite state is worth writing.
    bool finite = true;
    for (label i = 0; i < v.n && finite; ++i)
    {
        finite = isFinite(v.position[i]) && isFinite(v.velocity[i])
              && isFinite(v.rho[i]);
    }
    // Not written again where it is on disk already: the start, or a
    // write just before this step.
    if (finite && stepsRun_ == 0)
    {
        msg << "The last good state is the start time, "
            << startTimeName_ << "/.\n";
    }
    else if (finite && time_ == schedule_->lastWriteTime())
    {
        finishWrite();
        msg << "The last good state (time " << str(time_, 10)
            << ") is the last write, " << schedule_->lastWriteName()
            << "/.\n";
    }
    else if (finite)
    {
        // The step that failed started from it, so it may be bad already:
        // marked, a restart from latestTime does not go on from it.
        write(false, true);
        msg << "The state the failing step started from (time "
            << str(time_, 10) << ") was written to " << schedule_->name(time_)
            << "/ to look at; a restart from latestTime refuses it (blowUp"
               " in its uniform/time): remove it to go on from "
            << (schedule_->lastWriteTime() == beginTime_ ? startTimeName_
                : schedule_->lastWriteName()) << "/.\n";
    }
    msg << "Usual causes: a time step too large for the forces ("
        << (control_.adjustTimeStep ? "lower maxCo or maxDeltaT"
            : "lower deltaT, or set adjustTimeStep yes")
        << "), a speed of sound too low for the impact"
           " (raise c0), or particles packed too closely at the start.";
    if (wallsMove_)
    {
        // A motion in the wrong unit, or a table's stray row, throws the
        // walls and the water with them: say how fast they go.
        double wallSpeed = 0;
        for (label i = 0; i < v.n; ++i)
        {
            if (v.kind[i] == wallKind)
            {
                wallSpeed = std::max(wallSpeed, double(mag(v.velocity[i])));
            }
        }
        msg << " Walls move here (constant/motion), at up to "
            << str(wallSpeed) << " m/s at time " << str(time_, 10)
            << ": check that the motion is the one meant.";
    }
    if (model_.timeScheme == timeSchemeType::verlet)
    {
        msg << " With timeScheme verlet, density diffusion grows between its"
               " Euler steps: keep " << verletTestedLimits
            << ", or use timeScheme symplectic.";
    }
    fatalError(msg.str());
}


// * * * * * * * * * * * * * * * * * * Output * * * * * * * * * * * * * * * //

double fsiSolver::countInteractions()
{
    if (gpu_)
    {
        return countInteractionsGpu();
    }
    hostParticleStore store = hostStore();
    return countInteractionsOn(store);
}


#ifndef SPHVCPM_HAVE_CUDA
// Without the CUDA backend the constructor stops before any of these runs.
void cudaParticleStoreDeleter::operator()(cudaParticleStore*) const {}
void fsiSolver::startGpu() { fatalError("no CUDA backend in this build"); }
void fsiSolver::stepGpu() {}
void fsiSolver::gpuToHost() {}
void fsiSolver::updateWallsGpu() {}
double fsiSolver::countInteractionsGpu() { return 0; }
#endif


void fsiSolver::write(const bool inBackground, const bool afterBlowUp)
{
    finishWrite();
    // The step after a write is a Verlet scheme's Euler step, in this run as
    // in a run restarted from what is written here.
    verletStepsLeft_ = 0;
    const label n = particles_.size();
    std::vector<label> counts(bodies_.size(), 0);
    for (label i = 0; i < n; ++i) ++counts[particles_.body[i]];

    // Fluid and wall bodies from the particle set (solids below).
    std::vector<particleBody> out;
    std::vector<int> outIndex(bodies_.size(), -1);
    for (std::size_t b = 0; b < bodies_.size(); ++b)
    {
        if (bodies_[b].type == bodyType::solid) continue;
        outIndex[b] = int(out.size());
        out.emplace_back(bodies_[b].name, bodies_[b].type,
                         model_.nDimensions, bodies_[b].dp);
        out.back().resize(counts[b]);
        out.back().addVectorField("U");
        out.back().addScalarField("rho");
        out.back().addScalarField("p");
        out.back().addScalarField("mass");
    }
    std::vector<label> fill(bodies_.size(), 0);
    std::vector<scalar> solidPressure(coupling_ ? coupling_->size() : 0);
    label maxId = 0;
    for (label i = 0; i < n; ++i)
    {
        maxId = std::max(maxId, particles_.id[i]);
        if (particles_.kind[i] == solidKind)
        {
            solidPressure[particles_.link[i]] = particles_.p[i];
            continue;
        }
        particleBody& body = out[outIndex[particles_.body[i]]];
        const label k = fill[particles_.body[i]]++;
        body.position()[k] = particles_.position[i];
        body.id()[k] = particles_.id[i];
        body.vectorField("U")[k] = particles_.velocity[i];
        body.scalarField("rho")[k] = particles_.rho[i];
        body.scalarField("p")[k] = particles_.p[i];
        body.scalarField("mass")[k] = particles_.mass[i];
    }

    // The solids' own fields, with the pressure the fluid puts on them.
    std::vector<particleBody> solidsOut =
        solids_->output(model_.nDimensions, maxId);
    for (std::size_t b = 0; b < solidsOut.size(); ++b)
    {
        std::vector<scalar>& p = solidsOut[b].addScalarField("p");
        // The velocity the fluid sees (the last half step's mean), so that
        // a restart continues exactly.
        std::vector<vec3>& meanU = solidsOut[b].addVectorField("Umean");
        for (label i = 0; i < solidsOut[b].size(); ++i)
        {
            p[i] = solidPressure[coupling_->index(b, i)];
            meanU[i] = coupling_->meanVelocity[coupling_->index(b, i)];
        }
        out.push_back(std::move(solidsOut[b]));
    }
    for (particleBody& body : out) body.setNextId(maxId + 1);

    timeState state{time_, schedule_->writeName(time_), timeIndex_, deltaT_,
                    deltaT0_, beginTime_, {{"c0", model_.c0}}};
    if (afterBlowUp) state.solverValues.emplace_back("blowUp", 1);
    const writeFormat format = writeFormatFromName(control_.writeFormatName);
    const int precision = control_.writePrecision;
    log_<< "Writing time " << state.name << std::endl;
    if (!inBackground)
    {
        writeTimeDirectory(caseDir_, state, out, format, precision);
        return;
    }
    // out is a copy: the steps go on while a host thread writes it (still
    // atomically, so a run stopped meanwhile keeps the previous time).
    pendingWrite_ = std::async(std::launch::async,
        [this, state, format, precision, out = std::move(out)]()
        {
            writeTimeDirectory(caseDir_, state, out, format, precision);
        });
}


void fsiSolver::finishWrite()
{
    if (pendingWrite_.valid())
    {
        pendingWrite_.get();   // rethrows a failed write's error
    }
}


void fsiSolver::refreshWalls()
{
    // The walls' pressures of the step's last force pass were extrapolated
    // from the fluid at its start (or middle): extrapolate them from this
    // state, as a restart or -postProcess does from a written time.
    if (wallsFreshIndex_ == timeIndex_) return;
    if (gpu_)
    {
        updateWallsGpu();
    }
    else
    {
        hostParticleStore store = hostStore();
        updateWallsOn(store, false);
    }
    wallsFreshIndex_ = timeIndex_;
}


void fsiSolver::executeFunctions()
{
    bool due = false, wallsDue = false;
    for (const auto& f : functions_)
    {
        const bool now = f->due(time_, timeIndex_);
        due = due || now;
        wallsDue = wallsDue || (now && f->usesWallPressure());
    }
    if (!due) return;
    if (wallsDue)
    {
        refreshWalls();
    }
    if (gpu_)
    {
        gpuToHost();
    }
    const solverSnapshot s = snapshot();
    for (auto& f : functions_)
    {
        f->execute(s);
    }
}


void fsiSolver::reportRemoved()
{
    for (bodyInfo& b : bodies_)
    {
        if (b.nRemoved == b.nReported) continue;
        const label count = b.nRemoved - b.nReported;
        log_<< "Removed " << count << " particle" << (count > 1 ? "s" : "")
            << " of " << b.name << " that left the domain"
            << (b.nReported > 0 ? " since the last report (" : " (")
            << b.nRemoved << " in all)\n";
        b.nReported = b.nRemoved;
    }
}


void fsiSolver::run()
{
    if (!postProcessTime_.empty())
    {
        fatalError("fsiSolver::run: a solver made for -postProcess only"
            " reads its time");
    }
    schedule_.emplace(control_, time_);
    schedule_->countEarlierWrites(writesUpTo(caseDir_, time_));

    if (time_ >= control_.endTime*(1 - 1e-12))
    {
        log_<< "Time " << time_ << " is at or past endTime "
            << control_.endTime << ": nothing to do\n" << std::endl;
        return;
    }

    const double nInteract0 = countInteractions();
    interactionSamples_ += nInteract0;
    ++nInteractionSamples_;
    executeFunctions();

    if (!gpu_) log_<< threadContentionNote();
    log_<< "Starting time loop\n" << std::endl;
    const auto wallStart = std::chrono::steady_clock::now();
    double outputSeconds = 0;
    stopControl stop(control_, *schedule_, caseDir_, log_);
    while (time_ < control_.endTime*(1 - 1e-12))
    {
        step();
        {
            phaseTimers::scope s(timers_, phaseTimers::functions);
            executeFunctions();
        }

        const stopAction action = stop.afterStep(time_);
        if (control_.endTime > motionsCheckedUntil_) checkMotionsInDomain();
        const bool atEnd = time_ >= control_.endTime*(1 - 1e-12);
        const auto outputStart = std::chrono::steady_clock::now();
        bool wrote = false;
        if (stopControl::writes(action,
                schedule_->due(time_, timeIndex_) || atEnd))
        {
            // On the GPU the host is free while the steps run: the write
            // goes on beside them.
            refreshWalls();
            if (gpu_) gpuToHost();
            write(bool(gpu_));
            schedule_->written(time_, schedule_->name(time_), caseDir_,
                               startTimeName_);
            wrote = true;
        }
        const bool stopNow = stopControl::stops(action, wrote);
        if (stepsRun_ % control_.logInterval == 0 || atEnd || stopNow)
        {
            interactionSamples_ += countInteractions();
            outputSeconds += std::chrono::duration<double>(
                std::chrono::steady_clock::now() - outputStart).count();
            ++nInteractionSamples_;
            reportRemoved();
            log_<< "Time = " << schedule_->name(time_) << "\n"
                << "Step = " << timeIndex_ << "  deltaT = "
                << str(deltaT_, 4) << "  particles = " << particles_.size()
                << "\n" << executionTimeLine() << "\n"
                << progress_.line(time_, control_.endTime) << std::endl;
        }
        else
        {
            outputSeconds += std::chrono::duration<double>(
                std::chrono::steady_clock::now() - outputStart).count();
        }
        if (stopNow)
        {
            finishWrite();   // before the log says it is written
            stop.reportStop(action, time_);
            break;
        }
    }

    // The rates below are of the steps alone: writing time directories
    // and counting pairs for this summary are left out.
    const double loopSeconds = std::chrono::duration<double>(
        std::chrono::steady_clock::now() - wallStart).count();
    const double seconds = std::max(1e-9, loopSeconds - outputSeconds);
    const auto lastWrite = std::chrono::steady_clock::now();
    finishWrite();
    outputSeconds += std::chrono::duration<double>(
        std::chrono::steady_clock::now() - lastWrite).count();
    const double meanPairs = interactionSamples_/nInteractionSamples_;
    const int passes = model_.timeScheme == timeSchemeType::verlet ? 1 : 2;
    log_<< "Run summary: " << stepsRun_ << " steps of "
        << particles_.size() << " particles in " << str(seconds, 4)
        << " s wall clock (plus " << str(outputSeconds, 4)
        << " s writing and logging)\n"
        << "    " << str(particleSteps_/seconds/1e6, 4)
        << " M particle-steps/s, "
        << str(passes*meanPairs*stepsRun_/seconds/1e9, 4)
        << " G interactions/s (" << str(meanPairs/std::max<label>(1,
            particles_.size()), 4) << " neighbours per particle, "
        << passes << " force pass" << (passes > 1 ? "es" : "")
        << " per step), " << openmpThreads() << " threads\n";
    if (gpu_)
    {
        const gpuInfo info = cudaDeviceInfo();
        log_<< "    GPU memory in use at the end: "
            << str((info.totalMemory - info.freeMemory)/1073741824.0, 4)
            << " GiB of " << str(info.totalMemory/1073741824.0, 4)
            << " GiB (" << info.name << ")\n";
    }
    // Weak compressibility errs in density by about Ma^2 (docs/solver.md,
    // Choices, Speed-of-sound check).
    const double maxSpeed = std::sqrt(double(maxSpeed2_));
    const double mach = maxSpeed/model_.c0;
    log_<< "    largest fluid speed " << str(maxSpeed, 4) << " m/s (time "
        << schedule_->name(maxSpeedTime_) << "): Mach "
        << str(mach, 3) << " against c0 = " << str(model_.c0, 4)
        << " m/s (where it flows that fast, density errs by about Ma^2 = "
        << str(100*mach*mach, 2) << " %)\n";
    if (coupling_)
    {
        log_<< "    solids: " << coupling_->size() << " particles, "
            << str(solidSubSteps_/std::max<label>(1, stepsRun_), 4)
            << " solid steps per fluid step\n";
    }
    timers_.print(log_, stepsRun_);
    for (const bodyInfo& b : bodies_)
    {
        if (b.nRemoved > 0)
        {
            log_<< "    " << b.name << ": " << b.nRemoved
                << " particles removed for leaving the domain\n";
        }
    }
    log_<< std::endl;
}

} // End namespace sphvcpm
