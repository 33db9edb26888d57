/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "prescribedMotions.H"
#include "error.H"
#include "solidBodySet.H"

#include <cmath>
#include <ostream>

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

} // End namespace sphvcpm
