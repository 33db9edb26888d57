/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The inside of a closed STL surface.

#include "stlShape.H"
#include "error.H"
#include "stlReader.H"

#include <cmath>
#include <sstream>

namespace sphvcpm
{

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

void stlDetail::transform
(
    std::vector<vec3>& points,
    scalar scale,
    const vec3& axis,
    scalar angleDegrees,
    const vec3& translate
)
{
    const scalar angle = angleDegrees*M_PI/180;
    const scalar c = std::cos(angle);
    const scalar s = std::sin(angle);
    const scalar len = mag(axis);
    const vec3 k = len > 0 ? axis/len : vec3{0, 0, 1};
    for (vec3& p : points)
    {
        const vec3 x = scale*p;
        // Rodrigues' rotation formula.
        const vec3 r = c*x + s*cross(k, x) + ((1 - c)*dot(k, x))*k;
        p = r + translate;
    }
}


scalar stlDetail::defaultMergeDistance(const std::vector<vec3>& points)
{
    boundBox b = boundBox::invalid();
    for (const vec3& p : points)
    {
        b.add(p);
    }
    return b.valid() ? 1e-6*mag(b.max - b.min) : 0;
}


std::vector<std::string> stlDetail::surfaceKeywords()
{
    return {"file", "scale", "rotate", "translate", "mergeDistance",
            "checkClosed"};
}


void stlDetail::rethrowForShape
(
    const FatalError& err,
    const std::string& name,
    const dictionary& dict
)
{
    // An error in the surface file: say where the dictionary asked for
    // it, then what is wrong (errors in the dictionary itself name it).
    if (err.file() == dict.file())
    {
        throw err;
    }
    std::string message = err.message();
    const std::string own = "Shape '" + name + "': ";
    if (message.compare(0, own.size(), own) == 0)
    {
        message.erase(0, own.size());
    }
    std::ostringstream os;
    os << "Shape '" << name << "' (" << dict.file() << " line " << dict.line()
       << "): " << message;
    throw FatalError(os.str(), err.file(), err.line(), err.keyword());
}


stlDetail::surfaceInput stlDetail::readSurface
(
    const std::string& name,
    const dictionary& dict,
    const std::filesystem::path& caseDir
)
{
    surfaceInput in;
    const std::filesystem::path file = dict.get<std::string>("file");
    const std::filesystem::path path =
        file.is_absolute() || caseDir.empty() ? file : caseDir/file;
    const std::string problem = fileProblem(path.string());
    if (!problem.empty())
    {
        dict.fatalAt("file", "Keyword 'file': shape '" + name + "': the STL"
            " file " + path.string() + " " + problem
          + (file.is_absolute() ? "" : " (a relative file is taken from the"
             " case directory)"));
    }
    in.source = path.string();

    stlData stl = readSTL(path);

    const scalar scale = dict.getOrDefault<scalar>("scale", 1);
    if (!(std::isfinite(scale) && scale != 0))
    {
        dict.fatalAt("scale", "Keyword 'scale': expected a finite, non-zero"
            " factor (0.001 for a surface in mm), found "
            + shapeDetail::str(scale));
    }
    vec3 axis{0, 0, 1};
    scalar angle = 0;
    if (dict.found("rotate"))
    {
        const dictionary& rot = dict.subDict("rotate");
        rot.checkKeywords({"axis", "angle"});
        axis = unitVector(rot.get<vec3>("axis"));
        angle = rot.get<scalar>("angle");
        if (!(mag(unitVector(axis)) > 0))
        {
            rot.fatalAt("axis", "Keyword 'axis': the rotation axis must be a"
                " finite, non-zero vector, e.g. (0 0 1)");
        }
        if (!std::isfinite(angle))
        {
            rot.fatalAt("angle", "Keyword 'angle': expected a finite angle in"
                " degrees");
        }
    }
    const vec3 translate = dict.getOrDefault<vec3>("translate", {0, 0, 0});
    if (!std::isfinite(mag(translate)))
    {
        dict.fatalAt("translate", "Keyword 'translate': expected a finite"
            " vector");
    }
    stlDetail::transform(stl.vertices, scale, axis, angle, translate);

    in.mergeDistance = -1;
    if (dict.found("mergeDistance"))
    {
        in.mergeDistance = dict.get<scalar>("mergeDistance");
        if (!(in.mergeDistance >= 0) || !std::isfinite(in.mergeDistance))
        {
            dict.fatalAt("mergeDistance", "Keyword 'mergeDistance': expected"
                " a distance >= 0 [m], found "
                + shapeDetail::str(in.mergeDistance));
        }
    }
    in.checkClosed = dict.getOrDefault<bool>("checkClosed", true);
    in.soup = std::move(stl.vertices);
    return in;
}


void stlDetail::checkRepairs
(
    const triSurface& surface,
    const std::string& name,
    const std::string& source,
    scalar mergeDistance
)
{
    const triSurface::repairs& r = surface.repaired();
    if (surface.size() == 0)
    {
        fatalIOError(source, 0, "Shape '" + name + "': no triangle of the"
            " surface is left after dropping " + std::to_string(r.nDegenerate)
          + " degenerate and " + std::to_string(r.nDuplicate) + " coincident"
            " ones");
    }
    if (r.nMergedPoints || r.nDegenerate || r.nDuplicate)
    {
        std::ostringstream os;
        os << "Shape '" << name << "': repaired the surface: "
           << r.nMergedPoints << " vertices merged (closer than "
           << mergeDistance << " m), " << r.nDegenerate << " degenerate"
           << " triangles dropped, " << r.nDuplicate << " coincident"
           << " triangles dropped in pairs; " << surface.size()
           << " triangles left";
        warning(os.str(), source);
    }
}


// * * * * * * * * * * * * * * * Constructors * * * * * * * * * * * * * * * //

stlShape::stlShape
(
    std::string name,
    const std::vector<vec3>& soup,
    const std::string& source,
    scalar mergeDistance,
    bool checkClosed
)
:
    stlShape
    (
        std::move(name),
        input{soup, source, mergeDistance, checkClosed}
    )
{}


stlShape::stlShape
(
    std::string name,
    const dictionary& dict,
    int nDimensions,
    const std::filesystem::path& caseDir
)
try
:
    stlShape(name, read(name, dict, nDimensions, caseDir))
{}
catch (const FatalError& err)
{
    stlDetail::rethrowForShape(err, name, dict);
}


stlShape::stlShape(std::string name, input in)
:
    shape(std::move(name), 3),
    source_(in.source),
    surface_
    (
        in.soup,
        in.mergeDistance < 0
      ? stlDetail::defaultMergeDistance(in.soup)
      : in.mergeDistance
    ),
    inside_(surface_),
    volume_(-1)
{
    check(in.checkClosed, in.mergeDistance < 0
        ? stlDetail::defaultMergeDistance(in.soup) : in.mergeDistance);
    if (surface_.closed())
    {
        volume_ = std::abs(surface_.volume());
    }
}


stlShape::input stlShape::read
(
    const std::string& name,
    const dictionary& dict,
    int nDimensions,
    const std::filesystem::path& caseDir
)
{
    if (nDimensions != 3)
    {
        dict.fatalAt("shape", "Shape '" + name + "': this is the 3D stl"
            " shape; in 2D, shape::New builds the cut of the surface by"
            " z = 0 (stlSliceShape)");
    }

    return stlDetail::readSurface(name, dict, caseDir);
}


// * * * * * * * * * * * * * * * Private Members * * * * * * * * * * * * * //

void stlShape::check(bool checkClosed, scalar mergeDistance) const
{
    stlDetail::checkRepairs(surface_, name_, source_, mergeDistance);

    const std::vector<triSurface::edge>& open = surface_.openEdges();
    if (open.empty())
    {
        return;
    }
    std::ostringstream os;
    os.precision(8);
    boundBox where = boundBox::invalid();
    for (const triSurface::edge& e : open)
    {
        where.add(surface_.points()[e[0]]);
        where.add(surface_.points()[e[1]]);
    }
    os << "Shape '" << name_ << "': the surface is not closed: "
       << open.size() << " open edges (edges used by an odd number of"
       << " triangles: the rim of a hole, or a fold), within (" << where.min.x
       << ' ' << where.min.y << ' ' << where.min.z << ") to (" << where.max.x
       << ' ' << where.max.y << ' ' << where.max.z << ")";
    const std::size_t nList = std::min<std::size_t>(open.size(), 5);
    os << "; the first " << nList << ":";
    for (std::size_t i = 0; i < nList; ++i)
    {
        const vec3& a = surface_.points()[open[i][0]];
        const vec3& b = surface_.points()[open[i][1]];
        os << "\n    (" << a.x << ' ' << a.y << ' ' << a.z << ") - (" << b.x
           << ' ' << b.y << ' ' << b.z << ")";
    }
    if (checkClosed)
    {
        os << "\nClose the surface (in the CAD tool), raise mergeDistance"
           << " (now " << mergeDistance << " m) if the gaps are tiny, or set"
           << " checkClosed no to fill it anyway";
        fatalIOError(source_, 0, os.str(), "checkClosed");
    }
    os << "\nFilled anyway (checkClosed no): each point is decided by a vote"
       << " of three rays; the volume is unknown";
    warning(os.str(), source_);
}


// * * * * * * * * * * * * * * * Member Functions * * * * * * * * * * * * * //

bool stlShape::inside(const vec3& p, scalar) const
{
    return inside_.inside(p);
}

} // End namespace sphvcpm
