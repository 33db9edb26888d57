/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "solidOnlySolver.H"
#include "argList.H"
#include "dictionary.H"
#include "dimensionSet.H"
#include "error.H"
#include "parallel.H"
#include "sphModel.H"
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


vcpmMaterial solidOnlySolver::readMaterial
(
    const std::string& name,
    const scalar dp,
    const scalar massRho,
    scalar& damping
) const
{
    const fs::path file = caseDir_/"constant/solidProperties";
    if (!fs::is_regular_file(file))
    {
        fatalError("Solid " + name + ": " + file.string() + " does not exist;"
            " it gives the material as " + name + " { E ...; nu ...; }");
    }
    const dictionary all = dictionary::fromFile(file);
    const dictionary& props = all.subDict(name);
    // rho of the sub-dictionary, else the one generateParticles gave the
    // particles' mass (a body-level rho).
    const scalar rho = props.found("rho")
      ? props.getDimensioned<scalar>("rho", dimensions::density()) : massRho;
    damping = props.getOrDefault<scalar>("damping", 0);
    if (!(damping >= 0))
    {
        props.fatalAt("damping", "Keyword 'damping' of solid '" + name
            + "': the mass-proportional damping (1/s) must be >= 0");
    }
    return vcpmMaterial::read(props, name, nDim_, rho, dp);
}


solidOnlySolver::solidOnlySolver
(
    const fs::path& caseDir,
    const std::string& startTimeName,
    std::ostream& log
)
:
    caseDir_(caseDir),
    log_(log),
    control_(timeControl::read(caseDir)),
    startTimeName_(startTimeName)
{
    const timeState state = readTimeState(caseDir_, startTimeName_);
    time_ = state.value;
    timeIndex_ = state.index;
    beginTime_ = time_;
    const bool freshStart = state.index == 0;

    log_<< "Reading time " << startTimeName_ << " (solids alone: no fluid"
        << " body)\n";
    std::vector<particleBody> start =
        readTimeDirectory(caseDir_, startTimeName_);
    // The reference lattice: the start itself, or 0/ on a restart.
    std::vector<particleBody> zero;
    if (!freshStart)
    {
        if (!fs::is_directory(caseDir_/"0"))
        {
            fatalError("Restart from time " + startTimeName_ + " needs 0/,"
                " the reference lattice of the solids' bonds");
        }
        zero = readTimeDirectory(caseDir_, "0");
    }

    const vec3 g = readGravity(caseDir_, start.front().nDimensions());
    for (const particleBody& b : start)
    {
        nDim_ = b.nDimensions();
        if (b.type() != bodyType::solid)
        {
            log_<< "    " << b.name() << " (" << bodyTypeName(b.type())
                << "): ignored, no solid-wall contact yet\n";
            continue;
        }
        const label n = b.size();
        const scalar massRho = b.hasField("mass") && n
          ? b.scalarField("mass")[0]/std::pow(b.dp(), nDim_) : 0;
        scalar damping = 0;
        const vcpmMaterial mat = readMaterial(b.name(), b.dp(), massRho,
                                              damping);

        std::vector<vec3> reference = b.position();
        if (!freshStart)
        {
            auto it = std::find_if(zero.begin(), zero.end(),
                [&](const particleBody& z) { return z.name() == b.name(); });
            if (it == zero.end())
            {
                fatalError("Solid " + b.name() + " is not in 0/: a restart"
                    " takes its reference lattice from 0/" + b.name());
            }
            std::map<label, label> index;
            for (label i = 0; i < it->size(); ++i) index[it->id()[i]] = i;
            for (label i = 0; i < n; ++i)
            {
                auto k = index.find(b.id()[i]);
                if (k == index.end())
                {
                    fatalError("Solid " + b.name() + ": particle id "
                        + std::to_string(b.id()[i]) + " of time "
                        + startTimeName_ + " is not in 0/" + b.name());
                }
                reference[i] = it->position()[k->second];
            }
        }

        body sb{b.name(), b.dp(), b.id(),
                std::make_unique<vcpmSolid>(mat, reference)};
        vcpmSolid& s = *sb.solid;
        s.position = b.position();
        if (b.hasField("U")) s.velocity = b.vectorField("U");
        label nClamped = 0;
        if (b.hasField("clamped"))
        {
            for (label i = 0; i < n; ++i)
            {
                s.clamped[i] = b.labelField("clamped")[i] != 0;
                nClamped += s.clamped[i];
            }
        }
        s.gravity = g;
        s.damping = damping;
        const scalar dt = mat.stableTimeStep(damping > 0 ? 0.3 : 0.5);
        stableDeltaT_ = stableDeltaT_ > 0 ? std::min(stableDeltaT_, dt) : dt;

        log_<< "    " << b.name() << " (solid): " << n << " particles, "
            << nClamped << " clamped, " << s.bonds().nBonds() << " bonds\n"
            << "        E = " << mat.E << " Pa, nu = " << mat.nu
            << ", rho = " << mat.rho << " kg/m^3, "
            << (nDim_ == 2 ? (mat.plane == planeModel::planeStrain
                ? "square2D planeStrain" : "square2D planeStress")
                : "simpleCubic3D")
            << ", damping " << damping << " 1/s\n"
            << "        c_p = " << mat.pWaveSpeed << " m/s, stable deltaT = "
            << dt << " s\n";
        bodies_.push_back(std::move(sb));
    }
    stableDeltaT_ = std::min(stableDeltaT_, control_.maxDeltaT);
    deltaT_ = stableDeltaT_;
    log_<< "    g = (" << g.x << " " << g.y << " " << g.z << "), " << nDim_
        << "D, time = " << time_ << ", solid deltaT = " << stableDeltaT_
        << " s\n" << std::endl;
}


