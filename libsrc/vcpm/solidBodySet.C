/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "solidBodySet.H"
#include "dictionary.H"
#include "dimensionSet.H"
#include "error.H"
#include "formatting.H"
#include "parallel.H"
#include "timeDirectory.H"

#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>
#include <sstream>

namespace sphvcpm
{

namespace
{

// A solid whose own weight alone would strain it by more than 10 %
// (rho |g| L/E, L its extent along g) is far outside the lattice's small
// strains and collapses at once, before any fluid reaches it: most often
// E given in MPa or kPa as if in Pa. Said before the run, with the numbers.
void warnIfOwnWeightCrushes(const std::string& name, const vcpmMaterial& mat,
                            const std::vector<point>& reference,
                            const scalar dp, const vec3& g)
{
    const scalar gMag = mag(g);
    if (gMag <= 0 || reference.empty()) return;
    const vec3 down = g/gMag;
    scalar lo = dot(down, toVec3(reference[0])), hi = lo;
    for (const point& x : reference)
    {
        const scalar s = dot(down, toVec3(x));
        lo = std::min(lo, s);
        hi = std::max(hi, s);
    }
    const scalar L = hi - lo + dp;
    const scalar strain = mat.rho*gMag*L/mat.E;
    if (strain > 0.1)
    {
        std::ostringstream os;
        os.precision(3);
        os << "Solid " << name << ": its own weight strains it by about"
           << " rho |g| L/E = " << strain << " (rho = " << mat.rho
           << " kg/m^3, L = " << L << " m along g, E = " << mat.E << " Pa),"
           << " far beyond the lattice's small strains: it will collapse"
           << " under its own weight. E is read in Pa (5 MPa is 5e6)";
        warning(os.str(), "constant/solidProperties");
    }
}

} // End anonymous namespace


namespace fs = std::filesystem;

vcpmMaterial solidBodySet::readMaterial
(
    const dictionary& all,
    const std::string& name,
    const int nDimensions,
    const scalar dp,
    const scalar massRho,
    scalar& damping,
    scalar& latticeDamping
) const
{
    const dictionary& props = all.subDict(name);
    props.checkKeywords({"rho", "E", "nu", "lattice", "plane",
                         "surfaceCorrection", "damping", "latticeDamping"});
    // rho of the sub-dictionary, else the one generateParticles gave the
    // particles' mass (a body-level rho).
    const scalar rho = props.found("rho")
      ? props.getDimensioned<scalar>("rho", dimensions::density()) : massRho;
    // solidProperties changed since generateParticles: its rho wins, said.
    if (massRho > 0 && std::fabs(rho - massRho) > 1e-6*rho)
    {
        std::ostringstream os;
        os.precision(6);
        os << "Solid " << name << ": its particles' mass gives rho = "
           << massRho << " kg/m^3 (as generated), constant/solidProperties"
           << " rho = " << rho << ": the solver uses " << rho
           << " and sets the mass from it";
        warning(os.str(), props.file(), props.line());
    }
    damping = props.getOrDefault<scalar>("damping", 0);
    if (!(damping >= 0))
    {
        props.fatalAt("damping", "Keyword 'damping' of solid '" + name
            + "': the mass-proportional damping (1/s) must be >= 0");
    }
    latticeDamping = props.getOrDefault<scalar>("latticeDamping",
                                                defaultLatticeDamping);
    if (!(latticeDamping >= 0 && latticeDamping <= 0.2))
    {
        props.fatalAt("latticeDamping", "Keyword 'latticeDamping' of solid '"
            + name + "': the damping ratio of the lattice's highest mode must"
            " be in [0, 0.2] (0: none; more damps the structure's own modes)");
    }
    return vcpmMaterial::read(props, name, nDimensions, rho, dp);
}


solidBodySet::solidBodySet
(
    const fs::path& caseDir,
    const std::string& startTimeName,
    const std::vector<particleBody>& start,
    const bool freshStart,
    const vec3& g,
    std::ostream& log
)
:
    caseDir_(caseDir)
{
    const auto firstSolid = std::find_if(start.begin(), start.end(),
        [](const particleBody& b) { return b.type() == bodyType::solid; });
    if (firstSolid == start.end()) return;

    // Read once: every solid's material, and the check of its entries.
    const fs::path file = caseDir_/"constant/solidProperties";
    if (!fs::is_regular_file(file))
    {
        const std::string& name = firstSolid->name();
        fatalError("Solid " + name + ": " + file.string() + " does not exist;"
            " it gives the material as " + name + " { E ...; nu ...; }");
    }
    const dictionary solidProperties = dictionary::fromFile(file);

    // The reference lattice: the start itself, or on a restart the initial
    // time (index 0; 0/ of generateParticles unless the case starts
    // elsewhere). Not "0" by name: a run started at -1 writes its t = 0
    // there, deformed.
    std::vector<particleBody> zero;
    const std::string initial = initialTimeName(caseDir_);
    if (!freshStart)
    {
        if (initial.empty() || initial == startTimeName
         || readTimeState(caseDir_, initial).index != 0)
        {
            fatalError("Restart from time " + startTimeName + " needs the"
                " initial time (index 0, as the 0/ of generateParticles),"
                " the reference lattice of the solids' bonds; the earliest"
                " time of the case, " + (initial.empty() ? "none" : initial)
                + ", is not one");
        }
        zero = readTimeDirectory(caseDir_, initial);
        log << "    the solids' reference lattice: time " << initial << "\n";
    }

    for (const particleBody& b : start)
    {
        if (b.type() != bodyType::solid) continue;
        const int nDim = b.nDimensions();
        const label n = b.size();
        const scalar massRho = b.hasField("mass") && n
          ? b.scalarField("mass")[0]/std::pow(b.dp(), nDim) : 0;
        scalar damping = 0, latticeDamping = 0;
        const vcpmMaterial mat = readMaterial(solidProperties, b.name(),
                                              nDim, b.dp(),
                                              massRho, damping,
                                              latticeDamping);

        std::vector<point> reference = b.position();
        if (!freshStart)
        {
            auto it = std::find_if(zero.begin(), zero.end(),
                [&](const particleBody& z) { return z.name() == b.name(); });
            if (it == zero.end())
            {
                fatalError("Solid " + b.name() + " is not in " + initial
                    + "/: a restart takes its reference lattice from "
                    + initial + "/" + b.name());
            }
            // 0/ written again by generateParticles after the run (a changed
            // body) is not the lattice of this state: refused, not bent.
            const std::string regenerated = " (generateParticles run again"
                " since?). Start afresh without the later time directories,"
                " or restore the 0/ this run started from";
            if (it->size() != n)
            {
                fatalError("Solid " + b.name() + ": time " + startTimeName
                    + " has " + std::to_string(n) + " particles and "
                    + initial + "/" + b.name() + " "
                    + std::to_string(it->size()) + ": " + initial
                    + "/ is not the initial state of this run" + regenerated);
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
                        + startTimeName + " is not in " + initial + "/"
                        + b.name());
                }
                reference[i] = it->position()[k->second];
            }
            if (b.hasField("displacement"))
            {
                const std::vector<vec3>& u = b.vectorField("displacement");
                for (label i = 0; i < n; ++i)
                {
                    // Far above what ascii at 6 digits leaves of the three
                    // fields, far below a regenerated lattice's offsets.
                    const vec3 d = toVec3(b.position()[i] - reference[i]);
                    const scalar rounding = 2e-5*(mag(toVec3(
                        b.position()[i])) + mag(toVec3(reference[i])));
                    if (mag(d - u[i]) > 0.05*b.dp() + rounding)
                    {
                        fatalError("Solid " + b.name() + ": particle id "
                            + std::to_string(b.id()[i]) + " is displaced by "
                            + str(u[i]) + " m in " + startTimeName + "/"
                            + b.name() + "/displacement but by " + str(d)
                            + " m from its position in " + initial + "/: "
                            + initial + "/ is not the initial state of this"
                              " run" + regenerated);
                    }
                }
            }
        }

