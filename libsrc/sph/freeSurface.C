/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The fluid's free surface by marching triangles and tetrahedra (see
// freeSurface.H).

#include "freeSurface.H"
#include "binLists.H"
#include "error.H"
#include "formatting.H"
#include "parallel.H"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

namespace sphvcpm
{

namespace
{

// The fluid particles of every fluid body in one list.
struct fluidSamples
{
    int nDimensions = 3;
    std::vector<point> x;
    std::vector<scalar> volume;
    // Fields every fluid body has, concatenated like x.
    std::vector<std::pair<std::string, std::vector<scalar>>> scalars;
    std::vector<std::pair<std::string, std::vector<vec3>>> vectors;
};

fluidSamples gather(const std::vector<const particleBody*>& fluids)
{
    fluidSamples s;
    if (fluids.empty())
    {
        return s;
    }
    s.nDimensions = fluids.front()->nDimensions();
    auto everyBodyHas = [&](const std::string& name, const fieldKind kind)
    {
        for (const particleBody* b : fluids)
        {
            if (!b->hasField(name) || b->kindOf(name) != kind) return false;
        }
        return true;
    };
    for (const char* name : {"p", "rho"})
    {
        if (everyBodyHas(name, fieldKind::scalarField))
        {
            s.scalars.push_back({name, {}});
        }
    }
    if (everyBodyHas("U", fieldKind::vectorField))
    {
        s.vectors.push_back({"U", {}});
    }
    for (const particleBody* b : fluids)
    {
        const auto& mass = b->scalarField("mass");
        const auto& rho = b->scalarField("rho");
        for (label i = 0; i < b->size(); ++i)
        {
            if (!(rho[i] > 0) || !(mass[i] > 0))
            {
                fatalError("Fluid body '" + b->name() + "': particle "
                    + std::to_string(b->labelField("id")[i]) + " has mass "
                    + std::to_string(mass[i]) + " and rho "
                    + std::to_string(rho[i]) + ": no volume for the free"
                      " surface");
            }
            // A 2D body's z is not used: 0 here, as the grid's.
            point x = b->position()[i];
            if (s.nDimensions == 2)
            {
                x.z = 0;
            }
            s.x.push_back(x);
            s.volume.push_back(mass[i]/rho[i]);
        }
        for (auto& [name, values] : s.scalars)
        {
            const auto& f = b->scalarField(name);
            values.insert(values.end(), f.begin(), f.end());
        }
        for (auto& [name, values] : s.vectors)
        {
            const auto& f = b->vectorField(name);
            values.insert(values.end(), f.begin(), f.end());
        }
    }
    return s;
}


// The particles binned in cells of the kernel's support over the grid's
// box, for the sums at grid nodes and at the surface's points.
class particleBins
{
public:
    particleBins(const fluidSamples& s, const point& origin,
                 const vec3& span, const scalar support)
    :
        s_(s),
        origin_(origin),
        size_(support)
    {
        for (int d = 0; d < 3; ++d)
        {
            n_[d] = d < s.nDimensions
                ? std::int64_t(std::floor(span[d]/size_)) + 1 : 1;
        }
        buildBinLists(n_[0]*n_[1]*n_[2], s.x.size(),
            [&](const std::size_t i, const auto& visit)
            {
                std::int64_t c[3];
                cellOf(s.x[i], c);
                visit((c[2]*n_[1] + c[1])*n_[0] + c[0]);
            },
            start_, items_);
    }

    // f(j, r) for every particle j within the support of y.
    template<class Kernel, class F>
    void forEachNear(const Kernel& kernel, const point& y, const F& f) const
    {
        const scalar support2 = kernel.support()*kernel.support();
        std::int64_t c[3];
        cellOf(y, c);
        std::int64_t lo[3], hi[3];
        for (int d = 0; d < 3; ++d)
        {
            lo[d] = std::max<std::int64_t>(c[d] - 1, 0);
            hi[d] = std::min<std::int64_t>(c[d] + 1, n_[d] - 1);
        }
        for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
        {
            for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
            {
                for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
                {
                    const std::int64_t b = (k*n_[1] + j)*n_[0] + i;
                    for (std::int64_t e = start_[b]; e < start_[b + 1]; ++e)
                    {
                        const label p = items_[e];
                        const scalar r2 = magSqr(toVec3(y - s_.x[p]));
                        if (r2 < support2)
                        {
                            f(p, std::sqrt(r2));
                        }
                    }
                }
            }
        }
    }

private:
    void cellOf(const point& y, std::int64_t c[3]) const
    {
        for (int d = 0; d < 3; ++d)
        {
            const double f = std::floor((y[d] - origin_[d])/size_);
            c[d] = d < s_.nDimensions
                ? std::clamp<std::int64_t>(std::int64_t(f), 0, n_[d] - 1)
                : 0;
        }
    }

