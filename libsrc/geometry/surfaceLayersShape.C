/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Layers of a given thickness on one side of a surface.

#include "surfaceLayersShape.H"
#include "error.H"
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
    if (nDimensions != 3)
    {
        dict.fatalAt("shape", "Shape '" + name_ + "': shape surfaceLayers"
            " needs nDimensions 3");
    }
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
        if (surface_->closed())
        {
            inside_ = std::make_unique<triSurfaceInside>(*surface_);
        }
        distance_ =
            std::make_unique<triSurfaceDistance>(*surface_, thickness_);

        const boundBox b = surface_->bounds();
        const vec3 grow{thickness_, thickness_, thickness_};
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
    const triSurfaceDistance::nearest n = distance_->find(p);
    if (n.face < 0 || n.distance <= tol || n.distance > thickness_ + tol)
    {
        return false;
    }
    if (side_ == sideType::both)
    {
        return true;
    }
    const bool in = inside_ ? inside_->inside(p) : n.side < 0;
    if (!inside_ && n.side == 0)
    {
        return false;
    }
    return side_ == sideType::inside ? in : !in;
}

} // End namespace sphvcpm