        label nClamped = 0;
        std::vector<std::uint8_t> clamps;
        if (b.hasField("clamped"))
        {
            const std::vector<label>& clamped = b.labelField("clamped");
            clamps.assign(n, 0);
            for (label i = 0; i < n; ++i)
            {
                if (clamped[i] != 0 && clamped[i] != 1)
                {
                    fatalError("Solid " + b.name() + ": particle id "
                        + std::to_string(b.id()[i]) + " has clamped "
                        + std::to_string(clamped[i]) + " in "
                        + (caseDir/startTimeName/b.name()/"clamped").string()
                        + ": expected 0 (free) or 1 (clamped)");
                }
                clamps[i] = clamped[i] != 0;
                nClamped += clamps[i];
            }
        }
        solidBody sb{b.name(), b.dp(), b.id(),
                     std::make_unique<vcpmSolid>(mat, reference, clamps), 0};
        vcpmSolid& s = *sb.solid;
        s.position = b.position();
        if (b.hasField("U")) s.velocity = b.vectorField("U");
        s.gravity = g;
        s.damping = damping;
        s.latticeDamping = latticeDamping;
        // With the lattice damping known: lower near nu = 0.5.
        sb.stableDeltaT = s.stableTimeStep(damping > 0 ? 0.3 : 0.5);