    const fluidSamples& s_;
    point origin_;
    scalar size_;
    std::int64_t n_[3] = {1, 1, 1};
    std::vector<std::int64_t> start_;
    std::vector<label> items_;
};


// The contour of c = level on the grid: points on the grid's edges, shared
// by the cells that meet them.
class contour
{
public:
    contour(const std::vector<scalar>& c, const std::int64_t n[3],
            const point& origin, const scalar spacing, const scalar level,
            const int nDimensions)
    :
        c_(c),
        origin_(origin),
        spacing_(spacing),
        level_(level),
        nDimensions_(nDimensions)
    {
        std::copy(n, n + 3, n_);
        mesh_.nodesPerCell = nDimensions;
    }

    void run()
    {
        if (nDimensions_ == 2)
        {
            for (std::int64_t j = 0; j + 1 < n_[1]; ++j)
            {
                for (std::int64_t i = 0; i + 1 < n_[0]; ++i)
                {
                    square(i, j);
                }
            }
        }
        else
        {
            for (std::int64_t k = 0; k + 1 < n_[2]; ++k)
            {
                for (std::int64_t j = 0; j + 1 < n_[1]; ++j)
                {
                    for (std::int64_t i = 0; i + 1 < n_[0]; ++i)
                    {
                        cube(i, j, k);
                    }
                }
            }
        }
    }

    vtpMesh& mesh() { return mesh_; }
    double enclosed() const { return enclosed_; }

private:
    // The corner of a cell: bit 0 +x, bit 1 +y, bit 2 +z from (i, j, k).
    std::int64_t node(const int corner) const
    {
        const std::int64_t i = base_[0] + (corner & 1);
        const std::int64_t j = base_[1] + ((corner >> 1) & 1);
        const std::int64_t k = base_[2] + ((corner >> 2) & 1);
        return (k*n_[1] + j)*n_[0] + i;
    }

    point position(const int corner) const
    {
        return {origin_.x + spacing_*double(base_[0] + (corner & 1)),
                origin_.y + spacing_*double(base_[1] + ((corner >> 1) & 1)),
                origin_.z + spacing_*double(base_[2] + ((corner >> 2) & 1))};
    }

    bool inside(const int corner) const { return c_[node(corner)] > level_; }

    // The point where c = level on the edge from corner a to corner b
    // (a's bits a subset of b's: every edge of the split runs up the axes).
    std::int64_t edgePoint(int a, int b)
    {
        if (a > b)
        {
            std::swap(a, b);
        }
        const std::int64_t key = node(a)*8 + (a ^ b);
        const auto found = points_.find(key);
        if (found != points_.end())
        {
            return found->second;
        }
        const scalar ca = c_[node(a)], cb = c_[node(b)];
        const double t = double((level_ - ca)/(cb - ca));
        const point pa = position(a), pb = position(b);
        mesh_.points.push_back(pa + t*(pb - pa));
        points_.emplace(key, std::int64_t(mesh_.points.size() - 1));
        return std::int64_t(mesh_.points.size() - 1);
    }

    // Out of the fluid: from the mean of the inside corners to the mean of
    // the outside ones.
    point outward(const int* corners, const int n) const
    {
        point in{0, 0, 0}, out{0, 0, 0};
        int nIn = 0, nOut = 0;
        for (int v = 0; v < n; ++v)
        {
            const point p = position(corners[v]);
            if (inside(corners[v]))
            {
                in += toVec3(p);
                ++nIn;
            }
            else
            {
                out += toVec3(p);
                ++nOut;
            }
        }
        return out/double(nOut) - in/double(nIn);
    }

    void addCell(std::initializer_list<std::int64_t> ids)
    {
        mesh_.connectivity.insert(mesh_.connectivity.end(), ids);
        const point o = origin_;
        if (ids.size() == 2)
        {
            const point p = mesh_.points[*ids.begin()] - toVec3(o);
            const point q = mesh_.points[*(ids.begin() + 1)] - toVec3(o);
            enclosed_ += 0.5*(p.x*q.y - q.x*p.y);
        }
        else
        {
            const auto* id = ids.begin();
            const point a = mesh_.points[id[0]] - toVec3(o);
            const point b = mesh_.points[id[1]] - toVec3(o);
            const point c = mesh_.points[id[2]] - toVec3(o);
            enclosed_ += dot(a, cross(b, c))/6;
        }
    }

