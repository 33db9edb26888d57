/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Layers of a given thickness on one side of a surface.

#include "surfaceLayersShape.H"
#include "error.H"
#include "polygonShape.H"
#include "stlShape.H"

namespace sphvcpm
{

surfaceLayersShape::surfaceLayersShape
(
    std::string name,
    const dictionary& dict,
    int nDimensions,
    scalar dp,
    const std::filesystem::path& caseDir
)
:
    shape(std::move(name), nDimensions),
    bounds_(boundBox::invalid())
{
    try
    {
        stlDetail::surfaceInput in =
            stlDetail::readSurface(name_, dict, caseDir);
        const label layers = dict.get<label>("layers");
        if (layers < 1)
        {
            dict.fatalAt("layers", "Keyword 'layers': expected at least 1"
                " layer, found " + std::to_string(layers));
        }
        const std::string side =
            dict.getWord("side", {"both", "inside", "outside"});
        side_ = side == "outside" ? sideType::outside
              : side == "inside" ? sideType::inside : sideType::both;
        thickness_ = scalar(layers)*dp;

        const scalar merge = in.mergeDistance < 0
            ? stlDetail::defaultMergeDistance(in.soup) : in.mergeDistance;
        surface_ = std::make_unique<triSurface>(in.soup, merge);
        stlDetail::checkRepairs(*surface_, name_, in.source, merge);
        boundBox b;
        if (nDimensions_ == 3)
        {
            if (surface_->closed())
            {
                inside_ = std::make_unique<triSurfaceInside>(*surface_);
            }
            distance_ =
                std::make_unique<triSurfaceDistance>(*surface_, thickness_);
            b = surface_->bounds();
        }
        else
        {
            // The cut by z = 0, as for shape stl; closed when every
            // segment end is shared (then even-odd decides the side).
            cut_ = std::make_unique<planarRegion>
            (
                stlSliceShape::cutRegion(*surface_, name_, in.source)
            );
            closedCut_ = cut_->nOpenEnds() == 0;
            cutDistance_ = std::make_unique<segmentDistance>
            (
                cut_->segments(), thickness_
            );
            b = cut_->bounds();
        }
        const vec3 grow{thickness_, thickness_,
                        nDimensions_ == 3 ? thickness_ : 0};
        bounds_.add(b.min - grow);
        bounds_.add(b.max + grow);
    }
    catch (const FatalError& err)
    {
        stlDetail::rethrowForShape(err, name_, dict);
    }
}


bool surfaceLayersShape::inside(const vec3& p, scalar tol) const
{
    // Nearest point within the layers and its side; whether p is inside
    // when the surface (or cut) is closed.
    scalar distance = 0;
    int side = 0;
    bool closed = false;
    bool in = false;
    if (nDimensions_ == 3)
    {
        const triSurfaceDistance::nearest n = distance_->find(p);
        if (n.face < 0)
        {
            return false;
        }
        distance = n.distance;
        side = n.side;
        closed = bool(inside_);
        in = closed && inside_->inside(p);
    }
    else
    {
        const segmentDistance::nearest n = cutDistance_->find(p);
        if (n.segment < 0)
        {
            return false;
        }
        distance = n.distance;
        side = n.side;
        closed = closedCut_;
        in = closed && cut_->inside(p.x, p.y);
    }
    if (distance <= tol || distance > thickness_ + tol)
    {
        return false;
    }
    if (side_ == sideType::both)
    {
        return true;
    }
    if (!closed)
    {
        // Open: the normals decide; a point in line with a rim is on
        // neither side.
        if (side == 0)
        {
            return false;
        }
        in = side < 0;
    }
    return side_ == sideType::inside ? in : !in;
}

} // End namespace sphvcpm