        log << "    " << b.name() << " (solid): " << n << " particles, "
            << nClamped << " clamped, " << s.bonds().nBonds() << " bonds\n"
            << "        E = " << mat.E << " Pa, nu = " << mat.nu
            << ", rho = " << mat.rho << " kg/m^3, "
            << (nDim == 2 ? (mat.plane == planeModel::planeStrain
                ? "square2D planeStrain" : "square2D planeStress")
                : "simpleCubic3D")
            << ", damping " << damping << " 1/s, latticeDamping "
            << latticeDamping << "\n"
            << "        c_p = " << mat.pWaveSpeed << " m/s, stable deltaT = "
            << sb.stableDeltaT << " s\n";
        warnIfOwnWeightCrushes(b.name(), mat, reference, b.dp(), g);
        bodies_.push_back(std::move(sb));
    }

    // An entry for no solid of the case is most often a misspelt body
    // name, whose solid then stops at its missing material; or a stray
    // keyword. Either is unused: say so.
    std::string solids;
    for (const solidBody& b : bodies_) solids += " " + b.name;
    for (const std::string& key : solidProperties.keys())
    {
        // A solid uses the entry its name looks up: its own, or a quoted
        // pattern ("pla.*") that matches it.
        const auto* e = solidProperties.findEntry(key);
        const bool used = e->usedAsVariable()
          || std::any_of(bodies_.begin(), bodies_.end(),
            [&](const solidBody& b)
            { return solidProperties.findEntry(b.name) == e; });
        if (!used)
        {
            warning("Entry '" + key + "' of constant/solidProperties names"
                " no solid body of the case (solids:" + solids + "): it is"
                " not used", file.string());
        }
    }
}


scalar solidBodySet::stableDeltaT() const
{
    scalar dt = 0;
    for (const solidBody& b : bodies_)
    {
        dt = dt > 0 ? std::min(dt, b.stableDeltaT) : b.stableDeltaT;
    }
    return dt;
}


label solidBodySet::nParticles() const
{
    label n = 0;
    for (const solidBody& b : bodies_) n += b.solid->size();
    return n;
}


std::vector<particleBody> solidBodySet::output(const int nDimensions,
                                               label& maxId)
{
    std::vector<particleBody> out;
    for (solidBody& b : bodies_)
    {
        vcpmSolid& s = *b.solid;
        const label n = s.size();
        out.emplace_back(b.name, bodyType::solid, nDimensions, b.dp);
        particleBody& o = out.back();
        o.resize(n);
        o.position() = s.position;
        o.id() = b.id;
        o.addVectorField("U") = s.velocity;
        o.addScalarField("mass", s.material().mass);
        std::vector<label>& clamped = o.addLabelField("clamped", 0);
        for (label i = 0; i < n; ++i) clamped[i] = s.clamped()[i];
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
        if (nDimensions == 3)
        {
            component("stressXZ", &stressTensor::xz);
            component("stressYZ", &stressTensor::yz);
            component("stressZZ", &stressTensor::zz);
        }
        else if (s.material().plane == planeModel::planeStrain)
        {
            // Plane strain holds the thickness: sigma_zz = nu (sigma_xx +
            // sigma_yy), as vonMises counts it (the in-plane tensor alone
            // would give ParaView another von Mises).
            std::vector<scalar>& zz = o.addScalarField("stressZZ");
            const scalar nu = s.material().nu;
            for (label i = 0; i < n; ++i)
            {
                zz[i] = nu*(sigma[i].xx + sigma[i].yy);
            }
        }
        o.addScalarField("vonMises") = s.vonMisesOf(sigma);
        for (label id : b.id) maxId = std::max(maxId, id);
    }
    return out;
}


std::string solidBodySet::firstNonFinite() const
{
    for (const solidBody& b : bodies_)
    {
        const std::vector<point>& x = b.solid->position;
        for (std::size_t i = 0; i < x.size(); ++i)
        {
            if (std::isfinite(x[i].x + x[i].y + x[i].z)) continue;
            std::ostringstream os;
            os << "particle id " << b.id[i] << " of solid " << b.name
               << " (reference position (" << b.solid->reference()[i].x
               << " " << b.solid->reference()[i].y << " "
               << b.solid->reference()[i].z << "))";
            return os.str();
        }
    }
    return {};
}


std::string solidBodySet::firstCollapsed(const scalar fraction,
                                         label* flatIndex) const
{
    label offset = 0;
    for (const solidBody& b : bodies_)
    {
        const bondView bonds = b.solid->bonds().view();
        const std::vector<point>& x = b.solid->position;
        const label k = parallelReduce(openmpExec{}, bonds.nBonds,
            collapsedBondOp{bonds, x.data(), fraction}, bonds.nBonds,
            minOp());
        if (k == bonds.nBonds)
        {
            offset += label(x.size());
            continue;
        }
        const label i = bonds.first[k], j = bonds.second[k];
        if (flatIndex) *flatIndex = offset + i;
        std::ostringstream os;
        os << "solid " << b.name << ": the bond of particles id " << b.id[i]
           << " at (" << x[i].x << " " << x[i].y << " " << x[i].z
           << ") and id " << b.id[j] << " at (" << x[j].x << " " << x[j].y
           << " " << x[j].z << ") is " << mag(x[j] - x[i])/bonds.length[k]
           << " of its rest length " << bonds.length[k] << " m; E = "
           << b.solid->material().E << " Pa, latticeDamping "
           << b.solid->latticeDamping;
        return os.str();
    }
    return {};
}

} // End namespace sphvcpm