    // Marching triangles: a triangle of corners t[0..2] (each a subset of
    // the next).
    void triangle(const int t[3])
    {
        int in[3], out[3], nIn = 0, nOut = 0;
        for (int v = 0; v < 3; ++v)
        {
            (inside(t[v]) ? in[nIn++] : out[nOut++]) = t[v];
        }
        if (nIn == 0 || nOut == 0)
        {
            return;
        }
        std::int64_t p, q;
        if (nIn == 1)
        {
            p = edgePoint(in[0], out[0]);
            q = edgePoint(in[0], out[1]);
        }
        else
        {
            p = edgePoint(in[0], out[0]);
            q = edgePoint(in[1], out[0]);
        }
        const point d = outward(t, 3);
        const point e = mesh_.points[q] - toVec3(mesh_.points[p]);
        // (q - p) x z = (e.y, -e.x) must point out
        if (e.y*d.x - e.x*d.y < 0)
        {
            std::swap(p, q);
        }
        addCell({p, q});
    }

    // Marching tetrahedra: a tetrahedron of corners t[0..3].
    void tetrahedron(const int t[4])
    {
        int in[4], out[4], nIn = 0, nOut = 0;
        for (int v = 0; v < 4; ++v)
        {
            (inside(t[v]) ? in[nIn++] : out[nOut++]) = t[v];
        }
        if (nIn == 0 || nOut == 0)
        {
            return;
        }
        const point d = outward(t, 4);
        auto orient = [&](std::int64_t& a, std::int64_t& b,
                          const std::int64_t c)
        {
            const point pa = mesh_.points[a];
            const vec3 n = toVec3(cross(mesh_.points[b] - toVec3(pa),
                                        mesh_.points[c] - toVec3(pa)));
            if (dot(n, toVec3(d)) < 0)
            {
                std::swap(a, b);
            }
        };
        if (nIn == 1 || nOut == 1)
        {
            // one corner apart from the other three
            const int lone = nIn == 1 ? in[0] : out[0];
            const int* rest = nIn == 1 ? out : in;
            std::int64_t a = edgePoint(lone, rest[0]);
            std::int64_t b = edgePoint(lone, rest[1]);
            const std::int64_t c = edgePoint(lone, rest[2]);
            orient(a, b, c);
            addCell({a, b, c});
            return;
        }
        // two in, two out: the quadrilateral in0-out0, in0-out1, in1-out1,
        // in1-out0 (consecutive points share a corner), as two triangles
        std::int64_t q[4] = {edgePoint(in[0], out[0]),
                             edgePoint(in[0], out[1]),
                             edgePoint(in[1], out[1]),
                             edgePoint(in[1], out[0])};
        const vec3 n = toVec3(cross(mesh_.points[q[2]]
                                    - toVec3(mesh_.points[q[0]]),
                                    mesh_.points[q[3]]
                                    - toVec3(mesh_.points[q[1]])));
        if (dot(n, toVec3(d)) < 0)
        {
            std::swap(q[1], q[3]);
        }
        addCell({q[0], q[1], q[2]});
        addCell({q[0], q[2], q[3]});
    }

    // Cells whose corners are all on one side are skipped at once: most
    // of the grid.
    bool crossed(const int nCorners) const
    {
        const bool first = inside(0);
        for (int v = 1; v < nCorners; ++v)
        {
            if (inside(v) != first) return true;
        }
        return false;
    }

    void square(const std::int64_t i, const std::int64_t j)
    {
        base_[0] = i; base_[1] = j; base_[2] = 0;
        if (!crossed(4)) return;
        static const int halves[2][3] = {{0, 1, 3}, {0, 2, 3}};
        for (const auto& t : halves)
        {
            triangle(t);
        }
    }