void solidOnlySolver::write()
{
    std::vector<particleBody> out;
    label maxId = 0;
    for (body& b : bodies_)
    {
        vcpmSolid& s = *b.solid;
        const label n = s.size();
        out.emplace_back(b.name, bodyType::solid, nDim_, b.dp);
        particleBody& o = out.back();
        o.resize(n);
        o.position() = s.position;
        o.id() = b.id;
        o.addVectorField("U") = s.velocity;
        o.addScalarField("mass", s.material().mass);
        std::vector<label>& clamped = o.addLabelField("clamped", 0);
        for (label i = 0; i < n; ++i) clamped[i] = s.clamped[i];
        o.addVectorField("displacement") = s.displacement();

        std::vector<stressTensor> sigma;
        s.stress(openmpExec{}, sigma);
        // No tensor field type yet: the independent components.
        auto component = [&](const char* name, scalar stressTensor::*c)
        {
            std::vector<scalar>& f = o.addScalarField(name);
            for (label i = 0; i < n; ++i) f[i] = sigma[i].*c;
        };
        component("stressXX", &stressTensor::xx);
        component("stressXY", &stressTensor::xy);
        component("stressYY", &stressTensor::yy);
        if (nDim_ == 3)
        {
            component("stressXZ", &stressTensor::xz);
            component("stressYZ", &stressTensor::yz);
            component("stressZZ", &stressTensor::zz);
        }
        o.addScalarField("vonMises") = s.vonMisesOf(sigma);
        for (label id : b.id) maxId = std::max(maxId, id);
    }
    for (particleBody& o : out) o.setNextId(maxId + 1);

    const timeState state{time_, control_.name(time_), timeIndex_, deltaT_,
                          deltaT_, beginTime_, {}};
    writeTimeDirectory(caseDir_, state, out,
        writeFormatFromName(control_.writeFormatName),
        control_.writePrecision);
    log_<< "Writing time " << state.name << std::endl;
}


void solidOnlySolver::run()
{
    schedule_.emplace(control_, time_);
    if (time_ >= control_.endTime*(1 - 1e-12))
    {
        log_<< "Time " << time_ << " is at or past endTime "
            << control_.endTime << ": nothing to do\n" << std::endl;
        return;
    }

    for (body& b : bodies_) b.solid->computeForces(openmpExec{});

    log_<< "Starting time loop\n" << std::endl;
    label stepsRun = 0;
    while (time_ < control_.endTime*(1 - 1e-12))
    {
        // The same write times as the fluid loop.
        const scalar dt = schedule_->limitStep(time_, stableDeltaT_);
        for (body& b : bodies_) b.solid->step(openmpExec{}, dt);
        deltaT_ = dt;
        time_ += dt;
        if (schedule_->landed())
        {
            time_ = schedule_->landingTime();
        }
        ++timeIndex_;
        ++stepsRun;

        for (body& b : bodies_)
        {
            for (const vec3& x : b.solid->position)
            {
                if (!std::isfinite(x.x + x.y + x.z))
                {
                    fatalError("Solid " + b.name + " blew up at time "
                        + std::to_string(time_) + ": a non-finite position"
                          " (is maxDeltaT above the stable step?)");
                }
            }
        }

        const bool atEnd = time_ >= control_.endTime*(1 - 1e-12);
        if (schedule_->due(time_, timeIndex_) || atEnd)
        {
            write();
            schedule_->written(time_, control_.name(time_), caseDir_,
                               startTimeName_);
        }
        if (stepsRun % control_.logInterval == 0 || atEnd)
        {
            scalar kinetic = 0;
            for (const body& b : bodies_) kinetic += b.solid->kineticEnergy();
            log_<< "Time = " << control_.name(time_) << "\n"
                << "Step = " << timeIndex_ << "  deltaT = "
                << std::setprecision(4) << deltaT_ << std::setprecision(6)
                << "  kinetic energy = " << kinetic << " J\n"
                << executionTimeLine() << "\n" << std::endl;
        }
    }
}

} // End namespace sphvcpm
