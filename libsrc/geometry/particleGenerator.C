/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Particle bodies of a case from system/generateParticlesDict.

#include "particleGenerator.H"
#include "boundBox.H"
#include "containerShape.H"
#include "error.H"
#include "hostMemory.H"
#include "lattice.H"
#include "latticeMembers.H"
#include "pointLocator.H"
#include "vcpmBeam.H"

#include <algorithm>
#include <iomanip>
#include <map>
#include <cmath>
#include <ostream>
#include <sstream>

namespace sphvcpm
{

namespace fs = std::filesystem;

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

namespace
{

const std::vector<std::string> topKeywords =
    {"nDimensions", "dp", "latticeOrigin", "bodies"};

const std::vector<std::string> bodyKeywords =
    {"type", "rho", "U", "latticeOrigin", "container", "shapes", "clamp",
     "dp"};

// The generation order: what a later body must not overlap comes first.
const bodyType buildOrder[] = {bodyType::solid, bodyType::wall,
                               bodyType::fluid};

std::string volumeUnit(int nDimensions)
{
    return nDimensions == 2 ? " m^2" : " m^3";
}

// What generateParticles holds per particle at its peak: nodes, the body's
// fields, the overlap and gap searches' copies (137 bytes measured at 1
// million particles, damBreak3D at dp 5 mm), with a margin.
constexpr std::size_t bytesPerGeneratedParticle = 160;

// The most particles one more body may have in 80 % of the memory free now
// (the bodies made so far are in use already); no limit where it cannot be
// read.
std::size_t particlesMemoryTakes()
{
    const std::optional<std::uint64_t> free = availableMemoryBytes();
    if (!free) return SIZE_MAX;
    return std::size_t(0.8*double(*free)/bytesPerGeneratedParticle);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructor * * * * * * * * * * * * * * //

particleGenerator::particleGenerator
(
    const fs::path& caseDir,
    const fs::path& dictFile
)
:
    caseDir_(caseDir),
    dictFile_(dictFile.is_absolute() ? dictFile : caseDir/dictFile)
{
    const std::string problem = fileProblem(dictFile_.string());
    if (!problem.empty())
    {
        fatalError("The particle generation dictionary "
            + dictFile_.string() + " " + problem + "\nIt describes the bodies to fill:"
              " nDimensions, dp and bodies { <name> { type fluid|wall|solid;"
              " shapes { ... } } }");
    }
    dictionary dict = dictionary::fromFile(dictFile_);
    dict.checkKeywords(topKeywords);

    const label nDim = dict.get<label>("nDimensions");
    if (nDim != 2 && nDim != 3)
    {
        dict.fatalAt("nDimensions", "Keyword 'nDimensions': expected 2 (the"
            " x-y plane, z = 0) or 3, found " + std::to_string(nDim));
    }
    nDimensions_ = int(nDim);
    dict.setCaseDimensions(nDimensions_);
    dp_ = dict.getPositive("dp");
    const vec3 origin = dict.getOrDefault<vec3>("latticeOrigin", {0, 0, 0});

    const dictionary& bodies = dict.subDict("bodies");
    const std::vector<std::string> names = bodies.keys();
    if (names.empty())
    {
        dict.fatalAt("bodies", "Dictionary 'bodies' is empty: give at least"
            " one body, e.g. water { type fluid; shapes { ... } }");
    }
    for (const std::string& name : names)
    {
        readBody(bodies, name, origin);
    }

    readControlDict();
}


particleGenerator::~particleGenerator() = default;


// * * * * * * * * * * * * * * * Private Members * * * * * * * * * * * * * //

void particleGenerator::readBody
(
    const dictionary& bodies,
    const std::string& name,
    const vec3& origin
)
{
    const entry& e = bodies.lookupEntry(name);
    if (e.isPattern() || !e.isDict())
    {
        bodies.fatalAt(name, "Entry '" + name + "' of 'bodies' is not a body:"
            " a body is a sub-dictionary with a plain name, e.g. " + name
            + " { type fluid; shapes { ... } }");
    }
    if (e.mergedLine() > 0 && e.mergedFile() == e.file())
    {
        // Read as OpenFOAM reads it, the second would merge into the first:
        // a wall's container and a fluid's shapes became one body.
        fatalIOError(e.mergedFile(), e.mergedLine(), "Body '" + name
            + "' is given twice in 'bodies' (first at line "
            + std::to_string(e.line()) + "): the two would be read as one"
              " body. Give each body its own name", name);
    }
    if (e.mergedLine() > 0)
    {
        // Defaults from an #include'd file, completed or overridden here:
        // OpenFOAM's way, but say what happened.
        warning("Body '" + name + "' of " + e.file() + " line "
            + std::to_string(e.line()) + " is given again here: its entries"
              " are merged into it, the later ones replacing the earlier"
              " (#inputMode overwrite replaces the whole body)",
            e.mergedFile(), e.mergedLine());
    }
    const dictionary& dict = e.dict();
    dict.checkKeywords(bodyKeywords);

    const bodyType type = bodyTypeFromName(
        dict.getWord("type", {"fluid", "solid", "wall"}));
    // A solid may be finer than the fluid: dp/r, r = 1..4 (multi-resolution).
    scalar givenDp = 0;
    scalar dp = dp_;
    if (dict.found("dp"))
    {
        dp = dict.getPositive("dp");
        givenDp = dp;
        const scalar r = dp_/dp;
        const scalar rInt = std::round(r);
        if (type != bodyType::solid)
        {
            dict.fatalAt("dp", "Keyword 'dp': body '" + name + "' is a "
                + bodyTypeName(type) + "; only solids may have their own"
                " spacing (fluids and walls use the top-level dp)");
        }
        // Within 1 % of dp/r it is dp/r exactly: 'dp 0.00133;' for a
        // top-level 0.004 is meant as 0.004/3, and the lattices must nest.
        if (rInt < 1 || rInt > 4 || std::abs(r - rInt) > 0.01*r)
        {
            std::ostringstream os;
            os.precision(10);
            os << "Keyword 'dp' of solid '" << name << "': expected the"
               << " top-level dp " << dp_ << " divided by 1, 2, 3 or 4 ("
               << dp_ << ", " << dp_/2 << ", " << dp_/3 << " or " << dp_/4
               << ", to 1 %), found " << dp << " (ratio " << r << ")";
            dict.fatalAt("dp", os.str());
        }
        dp = dp_/rInt;
    }
    try
    {
        // Checks the name as a directory of 0/.
        (void)particleBody(name, type, nDimensions_, dp);
    }
    catch (const FatalError& err)
    {
        bodies.fatalAt(name, err.message());
    }

    bodySpec spec
    {
        name,
        type,
        0,
        dict.getOrDefault<vec3>("U", {0, 0, 0}),
        dict.getOrDefault<vec3>("latticeOrigin", origin),
        region(nDimensions_),
        e.file(),
        e.line(),
        std::nullopt,   // clamp, read below
        "",
        0,
        std::nullopt,   // material, read below
        dp,
        givenDp
    };
    if (nDimensions_ == 2 && spec.U.z != 0)
    {
        dict.fatalAt("U", "Keyword 'U': body '" + name + "' is 2D (x-y"
            " plane) but its velocity has a z component");
    }

    if (!dict.found("container") && !dict.found("shapes"))
    {
        fatalIOError(e.file(), e.line(), "Body '" + name + "' has neither"
            " 'shapes' nor 'container': give its region, e.g. shapes { block"
            " { shape box; min (0 0 0); max (1 1 1); } }", name);
    }
    if (dict.found("container"))
    {
        // The shell of a box: a tank's walls. Of fluid it would be a ring
        // of water round an empty box, of a solid a hollow box.
        if (type != bodyType::wall)
        {
            dict.fatalAt("container", "Keyword 'container': body '" + name
                + "' is a " + bodyTypeName(type) + "; 'container' is the"
                  " walls of a tank, for wall bodies (a " + bodyTypeName(type)
                + " takes its region from 'shapes')");
        }
        const dictionary& c = dict.subDict("container");
        c.checkKeywords(containerShape::keywords());
        spec.shapes.add
        (
            std::make_unique<containerShape>("container", c, nDimensions_,
                                             dp)
        );
    }
    if (dict.found("shapes"))
    {
        spec.shapes.addShapes(dict.subDict("shapes"), dp, caseDir_,
                              spec.origin);
    }

    if (dict.found("clamp"))
    {
        if (type != bodyType::solid)
        {
            dict.fatalAt("clamp", "Keyword 'clamp': body '" + name + "' is a "
                + bodyTypeName(type) + "; only solids have clamps");
        }
        const entry& c = dict.lookupEntry("clamp");
        if (!c.isDict())
        {
            dict.fatalAt("clamp", "Keyword 'clamp' of body '" + name + "': "
                "expected shapes, e.g. clamp { support { shape box; min (..);"
                " max (..); } }");
        }
        spec.clamp.emplace(nDimensions_);
        spec.clamp->addShapes(c.dict(), dp, caseDir_, spec.origin);
        spec.clampFile = c.file();
        spec.clampLine = c.line();
    }

    if (dict.found("rho"))
    {
        spec.rho = dict.getDimensioned<scalar>("rho", dimensions::density());
        if (!(spec.rho > 0))
        {
            dict.fatalAt("rho", "Keyword 'rho': the density of body '" + name
                + "' must be positive, found " + shapeDetail::str(spec.rho));
        }
        // One fluid, whose density every fluid and wall particle carries
        // in the SPH sums: a wall's material does not enter (walls are
        // rigid), and a second fluid density would be silently undone by
        // the equation of state.
        const std::optional<scalar> rho0 = type == bodyType::solid
            ? std::nullopt : fluidRho0();
        if (rho0 && std::fabs(spec.rho - *rho0) > 1e-9*(*rho0))
        {
            dict.fatalAt("rho", "Keyword 'rho' of " + bodyTypeName(type)
                + " body '" + name + "': " + shapeDetail::str(spec.rho)
                + " differs from rho0 " + shapeDetail::str(*rho0) + " of"
                " constant/fluidProperties. Fluid and wall particles all"
                " carry the fluid's density (one fluid phase; a rigid wall's"
                " own material does not enter the SPH sums): leave rho out"
                + (type == bodyType::fluid ? std::string(", or set rho0")
                                           : std::string()));
        }
    }
    else
    {
        spec.rho = defaultRho(e, type);
    }

    if (type == bodyType::solid)
    {
        if (const dictionary* props = solidPropertiesOf(name))
        {
            // The solver takes the material's rho (and sets the particles'
            // mass from it): a second value here would hold only in 0/.
            if (dict.found("rho") && props->found("rho"))
            {
                const scalar material = props->getDimensioned<scalar>("rho",
                    dimensions::density());
                if (std::fabs(spec.rho - material) > 1e-9*std::fabs(material))
                {
                    dict.fatalAt("rho", "Keyword 'rho' of solid body '" + name
                        + "': " + shapeDetail::str(spec.rho) + " differs from"
                          " rho " + shapeDetail::str(material) + " of "
                        + props->name() + ", which the solver uses (it sets"
                          " the particles' mass from it): give the density"
                          " in one place, constant/solidProperties");
                }
            }
            spec.material.emplace(vcpmMaterial::read(*props, spec.name,
                nDimensions_, spec.rho, dp));
        }
    }

    specs_.push_back(std::move(spec));
}


std::optional<scalar> particleGenerator::fluidRho0()
{
    if (rho0_) return rho0_;
    const fs::path file = caseDir_/"constant"/"fluidProperties";
    if (!fs::is_regular_file(file))
    {
        return std::nullopt;
    }
    const dictionary props = dictionary::fromFile(file);
    const scalar rho0 =
        props.getDimensioned<scalar>("rho0", dimensions::density());
    if (!(rho0 > 0))
    {
        props.fatalAt("rho0", "Keyword 'rho0': the reference density"
            " must be positive, found " + shapeDetail::str(rho0));
    }
    rho0_ = rho0;
    return rho0_;
}


scalar particleGenerator::defaultRho
(
    const entry& body,
    bodyType type
)
{
    const std::string& name = body.keyword();
    const std::string what = "Body '" + name + "' (" + bodyTypeName(type)
        + ") has no rho";

    if (type != bodyType::solid)
    {
        if (const std::optional<scalar> rho0 = fluidRho0()) return *rho0;
        fatalIOError(body.file(), body.line(), what + ", and "
            + (caseDir_/"constant"/"fluidProperties").string() + " (whose"
              " rho0 is the density of fluids and walls) does not exist:"
              " give rho0 there", "rho");
    }

    if (!solidProperties_)
    {
        const fs::path file = caseDir_/"constant"/"solidProperties";
        if (!fs::is_regular_file(file))
        {
            fatalIOError(body.file(), body.line(), what + ", and "
                + file.string() + " does not exist: give rho in the body, or"
                  " in constant/solidProperties as " + name + " { rho ...; }",
                "rho");
        }
        solidProperties_ = dictionary::fromFile(file);
    }
    const dictionary& props = solidProperties_->subDict(name);
    const scalar rho =
        props.getDimensioned<scalar>("rho", dimensions::density());
    if (!(rho > 0))
    {
        props.fatalAt("rho", "Keyword 'rho': the density of solid '" + name
            + "' must be positive, found " + shapeDetail::str(rho));
    }
    return rho;
}


const dictionary* particleGenerator::solidPropertiesOf(const std::string& name)
{
    if (!solidProperties_)
    {
        const fs::path file = caseDir_/"constant"/"solidProperties";
        if (!fs::is_regular_file(file))
        {
            return nullptr;
        }
        solidProperties_ = dictionary::fromFile(file);
    }
    return solidProperties_->findDict(name);
}


void particleGenerator::checkSolid
(
    const bodySpec& spec,
    particleBody& body,
    bodySummary& summary
) const
{
    const std::string what = "Solid '" + spec.name + "'";

    if (spec.clamp)
    {
        const scalar tol = 1e-9*spec.dp;
        std::vector<label>& clamped = body.addLabelField("clamped", 0);
        const std::vector<point>& position = body.position();
        label nClamped = 0;
        for (label p = 0; p < body.size(); ++p)
        {
            clamped[p] =
                spec.clamp->inside(toVec3(position[p]), tol) ? 1 : 0;
            nClamped += clamped[p];
        }
        if (!nClamped)
        {
            const boundBox bb = spec.clamp->bounds();
            fatalIOError(spec.clampFile, spec.clampLine, what + ": its clamp"
                " holds none of its " + std::to_string(body.size())
                + " particles (clamp within "
                + shapeDetail::str(bb.min, nDimensions_) + " to "
                + shapeDetail::str(bb.max, nDimensions_) + "): a clamp must"
                " overlap the body's shapes", "clamp");
        }
        // Held at one point (2D) or along one line (3D), the solid turns
        // about it freely: most likely a clamp box that only grazes the
        // body. A clamp usually holds the part inside a support.
        bool pivot = nClamped < nDimensions_;
        if (!pivot && nDimensions_ == 3)
        {
            label a = -1, b = -1;
            pivot = true;
            for (label p = 0; p < body.size() && pivot; ++p)
            {
                if (!clamped[p]) continue;
                if (a < 0) { a = p; continue; }
                if (b < 0) { b = p; continue; }
                const vec3 ab = toVec3(position[b] - position[a]);
                const vec3 ap = toVec3(position[p] - position[a]);
                pivot = mag(cross(ab, ap)) <= 1e-6*mag(ab)*mag(ap);
            }
        }
        if (pivot && nClamped < body.size())
        {
            const boundBox bb = spec.clamp->bounds();
            warning(what + ": its clamp holds only " + std::to_string(nClamped)
                + " of its " + std::to_string(body.size()) + " particles, "
                + (nDimensions_ == 2 ? "one point" : "on one line")
                + ", about which the solid can turn freely (clamp within "
                + shapeDetail::str(bb.min, nDimensions_) + " to "
                + shapeDetail::str(bb.max, nDimensions_) + "); a clamp"
                " usually holds the part of the body inside a support, a few"
                " layers deep", spec.clampFile, spec.clampLine);
        }
        if (nClamped == body.size())
        {
            // Held everywhere it neither bends nor moves (unless the
            // clamp's motion moves it rigidly): most likely a clamp box
            // drawn round the whole body.
            warning(what + ": its clamp holds all of its "
                + std::to_string(body.size()) + " particles, so it cannot"
                  " deform; a clamp usually holds one end (the part inside a"
                  " support)", spec.clampFile, spec.clampLine);
        }
        summary.nClamped = nClamped;
    }

    // Only members thinner than these layers matter: under 2 always, and
    // in 2D with a material the 5 % minimum of vcpmBeam.H.
    label minLayers = 2;
    const bool bending = nDimensions_ == 2 && spec.material;
    if (bending)
    {
        minLayers = std::max<label>(minLayers, minimumLayers(
            thinMemberTolerance, *spec.material));
    }
    const latticeMembers members =
        findThinMembers(toVectors(body.position()), spec.dp, nDimensions_,
                        minLayers);
    summary.thinnestLayers = members.thinnestLayers;

    if (!members.hasSecondNeighbours || (members.thinnestLayers >= 0
     && members.thinnestLayers < 2))
    {
        std::ostringstream os;
        os << what << " is too thin for the VCPM lattice: ";
        if (members.thinnestLayers >= 0)
        {
            const vec3 p = toVec3(body.position()[members.where]);
            os << "a member only " << members.thinnestLayers << " particle"
               << " thick (at " << shapeDetail::str(p, nDimensions_) << ")";
        }
        else
        {
            os << "no two of its " << body.size() << " particles are"
               << " diagonal neighbours";
        }
        os << " has no second-neighbour bonds across it, so it has no"
           << " shear or bending stiffness: make the solid at least 2"
           << " particles (2 dp = " << 2*spec.dp << " m) thick everywhere";
        fatalIOError(spec.file, spec.line, os.str(), spec.name);
    }

    if (bending && members.thinnestLayers >= 0)
    {
        const scalar error = thinMemberStiffnessError(
            scalar(members.thinnestLayers), *spec.material);
        if (std::abs(error) > thinMemberTolerance)
        {
            const vec3 p = toVec3(body.position()[members.where]);
            const scalar needed = spec.dp*members.thinnestLayers/minLayers;
            std::ostringstream os;
            os.precision(3);
            os << what << ": its thinnest member is "
               << members.thinnestLayers << " layers thick (at "
               << shapeDetail::str(p, nDimensions_) << "), so its bending"
               << " stiffness is expected " << 100*error << " % off ("
               << (error < 0 ? "too soft" : "too stiff") << ", docs/vcpm.md"
               << "); " << minLayers << " layers give at most "
               << 100*thinMemberTolerance << " % at nu = "
               << spec.material->nu << " (surface correction "
               << (spec.material->surfaceCorrection ? "on" : "off")
               << "): refine dp to at most " << needed << " m";
            // A solid's dp is the top-level dp over 1 to 4: name the
            // coarsest of those that is fine enough, if one is.
            label r = 1;
            while (r <= 4 && dp_/r > needed*(1 + 1e-9)) ++r;
            if (r <= 4)
            {
                os << " (the solid's own dp may be the top-level dp "
                   << dp_ << " divided by 1 to 4: 'dp "
                   << std::setprecision(10) << dp_/r
                   << std::setprecision(3) << ";'"
                   << " in its entry gives at least "
                   << std::lround(members.thinnestLayers*spec.dp*r/dp_)
                   << " layers)";
            }
            else
            {
                os << " (finer than the top-level dp " << dp_ << " divided by"
                   << " 4, the finest a solid's own dp may be: refine the"
                   << " top-level dp)";
            }
            warning(os.str(), spec.file, spec.line);
        }
    }
}


void particleGenerator::readControlDict()
{
    const fs::path file = caseDir_/"system"/"controlDict";
    if (!fs::is_regular_file(file))
    {
        return;
    }
    // Only the write settings matter here; the solver checks the rest.
    const dictionary control = dictionary::fromFile(file);
    format_ = writeFormatFromName(
        control.getWordOrDefault("writeFormat", {"ascii", "binary"}, "ascii"));
    const label precision = control.getOrDefault<label>("writePrecision", 10);
    if (precision < 1 || precision > 17)
    {
        control.fatalAt("writePrecision", "Keyword 'writePrecision': expected"
            " 1 to 17 significant digits, found " + std::to_string(precision));
    }
    precision_ = int(precision);
}


// * * * * * * * * * * * * * * * Member Functions * * * * * * * * * * * * * //

void particleGenerator::generate()
{
    bodies_.clear();
    summaries_.clear();

    // Solids, then walls too, by spacing: a node keeps (dp + dp_o)/2 from
    // an obstacle particle of spacing dp_o.
    std::map<scalar, std::vector<vec3>> obstacles;
    std::vector<obstacleBody> obstacleBodies;   // the same, body by body

    for (const bodyType type : buildOrder)
    {
        const bool anyOfType = std::any_of(specs_.begin(), specs_.end(),
            [&](const bodySpec& spec) { return spec.type == type; });
        if (!anyOfType)
        {
            continue;   // no locator over millions of obstacles for nothing
        }

        // Built once per stage: walls avoid solids, fluids avoid both.
        std::vector<std::pair<scalar, pointLocator>> near;
        if (type != bodyType::solid)
        {
            for (auto& [obstacleDp, points] : obstacles)
            {
                near.emplace_back(obstacleDp, pointLocator(points, dp_));
            }
        }

        // The bodies of this type so far, by spacing: two of one type
        // must not overlap (two fluids filled into one box would put a
        // particle on every particle of the other).
        struct sameTypeBodies
        {
            std::vector<vec3> nodes;
            std::string names;
        };
        std::map<scalar, sameTypeBodies> sameType;
        for (const bodySpec& spec : specs_)
        {
            if (spec.type != type)
            {
                continue;
            }
            const std::string what =
                "body '" + spec.name + "' (" + bodyTypeName(type) + ")";
            std::vector<vec3> nodes;
            const scalar cellVolume = std::pow(spec.dp, nDimensions_);
            try
            {
                nodes = lattice(spec.origin, spec.dp, nDimensions_)
                    .fill(spec.shapes, what, particlesMemoryTakes());
            }
            catch (const FatalError& err)
            {
                // The lattice knows the body, not where it is written (an
                // STL's own errors name the STL).
                if (err.isIOError()) throw;
                fatalIOError(spec.file, spec.line, err.message(), spec.name);
            }
            for (const auto& [earlierDp, earlier] : sameType)
            {
                const pointLocator locator(earlier.nodes, dp_);
                const scalar minDistance = 0.5*(spec.dp + earlierDp)
                    *(1 - overlapTolerance);
                const std::size_t nOverlap = std::count_if(nodes.begin(),
                    nodes.end(), [&](const vec3& p)
                    { return locator.anyWithin(p, minDistance); });
                if (nOverlap)
                {
                    std::ostringstream os;
                    os << "Body '" << spec.name << "' ("
                       << bodyTypeName(type) << ") overlaps the "
                       << bodyTypeName(type) << " bod"
                       << (earlier.names.find(',') == std::string::npos
                           ? "y " : "ies ") << earlier.names << ": "
                       << nOverlap << " of its lattice nodes lie within"
                       << " (dp + dp_o)/2 of their particles. Make it one"
                       << " body, or shape the two apart";
                    fatalIOError(spec.file, spec.line, os.str(), spec.name);
                }
            }

            const std::size_t nNodes = nodes.size();
            std::size_t nNearSolid = 0;     // walls: nodes a solid covers
            boundBox dropped = boundBox::invalid();   // where they lie
            for (const auto& [obstacleDp, locator] : near)
            {
                const scalar minDistance =
                    0.5*(spec.dp + obstacleDp)*(1 - overlapTolerance);
                std::size_t kept = 0;
                for (const vec3& p : nodes)
                {
                    if (!locator.anyWithin(p, minDistance))
                    {
                        nodes[kept++] = p;
                    }
                    else
                    {
                        dropped.add(p);
                    }
                }
                nodes.resize(kept);
            }
            if (type == bodyType::wall)
            {
                nNearSolid = nNodes - nodes.size();
            }
            const scalar gapExcess = type == bodyType::fluid
              ? interfaceGapExcess(nodes, spec, obstacleBodies, obstacles)
              : 0;
            if (nNearSolid)
            {
                // A solid inside a wall would be pushed by nothing and
                // held by nothing there: clamp it instead (its clamp
                // holds it, the fluid sees it as a wall).
                std::string solids;
                for (const bodySpec& o : specs_)
                {
                    if (o.type != bodyType::solid) continue;
                    solids += (solids.empty() ? "" : ", ") + o.name;
                }
                std::ostringstream os;
                os << "Wall body '" << spec.name << "' overlaps the solid"
                   << " body (" << solids << "): " << nNearSolid << " of its"
                   << " lattice nodes lie within (dp + dp_s)/2 of solid"
                   << " particles, from "
                   << shapeDetail::str(dropped.min, nDimensions_) << " to "
                   << shapeDetail::str(dropped.max, nDimensions_)
                   << ". Shape the wall around the solid, or hold"
                   << " the solid's end with its clamp { ... } instead of"
                   << " burying it in the wall";
                fatalIOError(spec.file, spec.line, os.str(),
                             spec.name);
            }

            if (nodes.empty())
            {
                std::ostringstream os;
                os << "Body '" << spec.name << "' (" << bodyTypeName(type)
                   << ") has no particles: ";
                if (nNodes)
                {
                    os << "all " << nNodes << " lattice nodes of its shapes"
                       << " lie closer than dp to "
                       << (type == bodyType::wall ? "solid" : "wall or solid")
                       << " particles";
                }
                else
                {
                    os << "no node of its lattice (spacing " << spec.dp
                       << ", origin (" << spec.origin.x << ' '
                       << spec.origin.y << ' ' << spec.origin.z << "))"
                       << " lies inside its shapes"
                       << (nDimensions_ == 2 ? " in the z = 0 plane" : "")
                       << ": check their sizes against dp";
                }
                fatalIOError(spec.file, spec.line, os.str(), spec.name);
            }

            particleBody body(spec.name, type, nDimensions_, spec.dp);
            body.resize(label(nodes.size()));
            std::transform(nodes.begin(), nodes.end(),
                           body.position().begin(),
                           [](const vec3& x) { return toPoint(x); });
            body.addVectorField("U", spec.U);
            body.addScalarField("rho", spec.rho);
            body.addScalarField("mass", spec.rho*cellVolume);

            bodySummary s;
            s.name = spec.name;
            s.type = type;
            s.nParticles = body.size();
            s.nDropped = label(nNodes - nodes.size());
            s.gapExcess = gapExcess;
            s.volume = body.size()*cellVolume;
            s.dp = spec.dp;
            s.givenDp = spec.givenDp;
            if (type == bodyType::wall) s.U = spec.U;
            s.shapeVolume = spec.shapes.volume();
            if (type == bodyType::solid)
            {
                checkSolid(spec, body, s);
            }
            summaries_.push_back(s);

            if (type != bodyType::fluid)
            {
                std::vector<vec3>& o = obstacles[spec.dp];
                obstacleBodies.push_back({spec.name, spec.dp, o.size(),
                                          nodes.size(),
                                          type == bodyType::solid});
                o.insert(o.end(), nodes.begin(), nodes.end());
            }
            sameTypeBodies& group = sameType[spec.dp];
            group.nodes.insert(group.nodes.end(), nodes.begin(), nodes.end());
            group.names += (group.names.empty() ? "" : ", ") + spec.name;
            bodies_.push_back(std::move(body));
        }
    }
    warnSolidsOutside();
}


void particleGenerator::warnSolidsOutside() const
{
    // Fluid and walls: where the water can go. A solid clear of their box
    // (a slip of a coordinate) feels nothing, yet the run goes on.
    boundBox scene = boundBox::invalid();
    for (const particleBody& b : bodies_)
    {
        if (b.type() == bodyType::solid) continue;
        for (const point& x : b.position()) scene.add(toVec3(x));
    }
    if (!scene.valid()) return;   // solids alone
    for (std::size_t k = 0; k < bodies_.size(); ++k)
    {
        const particleBody& b = bodies_[k];
        if (b.type() != bodyType::solid || b.size() == 0) continue;
        boundBox box = boundBox::invalid();
        for (const point& x : b.position()) box.add(toVec3(x));
        bool apart = false;
        for (int d = 0; d < nDimensions_; ++d)
        {
            apart |= box.min[d] > scene.max[d] + dp_
                  || box.max[d] < scene.min[d] - dp_;
        }
        if (!apart) continue;
        const bodySpec& spec = *std::find_if(specs_.begin(), specs_.end(),
            [&](const bodySpec& s) { return s.name == b.name(); });
        warning("Solid '" + b.name() + "' lies outside the box of the fluid"
            " and the walls (" + shapeDetail::str(scene.min, nDimensions_)
            + " to " + shapeDetail::str(scene.max, nDimensions_) + "): its"
            " particles span " + shapeDetail::str(box.min, nDimensions_)
            + " to " + shapeDetail::str(box.max, nDimensions_) + ": at the"
            " start no water reaches it (unless it falls or a motion carries"
            " it in). Check its shapes, clamp and latticeOrigin",
            spec.file, spec.line);
    }
}


void particleGenerator::printSummary(std::ostream& os) const
{
    const std::string unit = volumeUnit(nDimensions_);
    os << "Bodies (" << nDimensions_ << "D, dp " << dp_ << ")\n";
    std::int64_t total = 0;
    for (const bodySummary& s : summaries_)
    {
        os << "    " << s.name << " (" << bodyTypeName(s.type) << "): "
           << s.nParticles << " particles, volume " << s.volume << unit;
        if (s.shapeVolume >= 0)
        {
            os << " (shapes " << s.shapeVolume << unit;
            if (s.shapeVolume > 0)
            {
                // particles x dp^d against the shapes: the filling error.
                std::ostringstream err;
                err.setf(std::ios::fixed | std::ios::showpos);
                err.precision(2);
                const scalar e = 100*(s.volume - s.shapeVolume)/s.shapeVolume;
                err << (std::abs(e) < 0.005 ? scalar(0) : e);   // no -0.00
                os << ", error " << err.str() << " %";
            }
            os << ")";
        }
        const bool snapped = s.givenDp > 0
            && std::abs(s.givenDp - s.dp) > 1e-9*s.dp;
        if (s.dp != dp_ || snapped)
        {
            os << ", dp " << s.dp << " (dp/" << std::lround(dp_/s.dp);
            if (snapped) os << ", for the dp " << s.givenDp << " given";
            os << ")";
        }
        if (s.nClamped >= 0)
        {
            os << ", " << s.nClamped << " clamped";
        }
        if (s.nDropped)
        {
            os << ", " << s.nDropped << " dropped next to "
               << (s.type == bodyType::wall ? "solids" : "walls or solids");
        }
        if (mag(s.U) > 0)
        {
            // A wall stays in place: its U is what the fluid sees at its
            // face (a belt, a cavity's lid), not a motion.
            os << ", surface velocity U (" << s.U.x << ' ' << s.U.y << ' '
               << s.U.z << ") m/s, in place (a motion goes in"
               << " constant/motion)";
        }
        if (s.gapExcess > gapExcessNoted)
        {
            os << ", its first layer " << s.gapExcess << " dp beyond the"
               << " contact gap on average at its worst face";
        }
        os << "\n";
        total += s.nParticles;
    }
    os << "Total: " << total << " particles in " << summaries_.size()
       << (summaries_.size() == 1 ? " body" : " bodies") << "\n";
}


void particleGenerator::warnUnequalGaps
(
    const bodySpec& spec,
    const obstacleBody& o,
    const double sum[6],
    const label n[6]
) const
{
    // The pressure of still water on each face acts on the first layer's
    // particles: a face with a wider gap is pushed less, so the solid is
    // pushed toward it (a plate 0.75 dp thick with gaps 0 and 0.25 dp
    // beyond the contact gap bent 5-7 % of its length in still water).
    for (int axis = 0; axis < 3; ++axis)
    {
        const int lo = 2*axis, hi = 2*axis + 1;   // fluid on its -, + side
        if (n[lo] < 3 || n[hi] < 3) continue;
        const scalar eLo = scalar(sum[lo]/n[lo]/spec.dp);
        const scalar eHi = scalar(sum[hi]/n[hi]/spec.dp);
        if (std::abs(eHi - eLo) <= gapAsymmetryWarned) continue;
        const char name = "xyz"[axis];
        std::ostringstream os;
        os.precision(3);
        os << "Fluid body '" << spec.name << "' lies on both sides of solid '"
           << o.name << "' along " << name << ", with gaps that differ: its"
           << " first layer stands on average " << eLo << " dp beyond the"
           << " contact gap on the -" << name << " face and " << eHi
           << " dp on the +" << name << " face. The fluid beyond the wider"
           << " gap pushes less, so the solid moves toward it (a thin plate"
           << " bends) in still water. The solid moved by "
           << 0.5*(eHi - eLo)*spec.dp << " m along " << name << " (its"
           << " shapes, clamp and latticeOrigin together) makes the two"
           << " equal (" << 0.5*(eLo + eHi) << " dp each); a solid whose"
           << " thickness there is a whole number of the fluid's spacings"
           << " can have both at 0";
        warning(os.str(), spec.file, spec.line);
    }
}


scalar particleGenerator::interfaceGapExcess
(
    const std::vector<vec3>& nodes,
    const bodySpec& spec,
    const std::vector<obstacleBody>& bodies,
    const std::map<scalar, std::vector<vec3>>& obstacles
) const
{
    // The contact push holds fluid at (dp + dp_o)/2 from walls and solids
    // and nothing pulls it closer: a first layer standing farther off (a
    // face between the fluid lattice's nodes) falls into the gap at the
    // start, and "still" water flows for seconds. The mean excess of the
    // first layer (nodes within the gap plus 0.9 dp), in dp, largest over
    // the obstacles, body by body and face by face (one that lies well on
    // the lattice must not hide another: a baffle right on one side and
    // half a spacing off on the other averaged to a quarter). A node's
    // face is the direction, to the nearest axis, from its nearest
    // obstacle particle.
    scalar worst = 0;
    std::string worstName, worstFace;
    for (const obstacleBody& o : bodies)
    {
        const scalar gap = 0.5*(spec.dp + o.dp);
        const scalar window = gap + 0.9*spec.dp;
        const std::vector<vec3>& all = obstacles.at(o.dp);
        const pointLocator locator(std::vector<vec3>(all.begin() + o.first,
            all.begin() + o.first + o.count), window);
        double sum[6] = {0, 0, 0, 0, 0, 0};
        label n[6] = {0, 0, 0, 0, 0, 0};
        for (const vec3& p : nodes)
        {
            vec3 q;
            const scalar d = locator.nearestWithinCell(p, q);
            if (d >= window) continue;
            const vec3 out = p - q;
            int axis = 0;
            for (int a = 1; a < 3; ++a)
            {
                if (std::abs(out[a]) > std::abs(out[axis])) axis = a;
            }
            const int face = 2*axis + (out[axis] > 0 ? 1 : 0);
            sum[face] += std::max<scalar>(0, d - gap);
            ++n[face];
        }
        if (o.solid)
        {
            warnUnequalGaps(spec, o, sum, n);
        }
        for (int face = 0; face < 6; ++face)
        {
            // A face of fewer nodes is a corner's, or a member's end.
            if (n[face] < 3 || sum[face]/n[face]/spec.dp <= worst) continue;
            worst = scalar(sum[face]/n[face]/spec.dp);
            worstName = o.name;
            worstFace = std::string(face % 2 ? "+" : "-") + "xyz"[face/2];
        }
    }
    if (worst > gapExcessWarned)
    {
        std::ostringstream os;
        os  << "Fluid body '" << spec.name << "': its first layer of"
            << " particles stands on average " << worst << " dp farther"
            << " from the " << worstFace << " face of body '" << worstName
            << "' than the contact gap"
            << " (dp + dp_o)/2 that the solver holds: its faces lie between"
            << " the fluid lattice's nodes. The fluid falls into the gap at the start,"
            << " and still water flows. Put the faces half a spacing from"
            << " the fluid's nodes (a box of the fluid's spacing around"
            << " them), or move the fluid's latticeOrigin";
        warning(os.str(), spec.file, spec.line);
    }
    return worst;
}


void particleGenerator::write() const
{
    // A restart (startFrom latestTime) goes on from a later time, not from
    // this 0/; the solids' reference lattice must stay the one it ran from.
    // Said before 0/ is replaced, so that an interrupted write still says it.
    std::string later;
    for (const timeInstant& t : findTimes(caseDir_))
    {
        if (t.value > 0) later += " " + t.name;
    }
    if (!later.empty())
    {
        warning("The case has later time directories:" + later + ". The"
            " solver goes on from the latest of them (startFrom latestTime),"
            " not from the 0/ written now, and refuses a solid whose 0/ has"
            " changed: remove them for a fresh start");
    }

    writeTimeDirectory(caseDir_, timeState(), bodies_, format_, precision_);
}

} // End namespace sphvcpm