    void cube(const std::int64_t i, const std::int64_t j, const std::int64_t k)
    {
        base_[0] = i; base_[1] = j; base_[2] = k;
        if (!crossed(8)) return;
        static const int axes[6][3] =
            {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
        for (const auto& a : axes)
        {
            const int t[4] = {0, 1 << a[0], (1 << a[0]) | (1 << a[1]), 7};
            tetrahedron(t);
        }
    }

    const std::vector<scalar>& c_;
    point origin_;
    scalar spacing_;
    scalar level_;
    int nDimensions_;
    std::int64_t n_[3] = {1, 1, 1};
    std::int64_t base_[3] = {0, 0, 0};
    vtpMesh mesh_;
    std::unordered_map<std::int64_t, std::int64_t> points_;
    double enclosed_ = 0;
};


template<class Kernel>
freeSurface extract(const fluidSamples& s, const Kernel& kernel,
                    const scalar spacing, const int refine,
                    const freeSurfaceSettings& settings)
{
    freeSurface result;
    result.mesh.nodesPerCell = s.nDimensions;
    for (const scalar v : s.volume)
    {
        result.particleVolume += v;
    }
    if (s.x.empty())
    {
        return result;
    }

    // The grid: the fluid's bounds grown by the support and a spacing, so
    // that c = 0 on its border and the surface closes.
    point lo = s.x.front(), hi = s.x.front();
    for (const point& x : s.x)
    {
        for (int d = 0; d < 3; ++d)
        {
            lo[d] = std::min(lo[d], x[d]);
            hi[d] = std::max(hi[d], x[d]);
        }
    }
    const double grow = kernel.support() + spacing;
    std::int64_t n[3] = {1, 1, 1};
    double nNodes = 1;
    for (int d = 0; d < s.nDimensions; ++d)
    {
        lo[d] -= grow;
        hi[d] += grow;
        const double cells = std::ceil((hi[d] - lo[d])/spacing);
        nNodes *= cells + 1;
        n[d] = std::isfinite(cells) && cells < 1e9
            ? std::int64_t(cells) + 1 : 0;
    }
    if (s.nDimensions == 2)
    {
        lo.z = 0;
    }
    if (!(nNodes <= double(settings.maxNodes)))
    {
        // The particles farthest from the fluid's median point: a particle
        // flung far away is what makes the bounds huge.
        point median{0, 0, 0};
        std::vector<double> axis(s.x.size());
        for (int d = 0; d < 3; ++d)
        {
            for (std::size_t i = 0; i < s.x.size(); ++i) axis[i] = s.x[i][d];
            std::nth_element(axis.begin(), axis.begin() + axis.size()/2,
                             axis.end());
            median[d] = axis[axis.size()/2];
        }
        // Far: beyond four times the distance within which 90 % lie (the
        // farthest one at least).
        std::vector<double> distance(s.x.size());
        for (std::size_t i = 0; i < s.x.size(); ++i)
        {
            distance[i] = mag(toVec3(s.x[i] - median));
        }
        std::vector<double> sorted = distance;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size()*9/10,
                         sorted.end());
        const double bulk = sorted[sorted.size()*9/10];
        std::vector<std::size_t> farOnes;
        for (std::size_t i = 0; i < s.x.size(); ++i)
        {
            if (distance[i] > 4*bulk) farOnes.push_back(i);
        }
        if (farOnes.empty())
        {
            farOnes.push_back(std::size_t(std::max_element(distance.begin(),
                distance.end()) - distance.begin()));
        }
        std::sort(farOnes.begin(), farOnes.end(),
                  [&](std::size_t a, std::size_t b)
                  {
                      return distance[a] > distance[b];
                  });
        std::string far;
        for (std::size_t k = 0; k < std::min<std::size_t>(3, farOnes.size());
             ++k)
        {
            far += (k ? ", " : "") + str(toVec3(s.x[farOnes[k]]));
        }
        if (farOnes.size() > 3)
        {
            far += " and " + std::to_string(farOnes.size() - 3) + " more";
        }
        // A coarser grid helps only when it is then small enough.
        const double coarser = nNodes/std::pow(double(refine), s.nDimensions);
        fatalError("The free surface's grid would have "
            + std::to_string(std::int64_t(std::min(nNodes, 9e18)))
            + " nodes (spacing " + std::to_string(spacing) + " m over the"
              " fluid's bounds " + str(toVec3(lo)) + " to "
            + str(toVec3(hi)) + "), more than "
            + std::to_string(settings.maxNodes) + ".\nThe fluid particles"
              " farthest from its median point " + str(toVec3(median))
            + " are at " + far + " (90 % lie within " + str(bulk) + " m of"
              " it): look for particles far from the rest"
            + (refine > 1 && coarser <= double(settings.maxNodes)
               ? ", or use a coarser grid (-surfaceRefine 1)." : "."));
    }
    result.nNodes = n[0]*n[1]*n[2];

