/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "sphModel.H"
#include "error.H"
#include "formatting.H"

#include <cmath>

namespace sphvcpm
{

boundaryContact boundaryContactOf(const sphModel& m)
{
    boundaryContact b;
    if (m.contact <= 0) return b;
    b.strength = m.contact*m.c0*m.c0/(m.rho0*std::pow(m.dp, m.nDimensions));
    b.dp = m.dp;
    b.invRho0 = 1/m.rho0;
    b.nDimensions = m.nDimensions;
    // Walls share the fluid's spacing, solids are finer (dp/1 to dp/4).
    const scalar radiusMax = boundaryContact::kappa*m.dp;
    b.radiusMax2 = radiusMax*radiusMax;
    return b;
}


std::string kernelName(const kernelType k)
{
    return k == kernelType::wendlandC2 ? "wendlandC2" : "cubicSpline";
}

std::string densityDiffusionName(const densityDiffusionType d)
{
    switch (d)
    {
        case densityDiffusionType::none: return "none";
        case densityDiffusionType::molteniColagrossi:
            return "molteniColagrossi";
        default: return "fourtakas";
    }
}

std::string viscosityName(const viscosityType v)
{
    return v == viscosityType::laminar ? "laminar" : "artificial";
}

std::string timeSchemeName(const timeSchemeType t)
{
    return t == timeSchemeType::verlet ? "verlet" : "symplectic";
}


std::string shiftingName(const shiftingType s)
{
    return s == shiftingType::none ? "none" : "fickian";
}


namespace
{

// required: the end of the message where the file is missing ("" when
// it may be).
dictionary readCaseDict(const std::filesystem::path& caseDir,
                        const std::string& relative,
                        const std::string& required)
{
    const auto file = caseDir/relative;
    if (!std::filesystem::exists(file))
    {
        if (!required.empty())
        {
            fatalIOError(file.string(), 0, "cannot find the file "
                + relative + " of the case" + required);
        }
        return dictionary(file.string());
    }
    return dictionary::fromFile(file);
}

// A sub-dictionary with a required 'type' word, or a plain word entry
// (densityDiffusion none;) meaning the type alone.
std::string typeOf(const dictionary& dict, const std::string& key,
                   const std::vector<std::string>& allowed,
                   const std::string& deflt, const dictionary** sub)
{
    *sub = nullptr;
    if (!dict.found(key))
    {
        return deflt;
    }
    if (dict.isDict(key))
    {
        *sub = &dict.subDict(key);
        return (*sub)->getWord("type", allowed);
    }
    return dict.getWord(key, allowed);
}

// Keywords of one type in another type's sub-dictionary would be silently
// unused (alpha under laminar): an error naming them.
void onlyForType(const dictionary& sub, const std::vector<std::string>& keys,
                 const std::string& type, const std::string& owner)
{
    if (type == owner) return;
    for (const std::string& k : keys)
    {
        if (sub.found(k))
        {
            sub.fatalAt(k, "'" + k + "' applies to type " + owner
                + " only; with type " + type + " it would have no effect");
        }
    }
}

} // End anonymous namespace


sphModel readSphModel(const std::filesystem::path& caseDir,
                      const int nDimensions, const scalar dp)
{
    sphModel m;
    m.nDimensions = nDimensions;
    m.dp = dp;

    // system/sphSchemes
    {
        dictionary dict = readCaseDict(caseDir, "system/sphSchemes",
            " (an empty one takes every default: docs/solver.md)");
        dict.setCaseDimensions(nDimensions);
        dict.checkKeywords({"kernel", "hOverDp", "cellDivisor",
            "densityDiffusion", "viscosity", "shifting", "boundary",
            "domain", "initialDensity", "timeScheme"});

        m.kernel = dict.getWordOrDefault("kernel",
            {"wendlandC2", "cubicSpline"}, "wendlandC2") == "wendlandC2"
          ? kernelType::wendlandC2 : kernelType::cubicSpline;

        m.hOverDp = dict.getOrDefault<scalar>("hOverDp", 1.5);
        if (!(m.hOverDp >= 0.9 && m.hOverDp <= 3))
        {
            dict.fatalAt("hOverDp", "hOverDp " + std::to_string(m.hOverDp)
                + " is outside the usable range [0.9, 3]"
                  " (1.5 is recommended)");
        }
        m.h = m.hOverDp*dp;

        // 0: by device (the solver picks 2 on the CPU, 3 on the GPU)
        m.cellDivisor = dict.getOrDefault<label>("cellDivisor", 0);
        if (dict.found("cellDivisor")
         && (m.cellDivisor < 1 || m.cellDivisor > 4))
        {
            dict.fatalAt("cellDivisor",
                "cellDivisor must be 1, 2, 3 or 4 (cells of 2h/cellDivisor)");
        }

        const dictionary* sub = nullptr;
        const std::string dd = typeOf(dict, "densityDiffusion",
            {"fourtakas", "molteniColagrossi", "none"}, "fourtakas", &sub);
        m.densityDiffusion =
            dd == "fourtakas" ? densityDiffusionType::fourtakas
          : dd == "none" ? densityDiffusionType::none
          : densityDiffusionType::molteniColagrossi;
        if (sub)
        {
            sub->checkKeywords({"type", "delta"});
            if (dd == "none")
            {
                onlyForType(*sub, {"delta"}, dd,
                            "fourtakas or molteniColagrossi");
            }
            m.delta = sub->getOrDefault<scalar>("delta", 0.1);
            if (!(m.delta >= 0 && m.delta <= 1))
            {
                sub->fatalAt("delta", "delta must be in [0, 1] (0.1 is"
                    " the usual value)");
            }
        }

        const std::string visc = typeOf(dict, "viscosity",
            {"laminar", "artificial"}, "laminar", &sub);
        m.viscosity = visc == "laminar"
          ? viscosityType::laminar : viscosityType::artificial;
        if (sub)
        {
            sub->checkKeywords({"type", "alpha"});
            onlyForType(*sub, {"alpha"}, visc, "artificial");
            if (m.viscosity == viscosityType::artificial && sub->found("alpha"))
            {
                m.alpha = sub->getPositive("alpha");
            }
        }

        const std::string shift = typeOf(dict, "shifting",
            {"none", "fickian"}, "none", &sub);
        m.shifting = shift == "none" ? shiftingType::none
                                     : shiftingType::fickian;
        if (sub)
        {
            sub->checkKeywords({"type", "coefficient",
                "freeSurfaceThreshold", "maxShift", "noBoundary"});
            onlyForType(*sub, {"coefficient", "freeSurfaceThreshold",
                "maxShift", "noBoundary"}, shift, "fickian");
            m.shiftCoefficient =
                sub->getOrDefault<scalar>("coefficient", -2);
            m.shiftFreeSurface = sub->getOrDefault<scalar>(
                "freeSurfaceThreshold", nDimensions == 3 ? 2.75 : 1.5);
            m.maxShiftFraction = sub->getOrDefault<scalar>("maxShift", 0.1);
            m.shiftNoBoundary = sub->getOrDefault<bool>("noBoundary", true);
        }
        else if (m.shifting == shiftingType::fickian)
        {
            m.shiftFreeSurface = nDimensions == 3 ? 2.75 : 1.5;
        }

        typeOf(dict, "boundary", {"adami"}, "adami", &sub);
        if (sub)
        {
            sub->checkKeywords({"type", "contact"});
            m.contact = sub->getOrDefault<scalar>("contact", 1);
            if (!(m.contact >= 0 && m.contact <= 10))
            {
                sub->fatalAt("contact", "contact must be in [0, 10]"
                    " (1 is the default; 0 turns the push off)");
            }
        }
        const std::string scheme = typeOf(dict, "timeScheme",
            {"symplectic", "verlet"}, "symplectic", &sub);
        m.timeScheme = scheme == "verlet"
          ? timeSchemeType::verlet : timeSchemeType::symplectic;
        if (sub)
        {
            sub->checkKeywords({"type", "verletSteps"});
            onlyForType(*sub, {"verletSteps"}, scheme, "verlet");
            if (m.timeScheme == timeSchemeType::verlet)
            {
                m.verletSteps = sub->getOrDefault<label>("verletSteps", 40);
                if (m.verletSteps < 1)
                {
                    sub->fatalAt("verletSteps", "verletSteps must be a"
                        " positive number of steps (40 is usual)");
                }
            }
        }
        if (m.timeScheme == timeSchemeType::verlet
         && m.shifting != shiftingType::none)
        {
            dict.fatalAt("timeScheme", "shifting moves particles in the"
                " symplectic corrector: use timeScheme symplectic with"
                " shifting");
        }

        m.hydrostaticStart = dict.getWordOrDefault("initialDensity",
            {"hydrostatic", "asRead"}, "hydrostatic") == "hydrostatic";

        if (const dictionary* dom = dict.findDict("domain"))
        {
            dom->checkKeywords({"min", "max"});
            m.userDomain = true;
            m.domainMin = dom->get<vec3>("min");
            m.domainMax = dom->get<vec3>("max");
            for (int d = 0; d < nDimensions; ++d)
            {
                if (!(m.domainMax[d] > m.domainMin[d]))
                {
                    dom->fatalAt("max", "domain max must exceed min in"
                        " every direction");
                }
            }
        }
    }

    // constant/fluidProperties
    {
        const dictionary dict =
            readCaseDict(caseDir, "constant/fluidProperties",
                " (it needs rho0, and c0 or coefSound: docs/solver.md)");
        dict.checkKeywords({"rho0", "nu", "c0", "coefSound", "speedSystem",
            "gamma", "turbulence"});
        // Dimensions, where written, must be these ([1 -3 0 0 0 0 0] for a
        // viscosity is a slip that would otherwise run).
        const auto positive = [&dict](const char* key,
                                      const dimensionSet& dims)
        {
            const scalar v = dict.getDimensioned<scalar>(key, dims);
            if (!(v > 0))
            {
                dict.fatalAt(key, "Keyword '" + std::string(key)
                    + "': expected a positive number, found " + str(v));
            }
            return v;
        };
        m.rho0 = positive("rho0", dimensions::density());
        m.nu = dict.found("nu")
          ? dict.getDimensioned<scalar>("nu",
                                        dimensions::kinematicViscosity())
          : scalar(1e-6);
        if (!(m.nu >= 0))
        {
            dict.fatalAt("nu", "the kinematic viscosity nu must be >= 0");
        }
        const bool hasC0 = dict.found("c0");
        const bool hasCoef = dict.found("coefSound");
        if (hasC0 == hasCoef)
        {
            dict.fatal("give exactly one of c0 (speed of sound [m/s]) and"
                " coefSound (c0 = coefSound speedSystem, speedSystem by"
                " default sqrt(g H), H the fluid height)",
                hasC0 ? "c0" : "c0");
        }
        // The largest speed the flow reaches, where the free fall over the
        // fluid's height overstates it (sloshing, a slow current): sets
        // c0 with coefSound and the speed the check of c0 expects.
        if (dict.found("speedSystem"))
        {
            m.speedSystem = dict.getDimensioned<scalar>("speedSystem",
                dimensions::velocity());
            if (!(m.speedSystem > 0))
            {
                dict.fatalAt("speedSystem", "Keyword 'speedSystem': the"
                    " largest flow speed expected (m/s) must be > 0");
            }
        }
        if (hasC0)
        {
            m.c0 = positive("c0", dimensions::velocity());
        }
        else
        {
            m.coefSound = dict.getPositive("coefSound");
        }
        m.gamma = dict.getOrDefault<scalar>("gamma", 7);
        if (!(m.gamma >= 1))
        {
            dict.fatalAt("gamma", "the Tait exponent gamma must be >= 1");
        }
        m.sps = dict.getWordOrDefault("turbulence", {"off", "SPS"}, "off")
             == "SPS";
    }

    m.g = readGravity(caseDir, nDimensions);

    return m;
}

} // End namespace sphvcpm
