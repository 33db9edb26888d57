/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "prescribedMotions.H"
#include "boundBox.H"
#include "error.H"
#include "formatting.H"
#include "solidBodySet.H"
#include "timeDirectory.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <unordered_map>

namespace sphvcpm
{

prescribedMotions::prescribedMotions
(
    const std::filesystem::path& caseDir,
    const std::vector<particleBody>& bodies,
    const int nDimensions,
    const bool withWalls,
    std::ostream& log
)
:
    set_(motionSet::readIfPresent(caseDir, nDimensions))
{
    if (set_.empty()) return;

    std::vector<std::string> allowed, all;
    for (const particleBody& b : bodies)
    {
        all.push_back(b.name());
        bool clamps = false;
        if (b.type() == bodyType::solid && b.hasField("clamped"))
        {
            for (const label c : b.labelField("clamped")) clamps |= c != 0;
        }
        if ((withWalls && b.type() == bodyType::wall) || clamps)
        {
            allowed.push_back(b.name());
        }
    }
    set_.checkBodies(allowed, all, withWalls
        ? "a wall body or a solid body with clamped particles"
        : "a solid body with clamped particles (solids alone: walls are"
          " ignored)");

    for (const namedMotion& m : set_.motions())
    {
        // The plane of a 2D case is z = 0: it must stay there.
        const bool outOfPlane =
            (m.motion.rotates() && (std::fabs(m.motion.axis().x) > 1e-12
                                 || std::fabs(m.motion.axis().y) > 1e-12))
         || (m.motion.translates() && std::fabs(m.motion.direction().z) > 1e-12);
        if (nDimensions == 2 && outOfPlane)
        {
            fatalIOError(m.file, m.line, "Motion " + m.name + " of a 2D"
                " case: its axis must be (0 0 1) or (0 0 -1) and its"
                " direction in the x-y plane, so that the bodies stay in"
                " the plane z = 0", m.motion.rotates() ? "axis"
                                                       : "direction");
        }
        log << "    motion " << m.name << ": "
            << (m.motion.rotates() ? "rotation" : "")
            << (m.motion.rotates() && m.motion.translates() ? " and " : "")
            << (m.motion.translates() ? "translation" : "") << " of";
        for (const std::string& b : m.bodies) log << " " << b;
        log << "\n";
        if (!m.motion.note().empty())
        {
            log << "        " << m.motion.note() << "\n";
        }
    }
    if (nDimensions == 2)
    {
        set_.restrictToPlane();
    }
    for (const particleBody& b : bodies)
    {
        byBody_.push_back(set_.motionOf(b.name()));
    }
}


std::string prescribedMotions::nameOf(const std::size_t b) const
{
    for (const namedMotion& m : set_.motions())
    {
        if (&m.motion == of(b)) return m.name;
    }
    return "";
}


void prescribedMotions::checkWavemakerDepths
(
    const std::vector<particleBody>& bodies,
    const vec3& g,
    const scalar dp
) const
{
    const scalar gMag = mag(g);
    if (!(gMag > 0)) return;
    const vec3 up = -g/gMag;
    const auto across = [&](const point& p)
    {
        const vec3 x = toVec3(p);
        return x - dot(x, up)*up;
    };
    for (const namedMotion& m : set_.motions())
    {
        const scalar depth = m.motion.wavemakerDepth();
        if (!(depth > 0)) continue;
        // The wavemaker's particles projected across g, their box grown
        // by 3 dp: the water beside it is the fluid whose projection lies
        // in that box, its whole column along g.
        boundBox paddle = boundBox::invalid();
        for (const particleBody& b : bodies)
        {
            if (std::find(m.bodies.begin(), m.bodies.end(), b.name())
                == m.bodies.end()) continue;
            for (const point& p : b.position()) paddle.add(across(p));
        }
        if (!paddle.valid()) continue;
        paddle.min -= vec3{3*dp, 3*dp, 3*dp};
        paddle.max += vec3{3*dp, 3*dp, 3*dp};
        const scalar big = std::numeric_limits<scalar>::max();
        scalar bottom = big, top = -big;
        for (const particleBody& b : bodies)
        {
            if (b.type() != bodyType::fluid) continue;
            for (const point& p : b.position())
            {
                const vec3 a = across(p);
                if (!paddle.encloses(boundBox{a, a}, 3)) continue;
                const scalar h = dot(toVec3(p), up);
                bottom = std::min(bottom, h);
                top = std::max(top, h);
            }
        }
        if (top < bottom) continue;   // no water beside it
        const scalar water = top - bottom + dp;
        if (std::fabs(water - depth) <= std::max(1.5*dp, 0.02*depth))
        {
            continue;
        }
        warning("Motion " + m.name + ": its wavemaker's depth is "
            + str(depth) + " m, but the water beside its bodies is "
            + str(water, 4) + " m deep (the fluid within 3 dp of them"
            " across g, from its lowest to its highest particle, +- dp/2)."
            " The stroke, and so the waves' height, follow the depth given:"
            " set depth to the still-water depth at the paddle",
            m.file, m.line);
    }
}


bodyMove prescribedMotions::move(const std::size_t b, const double t0,
                                 const double t1) const
{
    const rigidMotion* m = of(b);
    return m ? m->move(t0, t1) : bodyMove::none();
}


std::vector<const rigidMotion*> prescribedMotions::clampMotions
(
    const solidBodySet& solids
) const
{
    std::vector<const rigidMotion*> out;
    for (const solidBody& s : solids.bodies())
    {
        out.push_back(set_.motionOf(s.name));
    }
    return out;
}


void prescribedMotions::placeSolids(solidBodySet& solids, const double t)
    const
{
    for (solidBody& s : solids.bodies())
    {
        const rigidMotion* m = set_.motionOf(s.name);
        if (!m) continue;
        const rigidTransform T = m->transform(t);
        vcpmSolid& solid = *s.solid;
        for (label i = 0; i < solid.size(); ++i)
        {
            const point X = solid.reference()[i];
            solid.position[i] = T.apply(X);
            solid.velocity[i] = T.velocityAt(X);
        }
    }
}


void prescribedMotions::checkRestart(const std::filesystem::path& caseDir,
    const std::string& startTimeName, const double t,
    const std::vector<particleBody>& bodies, const solidBodySet& solids)
    const
{
    const std::string initial = initialTimeName(caseDir);
    if (set_.empty() || initial.empty() || initial == startTimeName) return;
    // Well above the round-off of ascii writes, well below a change of
    // the motion that matters.
    const auto check = [&](const std::string& what, const std::string& name,
                           const scalar worst, const scalar dp)
    {
        if (!(worst > 0.1*dp)) return;
        fatalError(what + " " + name + " of the restart time "
            + startTimeName + " is up to " + str(worst) + " m (" + str(worst/dp)
            + " dp) from where constant/motion puts it at that time: the"
            " motion has changed since the run that wrote it, and the body"
            " would go on from where it is, off the new motion (and off"
            " the probes and gauges that follow it). Restore"
            " constant/motion as it was, or start again from " + initial
            + " (remove the later times: Allclean)");
    };
    for (std::size_t b = 0; b < bodies.size(); ++b)
    {
        const particleBody& body = bodies[b];
        if (body.type() != bodyType::wall || !of(b)) continue;
        const std::filesystem::path dir = caseDir/initial/body.name();
        particleBody reference(body.name(), body.type(), body.nDimensions(),
                               body.dp());
        readField(dir/"id", reference);
        readField(dir/"position", reference);
        std::unordered_map<label, point> X;
        for (label i = 0; i < reference.size(); ++i)
        {
            X.emplace(reference.id()[i], reference.position()[i]);
        }
        const rigidTransform T = of(b)->transform(t);
        scalar worst = 0;
        for (label i = 0; i < body.size(); ++i)
        {
            const auto found = X.find(body.id()[i]);
            if (found == X.end()) continue;
            worst = std::max(worst, scalar(mag(toVec3(
                T.apply(found->second) - body.position()[i]))));
        }
        check("Wall", body.name(), worst, body.dp());
    }
    for (const solidBody& s : solids.bodies())
    {
        const rigidMotion* m = set_.motionOf(s.name);
        if (!m) continue;
        const rigidTransform T = m->transform(t);
        const vcpmSolid& solid = *s.solid;
        scalar worst = 0;
        for (label i = 0; i < solid.size(); ++i)
        {
            if (!solid.clamped()[i]) continue;
            worst = std::max(worst, scalar(mag(toVec3(
                T.apply(solid.reference()[i]) - solid.position[i]))));
        }
        check("The clamp of solid", s.name, worst, s.dp);
    }
}

} // End namespace sphvcpm