    const particleBins bins(s, lo, toVec3(hi - lo), kernel.support());
    std::vector<scalar> c(result.nNodes);
    parallelFor(openmpExec{}, label(result.nNodes), [&](const label node)
    {
        const std::int64_t i = node % n[0];
        const std::int64_t j = (node/n[0]) % n[1];
        const std::int64_t k = node/(n[0]*n[1]);
        const point y{lo.x + spacing*double(i), lo.y + spacing*double(j),
                      lo.z + spacing*double(k)};
        scalar sum = 0;
        bins.forEachNear(kernel, y, [&](const label p, const scalar r)
        {
            sum += s.volume[p]*kernel.W(r);
        });
        c[node] = sum;
    });

    contour surface(c, n, lo, spacing, settings.level, s.nDimensions);
    surface.run();
    result.mesh = std::move(surface.mesh());
    result.enclosed = surface.enclosed();

    // Shepard interpolation of the fields to the surface's points.
    vtpMesh& mesh = result.mesh;
    const label nPoints = label(mesh.points.size());
    for (const auto& [name, values] : s.scalars)
    {
        mesh.scalarFields.push_back({name, std::vector<scalar>(nPoints)});
    }
    for (const auto& [name, values] : s.vectors)
    {
        mesh.vectorFields.push_back({name, std::vector<vec3>(nPoints)});
    }
    mesh.vectorFields.push_back({"Normals", std::vector<vec3>(nPoints)});
    mesh.normals = "Normals";
    std::vector<vec3>& normals = mesh.vectorFields.back().second;
    parallelFor(openmpExec{}, nPoints, [&](const label v)
    {
        std::vector<scalar> sums(s.scalars.size(), 0);
        std::vector<vec3> vsums(s.vectors.size(), vec3{0, 0, 0});
        scalar weight = 0;
        vec3 gradC{0, 0, 0};
        const point& y = mesh.points[v];
        bins.forEachNear(kernel, y, [&](const label p, const scalar r)
        {
            const scalar w = s.volume[p]*kernel.W(r);
            gradC += s.volume[p]*kernel.gradFactor(r)*toVec3(y - s.x[p]);
            weight += w;
            for (std::size_t f = 0; f < sums.size(); ++f)
            {
                sums[f] += w*s.scalars[f].second[p];
            }
            for (std::size_t f = 0; f < vsums.size(); ++f)
            {
                vsums[f] += w*s.vectors[f].second[p];
            }
        });
        // Every point has fluid in reach (c = level > 0 there).
        const scalar inv = weight > 0 ? 1/weight : 0;
        for (std::size_t f = 0; f < sums.size(); ++f)
        {
            mesh.scalarFields[f].second[v] = inv*sums[f];
        }
        for (std::size_t f = 0; f < vsums.size(); ++f)
        {
            mesh.vectorFields[f].second[v] = inv*vsums[f];
        }
        // Out of the fluid: down the gradient of c.
        const scalar g = mag(gradC);
        normals[v] = g > 0 ? (-1/g)*gradC : vec3{0, 0, 0};
    });
    return result;
}

} // End anonymous namespace


void checkFreeSurfaceSettings(const freeSurfaceSettings& settings)
{
    if (!(settings.level > 0 && settings.level < 1))
    {
        fatalError("The free surface's level " + str(settings.level)
            + " is not in (0, 1): it is the fluid's volume fraction there"
              " (0.5 is the fluid's edge)");
    }
    if (settings.refine < 0)
    {
        fatalError("The free surface's grid refinement "
            + std::to_string(settings.refine) + " is below 1"
              " (0: by dimension)");
    }
}


freeSurface fluidFreeSurface(const std::vector<const particleBody*>& fluids,
                             const kernelType kernel, const scalar h,
                             const freeSurfaceSettings& settings)
{
    checkFreeSurfaceSettings(settings);
    const fluidSamples s = gather(fluids);
    if (fluids.empty())
    {
        return {};
    }
    const int nDimensions = s.nDimensions;
    const int refine = settings.refine > 0 ? settings.refine
        : nDimensions == 2 ? 2 : 1;
    const scalar spacing = fluids.front()->dp()/refine;
    if (kernel == kernelType::wendlandC2)
    {
        return extract(s, wendlandC2Kernel(h, nDimensions), spacing, refine,
                       settings);
    }
    return extract(s, cubicSplineKernel(h, nDimensions), spacing, refine,
                   settings);
}

} // End namespace sphvcpm
