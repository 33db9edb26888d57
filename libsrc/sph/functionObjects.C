/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "functionObjects.H"
#include "dictionaryParser.H"
#include "error.H"
#include "formatting.H"
#include "fluidInteractions.H"
#include "motionSet.H"
#include "parallel.H"
#include "withKernel.H"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <ostream>
#include <sstream>

namespace sphvcpm
{
namespace functionObjects
{

// OpenFOAM cases carry libs and enabled in every entry; libs is ignored,
// enabled false skips the entry (readAll).
const std::vector<std::string> commonKeywords
{
    "type", "writeControl", "writeInterval", "enabled", "libs"
};


namespace
{

std::vector<std::string> keywords(std::vector<std::string> own)
{
    own.insert(own.begin(), commonKeywords.begin(), commonKeywords.end());
    return own;
}

// Points of a 2D case must lie in its plane (z = 0): off it they would
// silently see no particle.
std::vector<vec3> readPoints(const dictionary& dict, const std::string& key,
                             const std::string& name, const sphModel& model)
{
    const auto points = dict.get<std::vector<vec3>>(key);
    if (points.empty())
    {
        dict.fatalAt(key, "Function object '" + name + "': " + key
            + " is empty");
    }
    if (model.nDimensions != 3)
    {
        for (const vec3& x : points)
        {
            if (x.z != 0)
            {
                dict.fatalAt(key, "Function object '" + name + "': the case"
                    " is 2D (z = 0) but " + key + " has the point "
                    + str(x, 10));
            }
        }
    }
    return points;
}

// Whether x is within distance r of the grid box: farther out no particle
// can be within r (particles outside the grid are never in a cell), and
// forEachCandidate must not convert huge or NaN cell indices to int.
bool nearGrid(const cellGrid& g, const point& x, const scalar r)
{
    const int n[3] = {g.nx, g.ny, g.nz};
    for (int d = 0; d < 3; ++d)
    {
        const double lo = g.origin[d] - r;
        const double hi = g.origin[d] + n[d]*g.cellSize + r;
        if (!(x[d] >= lo && x[d] <= hi))
        {
            return false;
        }
    }
    return true;
}

// A probe beyond the support of the domain, or a gauge whose line up from
// its base misses it (most often a typo), reads 0: said once per point
// (warned, by point), when first found. time: NaN for points that stand
// still, else the sample's (a moving frame's point may leave the domain
// later). up: none for probes.
void warnOutsideDomain(const std::string& name, const std::string& what,
                       const std::vector<vec3>& points, const cellGrid& g,
                       const scalar support, std::vector<char>& warned,
                       const double time, const vec3& up = vec3{0, 0, 0})
{
    warned.resize(points.size(), 0);
    const vec3 lo = toVec3(g.origin);
    const vec3 hi = lo + g.cellSize*vec3{scalar(g.nx), scalar(g.ny),
                                         scalar(g.nz)};
    for (std::size_t k = 0; k < points.size(); ++k)
    {
        // The ray points[k] + t up, t >= 0 (a point alone for probes),
        // against the box grown by the support, axis by axis.
        double tMin = 0, tMax = mag(up) > 0 ? 1e300 : 0;
        for (int d = 0; d < 3; ++d)
        {
            const double a = lo[d] - support, b = hi[d] + support;
            const double x = points[k][d], u = up[d];
            if (u == 0)
            {
                if (x < a || x > b) tMax = -1;
                continue;
            }
            const double t1 = (a - x)/u, t2 = (b - x)/u;
            tMin = std::max(tMin, std::min(t1, t2));
            tMax = std::min(tMax, std::max(t1, t2));
        }
        const bool meets = tMin <= tMax;
        if (!meets && !warned[k])
        {
            warned[k] = 1;
            warning("Function object '" + name + "': " + what + " "
                + std::to_string(k) + " at " + str(points[k], 10)
                + (mag(up) > 0 ? ": its line up" : "") + " is outside the"
                " domain " + str(lo) + " to " + str(hi) + ", where there"
                " is no fluid: it reads 0" + (std::isnan(time) ? std::string()
                  : " (at time " + str(time) + ", moved by its frame)"));
        }
    }
}

// Calls f(j, r) for every particle j within the support of x that
// fluid(j) == ofFluid (the fluid, or the walls and solids), r the
// distance.
template<class Kernel, class F>
void forEachNear(const solverSnapshot& s, const Kernel& kernel,
                 const point& x, const bool ofFluid, const F& f)
{
    const scalar support = kernel.support();
    const scalar support2 = support*support;
    const cellGrid& g = s.cells.grid;
    if (!nearGrid(g, x, support) || s.cells.cellStart.empty())
    {
        return;
    }
    const particleFields& pf = s.particles;
    forEachCandidate(g, s.cells.cellStart.data(), x, [&](const label j)
    {
        if ((pf.kind[j] == fluidKind) != ofFluid) return;
        const scalar r2 = magSqr(toVec3(x - pf.position[j]));
        if (r2 >= support2) return;
        f(j, std::sqrt(r2));
    });
}

// ... for every fluid particle.
template<class Kernel, class F>
void forEachFluidNear(const solverSnapshot& s, const Kernel& kernel,
                      const point& x, const F& f)
{
    forEachNear(s, kernel, x, true, f);
}

// Fluid volume fraction sum_f V_f W(|x - x_f|): about 1 inside the fluid,
// 0.5 at a flat free surface, 0 in air.
template<class Kernel>
scalar concentration(const solverSnapshot& s, const Kernel& kernel,
                     const point& x)
{
    const particleFields& pf = s.particles;
    scalar c = 0;
    forEachFluidNear(s, kernel, x, [&](const label j, const scalar r)
    {
        c += pf.mass[j]/pf.rho[j]*kernel.W(r);
    });
    return c;
}

// The pressure part of the fluid particle j's push on the boundary
// particle w at distance r, as the pair terms see it (fluidPairTerms):
// a_j -= m_w (p_j + p_w)/(rho_j rho_w) G x_jw, times m_j.
template<class Kernel>
vec3 pressurePushOn(const particleFields& pf, const Kernel& kernel,
                    const label w, const label j, const scalar r)
{
    const vec3 d = toVec3(pf.position[j] - pf.position[w]);   // x_jw
    return (pf.mass[j]*pf.mass[w]*(pressureTowardBoundary(pf.p[j]) + pf.p[w])
           /(pf.rho[j]*pf.rho[w])*kernel.gradFactor(r))*d;
}

// The longest stretch of the line b + t up, 0 <= t <= tMax (sampled every
// ds), that lies inside one wall or solid body: where the body's own
// volume fraction sum_j dp_j^d W reaches 0.5, its face. body -1: none.
struct bodyStretch
{
    label body = -1;
    scalar from = 0, to = 0;
    scalar length() const { return to - from; }
};

template<class Kernel>
bodyStretch longestStretchInBody(const solverSnapshot& s,
                                 const Kernel& kernel, const vec3& b,
                                 const vec3& up, const scalar tMax,
                                 const scalar ds)
{
    const particleFields& pf = s.particles;
    const int d = s.model.nDimensions;
    bodyStretch longest, current;
    const label n = label(std::ceil(tMax/ds));
    for (label i = 0; i <= n; ++i)
    {
        const scalar t = std::min(i*ds, tMax);
        scalar c = 0, nearest = std::numeric_limits<scalar>::max();
        label body = -1;
        forEachNear(s, kernel, toPoint(b + t*up), false,
            [&](const label j, const scalar r)
        {
            c += std::pow(s.bodies[pf.body[j]].dp, d)*kernel.W(r);
            if (r < nearest)
            {
                nearest = r;
                body = pf.body[j];
            }
        });
        if (c < 0.5)
        {
            current.body = -1;
            continue;
        }
        if (body == current.body)
        {
            current.to = t;
        }
        else
        {
            current = {body, t, t};
        }
        if (current.length() > longest.length() || longest.body < 0)
        {
            longest = current;
        }
    }
    return longest;
}

// Distance from b along the unit vector u to where the ray leaves the
// cell grid (0 when it starts outside going out).
scalar extentAlong(const cellGrid& g, const vec3& b, const vec3& u)
{
    const int n[3] = {g.nx, g.ny, g.nz};
    scalar t = std::numeric_limits<scalar>::max();
    for (int d = 0; d < 3; ++d)
    {
        if (u[d] > 0)
        {
            t = std::min(t, scalar((g.origin[d] + n[d]*g.cellSize - b[d])/u[d]));
        }
        else if (u[d] < 0)
        {
            t = std::min(t, scalar((g.origin[d] - b[d])/u[d]));
        }
    }
    return t > 0 ? t : 0;
}

// The case's constant/motion (none without it), in its plane for a 2D case.
motionSet caseMotions(const std::filesystem::path& caseDir,
                      const int nDimensions)
{
    motionSet motions = motionSet::readIfPresent(caseDir, nDimensions);
    if (nDimensions == 2) motions.restrictToPlane();
    return motions;
}

// Sums over all particles accumulate in double in every build (a float
// sum of a million terms keeps only a few digits).
using sumVec = Vec3<double>;

sumVec toSum(const vec3& a)
{
    return {double(a.x), double(a.y), double(a.z)};
}

struct vecSum
{
    sumVec operator()(const sumVec& a, const sumVec& b) const
    {
        return a + b;
    }
};

// The inverse of a 3x3 matrix by its cofactors; false (inverse left 0)
// when it is singular against the size of its entries.
bool invert3(const double a[3][3], double inverse[3][3])
{
    const double c00 = a[1][1]*a[2][2] - a[1][2]*a[2][1];
    const double c01 = a[1][2]*a[2][0] - a[1][0]*a[2][2];
    const double c02 = a[1][0]*a[2][1] - a[1][1]*a[2][0];
    const double det = a[0][0]*c00 + a[0][1]*c01 + a[0][2]*c02;
    double scale = 0;
    for (int i = 0; i < 3; ++i) scale = std::max(scale, std::fabs(a[i][i]));
    for (int i = 0; i < 3; ++i)
    {
        for (int j = 0; j < 3; ++j) inverse[i][j] = 0;
    }
    if (!(std::fabs(det) > 1e-9*scale*scale*scale)) return false;
    inverse[0][0] = c00/det;
    inverse[1][0] = c01/det;
    inverse[2][0] = c02/det;
    inverse[0][1] = (a[0][2]*a[2][1] - a[0][1]*a[2][2])/det;
    inverse[1][1] = (a[0][0]*a[2][2] - a[0][2]*a[2][0])/det;
    inverse[2][1] = (a[0][1]*a[2][0] - a[0][0]*a[2][1])/det;
    inverse[0][2] = (a[0][1]*a[1][2] - a[0][2]*a[1][1])/det;
    inverse[1][2] = (a[0][2]*a[1][0] - a[0][0]*a[1][2])/det;
    inverse[2][2] = (a[0][0]*a[1][1] - a[0][1]*a[1][0])/det;
    return true;
}

// m += a b^T.
void addOuter(double m[3][3], const point& a, const point& b)
{
    const double u[3] = {double(a.x), double(a.y), double(a.z)};
    const double v[3] = {double(b.x), double(b.y), double(b.z)};
    for (int i = 0; i < 3; ++i)
    {
        for (int j = 0; j < 3; ++j) m[i][j] += u[i]*v[j];
    }
}

// The solid of that name among the snapshot's; FatalError naming the
// function object when the run has none.
const solidView& solidNamed(const solverSnapshot& s, const std::string& name,
                            const std::string& objectName)
{
    for (std::size_t i = 0; s.solids && i < s.solids->size(); ++i)
    {
        if ((*s.solids)[i].name == name) return (*s.solids)[i];
    }
    fatalError("Function object '" + objectName + "': solid '" + name
        + "' is not in the run");
}

// solidNamed, for the function objects that follow its particles:
// FatalError when it has none.
const solidView& solidToFollow(const solverSnapshot& s,
                               const std::string& name,
                               const std::string& objectName)
{
    const solidView& view = solidNamed(s, name, objectName);
    if (view.reference->empty())
    {
        fatalError("Function object '" + objectName + "': solid '" + name
            + "' has no particles");
    }
    return view;
}

// The index of the reference position nearest P (the first of equals).
label nearestReference(const std::vector<point>& X, const vec3& P)
{
    label best = 0;
    for (label i = 1; i < label(X.size()); ++i)
    {
        if (magSqr(X[i] - P) < magSqr(X[best] - P)) best = i;
    }
    return best;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * table  * * * * * * * * * * * * * * * //

table::table(std::string name, const dictionary& dict,
             const std::filesystem::path& caseDir,
             const std::string& startTimeName, std::string file)
:
    functionObject(std::move(name), dict, caseDir, startTimeName),
    fileNames_{std::move(file)}
{}


void table::writeUnits(std::ostream& os, const std::string& text)
{
    os << "# Units: " << text << '\n';
}


void table::sample(const solverSnapshot& s)
{
    const std::vector<std::vector<scalar>> all = rows(s);
    for (std::size_t f = 0; f < fileNames_.size(); ++f)
    {
        std::ofstream& os = output(fileNames_[f]);
        errno = 0;
        // Where this row starts: a row the disk could not take in full is
        // cut off again, so no half row reads as a wrong number.
        const std::streamoff rowStart = os.tellp();
        if (!headerWritten_)
        {
            writeFileHeader(os, f);
        }
        os << s.time;
        for (const scalar v : all.at(f))
        {
            os << ' ' << v;
        }
        os << '\n';
        os.flush();
        if (!os)
        {
            // The stream keeps no reason; errno has the failed write's.
            const std::string reason =
                errno ? std::strerror(errno) : "the stream failed";
            std::error_code ec;
            os.close();   // what it still buffers goes now, not after the cut
            if (rowStart >= 0)
            {
                std::filesystem::resize_file(outputPath(fileNames_[f]),
                    std::uintmax_t(rowStart), ec);
            }
            fatalError("Function object '" + name() + "': cannot write "
                + outputPath(fileNames_[f]).string() + ": " + reason
                + (rowStart >= 0 && !ec ? " (the file ends with the last"
                   " whole row)" : ""));
        }
    }
    headerWritten_ = true;
}


// * * * * * * * * * * * * * * * * * pointFrame * * * * * * * * * * * * * * //

pointFrame::pointFrame(const dictionary& dict, const std::string& objectName,
                       const std::filesystem::path& caseDir,
                       const int nDimensions,
                       const std::vector<bodyInfo>& bodies)
{
    const std::string frame = dict.getOrDefault<std::string>("frame", "lab");
    if (frame == "lab") return;
    const motionSet motions = caseMotions(caseDir, nDimensions);
    std::vector<std::string> moving, names;
    const bodyInfo* body = nullptr;
    for (const bodyInfo& b : bodies)
    {
        names.push_back(b.name);
        if (b.name == frame) body = &b;
        if (b.type != bodyType::fluid && motions.namedMotionOf(b.name))
        {
            moving.push_back(b.name);
        }
    }
    const std::string head = "Function object '" + objectName + "': frame "
        + frame + ": ";
    const std::string choices = moving.empty()
      ? "no body moves in this case (" + std::string(motions.empty()
            ? "it has no constant/motion" : "constant/motion moves none of"
              " its wall or solid bodies") + "), so leave frame out: the"
            " points stand still in the lab"
      : "give lab (the points stand still, the default) or a body that"
        " constant/motion moves: " + str(moving);
    std::string why;
    if (!body)
    {
        const namedMotion* asMotion = nullptr;
        for (const namedMotion& m : motions.motions())
        {
            if (m.name == frame) asMotion = &m;
        }
        const std::string guess = dictionaryDetail::closest(frame, names);
        why = asMotion
            ? frame + " is a motion of constant/motion; frame names a body it"
              " moves, " + str(asMotion->bodies)
            : frame == "clamp"
            ? "clamp is a frame of solidPoints (a solid's clamp); probes and"
              " gauges name the body whose motion they follow"
            : "there is no body " + frame + (guess.empty() ? std::string()
              : " (did you mean " + guess + "?)");
    }
    else if (body->type == bodyType::fluid)
    {
        why = frame + " is the fluid, which constant/motion cannot move";
    }
    else if (const namedMotion* m = motions.namedMotionOf(frame))
    {
        motion_ = m->motion;
        motionName_ = m->name;
        body_ = frame;
        return;
    }
    else
    {
        why = "body " + frame + " is in no motion of constant/motion, so"
            " its points would stand still";
    }
    dict.fatalAt("frame", head + why + "; " + choices);
}


rigidTransform pointFrame::at(const double t) const
{
    return motion_ ? motion_->transform(t) : rigidTransform::identity();
}


std::string pointFrame::headerLine() const
{
    if (!motion_) return "";
    return "# The points move with body " + body_ + " (motion " + motionName_
        + "), from the positions given here at its reference position\n";
}


// * * * * * * * * * * * * * * * * * * probes * * * * * * * * * * * * * * * //

const std::vector<std::string> probes::fieldNames{"p", "U", "rho"};


const dictionary& probes::withoutFrameOnSolid(const dictionary& dict,
                                              const std::string& name)
{
    if (dict.found("onSolid") && dict.found("frame"))
    {
        dict.fatalAt("onSolid", "Function object '" + name + "': onSolid"
            " carries the points with the solid, its clamp's motion"
            " included; leave frame out");
    }
    return dict;
}


probes::probes(std::string name, const dictionary& dict,
               const std::filesystem::path& caseDir,
               const std::string& startTimeName, const sphModel& model,
               const std::vector<bodyInfo>& bodies)
:
    table(std::move(name), dict, caseDir, startTimeName, "p.dat"),
    fields_{"p"},
    nDimensions_(model.nDimensions),
    frame_(withoutFrameOnSolid(dict, this->name()), this->name(), caseDir,
           model.nDimensions, bodies)
{
    dict.checkKeywords(keywords({"fields", "probeLocations", "wetFraction",
                                 "frame", "onSolid"}));
    if (dict.found("onSolid"))
    {
        solid_ = dict.get<std::string>("onSolid");
        std::vector<std::string> solids;
        const bodyInfo* body = nullptr;
        for (const bodyInfo& b : bodies)
        {
            if (b.type == bodyType::solid) solids.push_back(b.name);
            if (b.name == solid_) body = &b;
        }
        if (!body || body->type != bodyType::solid)
        {
            const std::string guess = dictionaryDetail::closest(solid_,
                                                                solids);
            dict.fatalAt("onSolid", "Function object '" + this->name()
                + "': " + (body ? "'" + solid_ + "' is a "
                    + bodyTypeName(body->type) + " body, not a solid"
                    + (body->type == bodyType::wall ? " (points that move"
                       " with a wall that constant/motion moves take frame "
                       + solid_ + ")" : std::string())
                  : "there is no body '" + solid_ + "'"
                    + (guess.empty() ? "" : " (did you mean " + guess
                       + "?)")) + ". Solid bodies: " + str(solids));
        }
        solidDp_ = body->dp;
    }
    if (dict.found("wetFraction"))
    {
        wetFraction_ = dict.get<scalar>("wetFraction");
        if (!(wetFraction_ >= 0 && wetFraction_ <= 1))
        {
            dict.fatalAt("wetFraction", "Function object '" + this->name()
                + "': wetFraction is the part of the kernel's support (less"
                " the walls') the fluid must fill for a probe to read it,"
                " between 0 and 1; found " + str(wetFraction_));
        }
    }
    if (dict.found("fields"))
    {
        fields_ = dict.get<std::vector<std::string>>("fields");
        if (fields_.empty())
        {
            dict.fatalAt("fields", "Function object '" + this->name()
                + "': fields is empty; probes samples " + str(fieldNames));
        }
        std::vector<std::string> files;
        for (const auto& f : fields_)
        {
            if (std::find(fieldNames.begin(), fieldNames.end(), f)
                == fieldNames.end())
            {
                dict.fatalAt("fields", "Function object '" + this->name()
                    + "': probes cannot sample field '" + f + "'; the fields"
                    " it samples are " + str(fieldNames));
            }
            if (std::count(fields_.begin(), fields_.end(), f) > 1)
            {
                dict.fatalAt("fields", "Function object '" + this->name()
                    + "': field '" + f + "' is listed twice");
            }
            files.push_back(f + ".dat");
        }
        setFiles(files);
    }
    locations_ = readPoints(dict, "probeLocations", this->name(), model);
}


std::vector<scalar> probes::values(const solverSnapshot& s) const
{
    return rows(s).front();
}


namespace
{

// The outward normal of a solid, in its reference lattice, at its
// particle p for the point P: out from the mean of p and its neighbours
// to p, which is square to a flat face; at an edge or corner the lattice
// axis of that direction along which P lies farthest out (a sensor on a
// plate's face, or on its top, beside a corner particle), or the diagonal
// where P lies along none. A single row of particles (a sheet in 3D) has
// no inside: from p out to P, square to the row. Amid the solid: 0.
vec3 referenceNormal(const std::vector<point>& X,
                     const std::vector<label>& neighbours, const label p,
                     const vec3& P, const bool planar)
{
    const vec3 Xp = toVec3(X[p]);
    vec3 mean = Xp;
    for (const label j : neighbours) mean += toVec3(X[j]);
    const vec3 out = Xp - mean/scalar(neighbours.size() + 1);
    const vec3 V = P - Xp;
    // Neighbour spacings are dp or more; a tenth of the smallest.
    scalar small = std::numeric_limits<scalar>::max();
    for (const label j : neighbours) small = std::min(small, mag(X[j] - X[p]));
    small = neighbours.empty() ? 0 : scalar(0.1)*small;
    if (mag(out) <= small)
    {
        std::vector<vec3> along;    // orthonormal, spanning the row
        for (const label j : neighbours)
        {
            vec3 o = toVec3(X[j]) - Xp;
            for (const vec3& e : along) o = o - dot(o, e)*e;
            if (mag(o) > small) along.push_back(o/mag(o));
        }
        vec3 n = V;
        for (const vec3& e : along) n = n - dot(n, e)*e;
        if (planar) n.z = 0;
        return mag(n) > small ? n/mag(n) : vec3{0, 0, 0};
    }
    int axis = -1;
    scalar farthest = 0;
    for (int i = 0; i < (planar ? 2 : 3); ++i)
    {
        if (std::fabs(out[i]) <= small) continue;
        const scalar reach = out[i] > 0 ? V[i] : -V[i];
        if (reach > farthest)
        {
            farthest = reach;
            axis = i;
        }
    }
    if (axis < 0) return out/mag(out);
    vec3 n{0, 0, 0};
    n[axis] = out[axis] > 0 ? 1 : -1;
    return n;
}

} // End anonymous namespace


std::vector<vec3> probes::pointsAt(const solverSnapshot& s) const
{
    std::vector<vec3> here;
    if (solid_.empty())
    {
        const rigidTransform T = frame_.at(s.time);
        for (const vec3& x : locations_)
        {
            here.push_back(toVec3(T.apply(toPoint(x))));
        }
        return here;
    }
    const solidView& view = solidToFollow(s, solid_, name());
    const std::vector<point>& X = *view.reference;
    const std::vector<point>& x = *view.position;
    const bool planar = s.model.nDimensions == 2;
    if (attached_.empty())
    {
        // Each point rides on its nearest particle, offset as in the
        // reference configuration and turned and stretched by the local
        // map F of the particles within 1.5 dp (a lattice's nearest and
        // diagonal ones): least squares of x_j - x_p = F (X_j - X_p).
        for (const vec3& P : locations_)
        {
            attachment a{nearestReference(X, P), {}, {}, 0, {0, 0, 0}, {0, 0, 0}};
            const point Xp = X[a.particle];
            a.reference = toVec3(Xp);
            const scalar d = mag(toVec3(Xp) - P);
            if (d > 2*solidDp_)
            {
                warning("Function object '" + name() + "': the point "
                    + str(P, 10) + " is " + str(d) + " m from solid '"
                    + solid_ + "' (its nearest particle, at "
                    + str(toVec3(Xp), 10) + ", carries it): check the"
                    " points");
            }
            double A[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
            const scalar r2 = 2.25*solidDp_*solidDp_;
            for (label j = 0; j < label(X.size()); ++j)
            {
                if (j == a.particle || magSqr(X[j] - Xp) > r2) continue;
                a.neighbours.push_back(j);
                addOuter(A, X[j] - Xp, X[j] - Xp);
            }
            a.normal = referenceNormal(X, a.neighbours, a.particle, P,
                                       planar);
            // In the plane z maps to itself: an entry of A's size there.
            if (planar) A[2][2] = 0.5*(A[0][0] + A[1][1]);
            a.zz = A[2][2];
            if (!invert3(A, a.inverseA))
            {
                warning("Function object '" + name() + "': the particles of"
                    " solid '" + solid_ + "' round the point " + str(P, 10)
                    + " do not span the " + (planar ? "plane" : "space")
                    + ": it moves with its particle's displacement alone,"
                    " not turning with the solid");
            }
            attached_.push_back(std::move(a));
        }
    }
    faces_.assign(locations_.size(), {vec3{0, 0, 0}, vec3{0, 0, 0}});
    for (std::size_t k = 0; k < locations_.size(); ++k)
    {
        const attachment& a = attached_[k];
        const point xp = x[a.particle];
        const point Xp = X[a.particle];
        const point offset = toPoint(locations_[k]) - Xp;
        bool translate = true;
        for (int i = 0; i < 3; ++i) translate &= a.inverseA[i][i] == 0;
        const bool hasSide = magSqr(a.normal) > 0;
        if (translate)
        {
            here.push_back(toVec3(xp + offset));
            if (hasSide) faces_[k] = {toVec3(xp), a.normal};
            continue;
        }
        double B[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, planar ? a.zz : 0}};
        for (const label j : a.neighbours)
        {
            addOuter(B, x[j] - xp, X[j] - Xp);
        }
        // F = B A^-1: x = x_p + F (P - X_p), and a normal turns and
        // stretches by F^-T.
        double F[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
        for (int i = 0; i < 3; ++i)
        {
            for (int j = 0; j < 3; ++j)
            {
                for (int m = 0; m < 3; ++m) F[i][j] += B[i][m]*a.inverseA[m][j];
            }
        }
        const double o[3] = {double(offset.x), double(offset.y),
                             double(offset.z)};
        double moved[3] = {0, 0, 0};
        for (int i = 0; i < 3; ++i)
        {
            for (int j = 0; j < 3; ++j) moved[i] += F[i][j]*o[j];
        }
        here.push_back(toVec3(xp) + vec3{scalar(moved[0]), scalar(moved[1]),
                                         scalar(planar ? 0 : moved[2])});
        if (!hasSide) continue;
        vec3 n = a.normal;
        double Finv[3][3];
        if (invert3(F, Finv))
        {
            for (int i = 0; i < 3; ++i)
            {
                n[i] = scalar(Finv[0][i]*a.normal[0] + Finv[1][i]*a.normal[1]
                            + Finv[2][i]*a.normal[2]);
            }
            if (planar) n.z = 0;
        }
        if (mag(n) > 0) faces_[k] = {toVec3(xp), n/mag(n)};
    }
    return here;
}


std::vector<std::vector<scalar>> probes::rows(const solverSnapshot& s) const
{
    const std::vector<vec3> here = pointsAt(s);
    warnOutsideDomain(name(), "probe", here, s.cells.grid, 2*s.model.h,
        warned_, frame_.moving() || !solid_.empty() ? s.time
                                                    : std::nan(""));
    // Shepard means over the fluid within a support: sum f W V / sum W V.
    const std::size_t n = locations_.size();
    std::vector<scalar> p(n, 0), rho(n, 0);
    std::vector<vec3> U(n, vec3{0, 0, 0});
    const particleFields& pf = s.particles;
    withKernel(s.model, [&](auto kernel)
    {
        for (std::size_t k = 0; k < n; ++k)
        {
            const point x = toPoint(here[k]);
            scalar sumW = 0, sumP = 0, sumRho = 0;
            vec3 sumU{0, 0, 0};
            // On a solid, the fluid on the point's side of it only: a thin
            // plate's far side is within the support of its near face.
            const vec3 base = solid_.empty() ? vec3{0, 0, 0} : faces_[k].first;
            const vec3 normal = solid_.empty() ? vec3{0, 0, 0}
                                               : faces_[k].second;
            const bool oneSide = magSqr(normal) > 0;
            forEachFluidNear(s, kernel, x, [&](const label j, const scalar r)
            {
                if (oneSide
                 && dot(toVec3(pf.position[j]) - base, normal) < 0) return;
                const scalar WV = kernel.W(r)*pf.mass[j]/pf.rho[j];
                sumW += WV;
                sumP += pf.p[j]*WV;
                sumRho += pf.rho[j]*WV;
                sumU += WV*pf.velocity[j];
            });
            // Wet when the fluid fills wetFraction of the support that the
            // walls leave: 0.5 is the free surface as the gauges find it,
            // also on a wall's face (walls fill the other half). 0, the
            // default, is any fluid in reach: a wall's pressure sensor
            // feels a jet thinner than the support (Lobovsky's sensor 1
            // read the arrival 5 % later with 0.5).
            // On a solid, the support on the point's side of the solid's
            // face (half a spacing out from the plane through its
            // particle) and the walls there.
            const scalar face = 0.5*solidDp_;
            scalar room = 0;
            if (wetFraction_ > 0)
            {
                room = oneSide
                     ? kernelShareInFrontOfPlane(kernel, nDimensions_,
                           dot(here[k] - base, normal) - face)
                     : 1;
                // A wall particle's volume dp^d (its mass is rho0 dp^d; its
                // rho follows the extrapolated pressure).
                forEachNear(s, kernel, x, false,
                    [&](const label j, const scalar r)
                    {
                        if (oneSide
                         && dot(toVec3(pf.position[j]) - base, normal) < face)
                        {
                            return;
                        }
                        room -= kernel.W(r)*pf.mass[j]/s.model.rho0;
                    });
            }
            if (sumW > 0
             && sumW >= wetFraction_*std::max(scalar(0), room))
            {
                p[k] = sumP/sumW;
                rho[k] = sumRho/sumW;
                U[k] = sumU/sumW;
            }
        }
    });
    std::vector<std::vector<scalar>> all;
    for (const std::string& f : fields_)
    {
        if (f == "U")
        {
            std::vector<scalar> row;
            for (const vec3& u : U)
            {
                row.push_back(u.x);
                row.push_back(u.y);
                if (nDimensions_ == 3) row.push_back(u.z);
            }
            all.push_back(row);
        }
        else
        {
            all.push_back(f == "p" ? p : rho);
        }
    }
    return all;
}


void probes::writeHeader(std::ostream& os) const
{
    writeFileHeader(os, 0);
}


void probes::writeFileHeader(std::ostream& os, const std::size_t file) const
{
    os << frame_.headerLine();
    if (!solid_.empty())
    {
        os << "# The points ride on solid " << solid_ << ", each on its"
              " particle nearest it at the reference position given here,"
              " turned and stretched with the particles round that one\n";
    }
    for (std::size_t k = 0; k < locations_.size(); ++k)
    {
        os << "# Probe " << k << ' ' << str(locations_[k], 10);
        if (k < attached_.size())
        {
            os << " on the particle at " << str(attached_[k].reference, 10);
        }
        os << '\n';
    }
    const std::string& field = fields_.at(file);
    writeUnits(os, "Time [s], " + field + (field == "p" ? " [Pa]"
        : field == "U" ? " [m/s]" : " [kg/m^3]"));
    os << "# Time";
    for (std::size_t k = 0; k < locations_.size(); ++k)
    {
        if (field == "U")
        {
            for (const char c : std::string(nDimensions_ == 3 ? "xyz" : "xy"))
            {
                os << " U" << k << c;
            }
        }
        else
        {
            os << ' ' << field << k;
        }
    }
    os << '\n';
}


// * * * * * * * * * * * * * * * freeSurfaceGauges  * * * * * * * * * * * * //

freeSurfaceGauges::freeSurfaceGauges(std::string name,
    const dictionary& dict, const std::filesystem::path& caseDir,
    const std::string& startTimeName, const sphModel& model,
    const std::vector<bodyInfo>& bodies)
:
    table(std::move(name), dict, caseDir, startTimeName, "height.dat"),
    frame_(dict, this->name(), caseDir, model.nDimensions, bodies),
    maxHeight_(0)
{
    dict.checkKeywords(keywords({"locations", "maxHeight", "frame"}));
    locations_ = readPoints(dict, "locations", this->name(), model);
    if (dict.found("maxHeight"))
    {
        maxHeight_ = dict.getPositive("maxHeight");
    }
    const scalar magG = mag(model.g);
    if (!(magG > 0))
    {
        dict.fatalAt("type", "Function object '" + this->name()
            + "': freeSurfaceGauges measure against gravity, but g is zero"
              " (constant/g)");
    }
    up_ = (-1/magG)*model.g;
}


std::vector<scalar> freeSurfaceGauges::values(const solverSnapshot& s) const
{
    // In a moving frame the base points move and the line up turns with
    // the body (a gauge fixed to a rolling tank measures along its wall).
    const rigidTransform T = frame_.at(s.time);
    const vec3 up = toVec3(T.rotate(toPoint(up_)));
    std::vector<vec3> bases;
    for (const vec3& b : locations_)
    {
        bases.push_back(toVec3(T.apply(toPoint(b))));
    }
    warnOutsideDomain(name(), "gauge", bases, s.cells.grid, 0, warned_,
        frame_.moving() ? s.time : std::nan(""), up);
    std::vector<scalar> heights(locations_.size(), 0);
    warnedInBody_.resize(locations_.size(), 0);
    withKernel(s.model, [&](auto kernel)
    {
        const scalar ds = 0.25*s.model.dp;
        for (std::size_t k = 0; k < locations_.size(); ++k)
        {
            const vec3& b = bases[k];
            const scalar sMax = maxHeight_ > 0
              ? maxHeight_ : extentAlong(s.cells.grid, b, up);
            const label n = label(std::ceil(sMax/ds));
            const auto at = [&](label i)
            {
                return std::min(i*ds, sMax);
            };
            // From the top down: the first c >= 0.5 met is the last
            // crossing from inside to outside, and the scan stops there.
            scalar cAbove = 0;
            for (label i = n; i >= 0; --i)
            {
                const scalar c =
                    concentration(s, kernel, toPoint(b + at(i)*up));
                if (c >= 0.5)
                {
                    heights[k] = i == n
                      ? sMax
                      : at(i) + (at(i + 1) - at(i))*(c - 0.5)/(c - cAbove);
                    break;
                }
                cAbove = c;
            }
            if (heights[k] == 0 && !warnedInBody_[k])
            {
                warnIfInsideBody(s, kernel, k, b, up, sMax, ds);
            }
        }
    });
    return heights;
}


template<class Kernel>
void freeSurfaceGauges::warnIfInsideBody(const solverSnapshot& s,
                                         const Kernel& kernel,
                                         const std::size_t k, const vec3& b,
                                         const vec3& up, const scalar sMax,
                                         const scalar ds) const
{
    // A dry gauge whose line runs a spacing or more inside a wall or a
    // solid (a gauge put inside a gate): the fluid cannot be there, and
    // the 0 it reads looks like a dry bed. Said once per gauge.
    const bodyStretch in = longestStretchInBody(s, kernel, b, up, sMax, ds);
    if (in.body < 0 || in.length() < s.bodies[in.body].dp) return;
    warnedInBody_[k] = 1;
    const bodyInfo& body = s.bodies[in.body];
    warning("Function object '" + name() + "': gauge " + std::to_string(k)
        + " at " + str(b, 10) + " reads no water, and its line up runs"
          " inside " + bodyTypeName(body.type) + " body '" + body.name
        + "' from " + str(in.from) + " to " + str(in.to) + " m above its"
          " base, where the fluid cannot be: it reads 0 until water stands"
          " above that (at time " + str(s.time) + "). Move the gauge out of"
          " the body to measure the water beside it");
}


void freeSurfaceGauges::writeHeader(std::ostream& os) const
{
    os << frame_.headerLine();
    for (std::size_t k = 0; k < locations_.size(); ++k)
    {
        os << "# Gauge " << k << ' ' << str(locations_[k], 10) << '\n';
    }
    writeUnits(os, "Time [s], h [m]");
    os << "# Time";
    for (std::size_t k = 0; k < locations_.size(); ++k)
    {
        os << " h" << k;
    }
    os << '\n';
}


// * * * * * * * * * * * * * * * * * * forces * * * * * * * * * * * * * * * //

forces::forces(std::string name, const dictionary& dict,
               const std::filesystem::path& caseDir,
               const std::string& startTimeName,
               const std::vector<bodyInfo>& bodies, const int nDimensions)
:
    table(std::move(name), dict, caseDir, startTimeName, "force.dat"),
    body_(-1),
    frame_(dict, this->name(), caseDir, nDimensions, bodies),
    dp_(0),
    nDimensions_(nDimensions)
{
    dict.checkKeywords(keywords({"body", "CofR", "frame", "shapes"}));
    if (dict.found("frame") && !dict.found("CofR"))
    {
        dict.fatalAt("frame", "Function object '" + this->name() + "': frame"
            " moves the point CofR that the moment is taken about, and there"
            " is no CofR (the force itself, in the lab's axes, is the same"
            " in every frame): give CofR or leave frame out");
    }
    const std::string body = dict.get<std::string>("body");
    if (dict.found("CofR"))
    {
        // As OpenFOAM's forces: the moment about this point too.
        CofR_ = dict.get<vec3>("CofR");
        if (nDimensions == 2 && CofR_.z != 0)
        {
            dict.fatalAt("CofR", "Function object '" + this->name()
                + "': CofR of a 2D case must have z = 0 (the moment is"
                " about the z axis through it), found " + str(CofR_));
        }
        moment_ = true;
        setFiles({"force.dat", "moment.dat"});
    }
    std::vector<std::string> walls;
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
        if (bodies[i].type != bodyType::fluid)
        {
            walls.push_back(bodies[i].name);
            if (bodies[i].name == body)
            {
                body_ = label(i);
            }
        }
    }
    if (body_ < 0)
    {
        const std::string list = str(walls);
        std::string what = "there is no body '" + body + "'";
        for (const auto& b : bodies)
        {
            if (b.name == body)
            {
                what = "'" + body + "' is a " + bodyTypeName(b.type)
                     + " body, not a wall or a solid";
            }
        }
        dict.fatalAt("body", "Function object '" + this->name() + "': "
            + what + ". Wall and solid bodies: " + list);
    }
    dp_ = bodies[body_].dp;
    bodyName_ = body;
    if (dict.found("shapes"))
    {
        // Part of the body: its particles inside these shapes as it stands
        // in the reference configuration, so that the same particles are
        // summed however the body moves or bends (the upper half of a gate,
        // one wall of a rolling tank).
        if (!dict.isDict("shapes"))
        {
            dict.fatalAt("shapes", "Function object '" + this->name()
                + "': shapes is a dictionary of shapes, as a body's shapes"
                " in generateParticlesDict: shapes { top { shape box; min"
                " (...); max (...); } }");
        }
        part_.emplace(nDimensions);
        part_->addShapes(dict.subDict("shapes"), dp_, caseDir);
        const motionSet motions = caseMotions(caseDir, nDimensions);
        if (bodies[body_].type == bodyType::wall)
        {
            if (const namedMotion* m = motions.namedMotionOf(body))
            {
                bodyMotion_ = m->motion;
            }
        }
    }
}


std::vector<scalar> forces::values(const solverSnapshot& s) const
{
    return rows(s).front();
}


std::vector<std::vector<scalar>> forces::rows(const solverSnapshot& s) const
{
    const particleFields& pf = s.particles;
    const sphModel& m = s.model;
    const std::uint8_t body = std::uint8_t(body_);
    const bool laminar = m.viscosity == viscosityType::laminar;
    const scalar fourNu = 4*m.nu;
    const scalar eta2 = m.eta2();
    const boundaryContact contact = boundaryContactOf(m);
    // The force and its moment about CofR, each wall particle's force
    // acting at its centre.
    struct forceMoment { sumVec F, M; };
    forceMoment sum{{0, 0, 0}, {0, 0, 0}};
    const vec3 CofR = toVec3(frame_.at(s.time).apply(toPoint(CofR_)));
    const std::vector<char> inPart = partMask(s);

    withKernel(m, [&](auto kernel)
    {
        // Minus the rate of momentum the wall gives the fluid, pair by
        // pair: the pressure term, the contact push and the laminar
        // viscous term of the fluid's momentum equation (fluidRatesOp).
        // The artificial viscosity is left out: it is a numerical
        // stabiliser, small in a resolved flow, not a physical stress.
        const auto onWall = [&](const label w)
        {
            vec3 f{0, 0, 0};
            if (pf.kind[w] == fluidKind || pf.body[w] != body) return f;
            if (part_ && !inPart[w]) return f;
            const point xw = pf.position[w];
            const vec3 vw = pf.velocity[w];
            const scalar mw = pf.mass[w];
            const scalar rhow = pf.rho[w];
            forEachFluidNear(s, kernel, xw, [&](const label j, const scalar r)
            {
                if (r <= 0) return;
                const vec3 d = toVec3(pf.position[j] - xw);  // x_fw
                const scalar G = kernel.gradFactor(r);
                const scalar mf = pf.mass[j];
                const scalar rhof = pf.rho[j];
                f += pressurePushOn(pf, kernel, w, j, r);
                // a_f += m_w C x_fw, the contact push
                f -= (mf*mw*contact(r*r, mw))*d;
                if (laminar)
                {
                    const scalar r2 = r*r;
                    // a_f += m_w 4 nu G r^2/((rho_f + rho_w)(r^2 + eta^2))
                    //        v_fw
                    f -= (mf*mw*fourNu*G*r2/((rhof + rhow)*(r2 + eta2)))
                        *(pf.velocity[j] - vw);
                }
            });
            return f;
        };
        sum = parallelReduce(openmpExec{}, pf.size(),
            [&](const label w)
            {
                const sumVec f = toSum(onWall(w));
                if (!moment_) return forceMoment{f, {0, 0, 0}};
                const sumVec arm = toSum(toVec3(pf.position[w]) - CofR);
                return forceMoment{f, cross(arm, f)};
            },
            forceMoment{{0, 0, 0}, {0, 0, 0}},
            [](const forceMoment& a, const forceMoment& b)
            {
                return forceMoment{a.F + b.F, a.M + b.M};
            });
        if (part_ && !cutChecked_) warnIfCutThrough(s, kernel, inPart);
    });
    const sumVec& F = sum.F;
    const sumVec& M = sum.M;
    if (!moment_)
    {
        return {{scalar(F.x), scalar(F.y), scalar(F.z)}};
    }
    return {{scalar(F.x), scalar(F.y), scalar(F.z)},
            {scalar(M.x), scalar(M.y), scalar(M.z)}};
}


template<class Kernel>
void forces::warnIfCutThrough(const solverSnapshot& s, const Kernel& kernel,
                              const std::vector<char>& inPart) const
{
    // The fluid's pressure push on the part from the fluid that lies
    // against the rest of the body (its nearest particle of the body is
    // not of the part), against the pairs' whole push by size. A long
    // part cut along a member has only the pairs that reach slantwise
    // across the cut's edge there (4-7 % in the tests); one cut through a
    // member thinner than the support also takes the push of the fluid on
    // the far face, against its own face's load.
    const particleFields& pf = s.particles;
    const std::uint8_t body = std::uint8_t(body_);
    vec3 fromRest{0, 0, 0};
    scalar gross = 0;
    for (label w = 0; w < pf.size(); ++w)
    {
        if (pf.kind[w] == fluidKind || pf.body[w] != body || !inPart[w])
        {
            continue;
        }
        forEachFluidNear(s, kernel, pf.position[w],
            [&](const label j, const scalar r)
        {
            if (r <= 0) return;
            const vec3 push = pressurePushOn(pf, kernel, w, j, r);
            scalar nearest = std::numeric_limits<scalar>::max();
            bool againstRest = false;
            forEachNear(s, kernel, pf.position[j], false,
                [&](const label k, const scalar rk)
            {
                if (pf.body[k] != body || rk >= nearest) return;
                nearest = rk;
                againstRest = !inPart[k];
            });
            gross += mag(push);
            if (againstRest) fromRest += push;
        });
    }
    if (gross <= 0) return;   // dry: looked at again at the next sample
    cutChecked_ = true;
    const scalar share = mag(fromRest)/gross;
    if (share < 0.1) return;
    warning("Function object '" + name() + "': " + str(100*share, 3)
        + " % of the fluid's push on its part of body " + bodyName_
        + " is the push of fluid that lies against the rest of the body (at"
          " time " + str(s.time) + "): the shapes cut through a member"
          " thinner than the kernel's support 2h = " + str(kernel.support())
        + " m, which the fluid on its far face reaches across, or leave a"
          " part not much longer than that, so the part's force is not the"
          " load on its own faces. Cut parts along the member (its upper"
          " half, say), or integrate probes onSolid on a face"
          " (docs/postProcessing.md)");
}


std::vector<char> forces::partMask(const solverSnapshot& s) const
{
    if (!part_) return {};
    const particleFields& pf = s.particles;
    const std::uint8_t body = std::uint8_t(body_);
    const bodyInfo& info = s.bodies.at(body_);
    // A solid's reference lattice; a wall where it stands in 0/.
    const solidView* solid = info.type == bodyType::solid
        ? &solidNamed(s, info.name, name()) : nullptr;
    const rigidTransform T = bodyMotion_ ? bodyMotion_->transform(s.time)
                                         : rigidTransform::identity();
    const scalar tol = 1e-6*dp_;
    std::vector<char> in(pf.size(), 0);
    label nIn = 0, nBody = 0;
    boundBox where = boundBox::invalid();
    for (label w = 0; w < pf.size(); ++w)
    {
        if (pf.kind[w] == fluidKind || pf.body[w] != body) continue;
        const point X = solid
            ? (*solid->reference)[pf.link[w] - solid->first]
            : bodyMotion_ ? T.reference(pf.position[w]) : pf.position[w];
        in[w] = part_->inside(toVec3(X), tol);
        nIn += in[w];
        ++nBody;
        if (!partChecked_) where.add(toVec3(X));   // for its warning
    }
    if (!partChecked_ && nBody > 0 && nIn == 0)
    {
        warning("Function object '" + name() + "': its shapes hold none of"
            " the particles of body " + info.name + ", which lie within "
            + str(where.min, 6) + " - " + str(where.max, 6) + " in the"
            " reference configuration (as in 0/): its force reads 0");
    }
    partChecked_ = true;
    nInPart_ = nIn;
    nInBody_ = nBody;
    return in;
}


void forces::writeHeader(std::ostream& os) const
{
    writeFileHeader(os, 0);
}


void forces::writeFileHeader(std::ostream& os, const std::size_t file) const
{
    if (part_)
    {
        os << "# On the " << nInPart_ << " of the " << nInBody_
           << " particles of body " << bodyName_ << " inside shapes, as it"
              " stands in the reference configuration (0/)\n";
    }
    if (file == 0)
    {
        writeUnits(os, "Time [s], F [" + perDepth("N", nDimensions_) + "]"
            + perDepthNote(nDimensions_));
        os << "# Time Fx Fy Fz\n";
        return;
    }
    os << frame_.headerLine()
       << "# Moment about CofR " << str(CofR_, 10) << "\n";
    writeUnits(os, "Time [s], M [" + perDepth("N m", nDimensions_) + "]"
        + perDepthNote(nDimensions_));
    os << "# Time Mx My Mz\n";
}


// * * * * * * * * * * * * * * * * * * energy * * * * * * * * * * * * * * * //

energy::energy(std::string name, const dictionary& dict,
               const std::filesystem::path& caseDir,
               const std::string& startTimeName, const int nDimensions)
:
    table(std::move(name), dict, caseDir, startTimeName, "energy.dat"),
    nDimensions_(nDimensions)
{
    dict.checkKeywords(commonKeywords);
}


std::vector<scalar> energy::values(const solverSnapshot& s) const
{
    const particleFields& pf = s.particles;
    const vec3 g = s.model.g;
    // (mass, kinetic, potential) in a vec3 for the reduction.
    const sumVec e = parallelReduce(openmpExec{}, pf.size(),
        [&](const label i)
        {
            if (pf.kind[i] != fluidKind) return sumVec{0, 0, 0};
            const double m = pf.mass[i];
            return sumVec{m, 0.5*m*magSqr(pf.velocity[i]),
                          -m*dot(toPoint(g), pf.position[i])};
        },
        sumVec{0, 0, 0}, vecSum{});
    return {scalar(e.x), scalar(e.y), scalar(e.z)};
}


void energy::writeHeader(std::ostream& os) const
{
    writeUnits(os, "Time [s], mass [" + perDepth("kg", nDimensions_)
        + "], kinetic and potential [" + perDepth("J", nDimensions_) + "]"
        + perDepthNote(nDimensions_));
    os << "# Time mass kinetic potential\n";
}


// * * * * * * * * * * * * * * * * * surgeFront * * * * * * * * * * * * * * //

surgeFront::surgeFront(std::string name, const dictionary& dict,
                       const std::filesystem::path& caseDir,
                       const std::string& startTimeName,
                       const int nDimensions)
:
    table(std::move(name), dict, caseDir, startTimeName, "front.dat"),
    origin_(dict.getOrDefault<vec3>("origin", vec3{0, 0, 0}))
{
    dict.checkKeywords(keywords({"direction", "origin"}));
    const vec3 d = dict.get<vec3>("direction");
    if (!(mag(unitVector(d)) > 0))
    {
        dict.fatalAt("direction", "Function object '" + this->name()
            + "': direction must be a finite, non-zero vector, found "
            + str(d, 10));
    }
    if (nDimensions == 2 && d.z != 0)
    {
        dict.fatalAt("direction", "Function object '" + this->name()
            + "': in a 2D case the direction lies in the x-y plane (z = 0),"
            " found " + str(d, 10));
    }
    direction_ = unitVector(d);
}


std::vector<scalar> surgeFront::values(const solverSnapshot& s) const
{
    const particleFields& pf = s.particles;
    const scalar none = -std::numeric_limits<scalar>::infinity();
    const scalar front = parallelReduce(openmpExec{}, pf.size(),
        [&](const label i)
        {
            return pf.kind[i] == fluidKind
              ? dot(toVec3(pf.position[i] - origin_), direction_) : none;
        },
        none,
        [](const scalar a, const scalar b) { return a > b ? a : b; });
    // No fluid left: 0 rather than -inf in the table.
    return {front == none ? 0 : front};
}


void surgeFront::writeHeader(std::ostream& os) const
{
    writeUnits(os, "Time [s], front [m]");
    os << "# Time front\n";
}

// * * * * * * * * * * * * * * * * solidPoints  * * * * * * * * * * * * * * //

solidPoints::solidPoints(std::string name, const dictionary& dict,
                         const std::filesystem::path& caseDir,
                         const std::string& startTimeName,
                         const sphModel& model,
                         const std::vector<bodyInfo>& bodies)
:
    table(std::move(name), dict, caseDir, startTimeName, "displacement.dat"),
    nDimensions_(model.nDimensions),
    dp_(model.dp)
{
    dict.checkKeywords(keywords({"body", "points", "frame"}));
    body_ = dict.get<std::string>("body");
    std::string solids;
    bool found = false;
    for (const bodyInfo& b : bodies)
    {
        if (b.type != bodyType::solid) continue;
        solids += (solids.empty() ? "" : " ") + b.name;
        found = found || b.name == body_;
    }
    if (!found)
    {
        dict.fatalAt("body", "Function object '" + this->name() + "': there"
            " is no solid body '" + body_ + "'. Solid bodies: (" + solids
            + ")");
    }
    points_ = readPoints(dict, "points", this->name(), model);

    const std::string frame = dict.getOrDefault<std::string>("frame", "lab");
    if (frame != "lab" && frame != "clamp")
    {
        dict.fatalAt("frame", "Function object '" + this->name() + "': frame"
            " '" + frame + "' is not one of: lab (x - X, the default), clamp"
            " (relative to the motion of the solid's clamp, in its axes)."
            " A body's name is the frame of probes and gauges, not of"
            " solidPoints, which follows its own solid's clamp");
    }
    if (frame == "clamp")
    {
        const motionSet motions = caseMotions(caseDir, nDimensions_);
        if (const namedMotion* m = motions.namedMotionOf(body_))
        {
            clampMotion_ = m->motion;
            clampMotionName_ = m->name;
        }
        else
        {
            dict.fatalAt("frame", "Function object '" + this->name() + "':"
                " frame clamp, but solid '" + body_ + "' is in no motion of"
                " constant/motion: its clamp stays in the lab frame (leave"
                " frame out), or name " + body_ + " among the bodies of the"
                " motion that carries it");
        }
    }
}


std::vector<scalar> solidPoints::values(const solverSnapshot& s) const
{
    const solidView& view = solidToFollow(s, body_, name());
    const std::vector<point>& X = *view.reference;
    const std::vector<point>& x = *view.position;
    if (particles_.empty())
    {
        for (const vec3& p : points_)
        {
            const label best = nearestReference(X, p);
            particles_.push_back(best);
            chosen_.push_back(toVec3(X[best]));
            const scalar d = mag(chosen_.back() - p);
            if (d > 2*dp_)
            {
                warning("Function object '" + name() + "': the point "
                    + str(p, 10) + " is " + str(d) + " m from solid '" + body_
                    + "' (its nearest particle, at " + str(chosen_.back(), 10)
                    + ", is followed instead): check the points");
            }
        }
    }
    std::vector<scalar> row;
    rigidTransform T = rigidTransform::identity();
    if (clampMotion_) T = clampMotion_->transform(s.time);
    for (const label i : particles_)
    {
        // frame clamp: what the solid adds to its clamp's rigid motion,
        // seen from the axes that move with it (a baffle's bending on a
        // rolling tank, without the roll).
        const vec3 u = clampMotion_ ? toVec3(T.rotateBack(x[i] - T.apply(X[i])))
                                    : toVec3(x[i] - X[i]);
        row.push_back(u.x);
        row.push_back(u.y);
        if (nDimensions_ == 3) row.push_back(u.z);
    }
    return row;
}


void solidPoints::writeHeader(std::ostream& os) const
{
    if (clampMotion_)
    {
        os << "# Displacement R^T (x - T(X)) of solid " << body_ << " relative"
           << " to its clamp's motion " << clampMotionName_ << " (T, rotation"
           << " R), in the axes that turn with it, at the particles with"
           << " reference positions X:\n";
    }
    else
    {
        os << "# Displacement x - X of solid " << body_ << " at the particles"
           << " with reference positions X:\n";
    }
    for (std::size_t k = 0; k < chosen_.size(); ++k)
    {
        os << "#   point " << k << ": " << str(chosen_[k], 10) << " (asked "
           << str(points_[k], 10) << ")\n";
    }
    writeUnits(os, "Time [s], u [m]");
    os << "# Time";
    for (std::size_t k = 0; k < chosen_.size(); ++k)
    {
        os << " ux" << k << " uy" << k;
        if (nDimensions_ == 3) os << " uz" << k;
    }
    os << "\n";
}

} // End namespace functionObjects
} // End namespace sphvcpm
