/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Ordered union and subtraction of shapes.

#include "region.H"
#include "error.H"

namespace sphvcpm
{

region::region(int nDimensions)
:
    nDimensions_(nDimensions)
{}


void region::addShapes
(
    const dictionary& shapesDict,
    scalar dp,
    const std::filesystem::path& caseDir,
    const vec3& latticeOrigin
)
{
    const std::vector<std::string> names = shapesDict.keys();
    if (names.empty())
    {
        shapesDict.fatal("Dictionary 'shapes' is empty: give at least one"
            " shape, e.g. column { shape box; min (0 0 0); max (1 1 1); }",
            "shapes");
    }

    for (const std::string& name : names)
    {
        const dictionary* dict = shapesDict.findDict(name);
        if (!dict)
        {
            std::string valid;
            for (const std::string& t : shape::types())
            {
                valid += (valid.empty() ? "" : " ") + t;
            }
            shapesDict.fatalAt(name, "Entry '" + name + "' of 'shapes' is not"
                " a shape: each shape is a sub-dictionary, e.g. " + name
                + " { shape box; min (0 0 0); max (1 1 1); }. Valid shapes"
                  " are: (" + valid + ")");
        }
        std::unique_ptr<shape> s =
            shape::New
            (
                name, *dict, nDimensions_, dp, {"operation"}, caseDir,
                latticeOrigin
            );
        const operation op =
            dict->getWordOrDefault("operation", {"add", "subtract"}, "add")
         == "add"
          ? operation::add
          : operation::subtract;
        if (op == operation::subtract && shapes_.empty())
        {
            dict->fatalAt("operation", "Shape '" + name + "' subtracts from"
                " nothing: it is the first shape, and the first shape must"
                " add (operation add, the default)");
        }
        add(std::move(s), op);
    }
}


void region::add(std::unique_ptr<shape> s, operation op)
{
    if (s->nDimensions() != nDimensions_)
    {
        fatalError("Shape '" + s->name() + "' is "
            + std::to_string(s->nDimensions()) + "D, the region "
            + std::to_string(nDimensions_) + "D");
    }
    shapes_.push_back(std::move(s));
    ops_.push_back(op);
}


bool region::inside(const vec3& p, scalar tol) const
{
    // The last shape containing p decides; walking backwards stops there.
    for (std::size_t i = shapes_.size(); i-- > 0;)
    {
        if (shapes_[i]->inside(p, tol))
        {
            return ops_[i] == operation::add;
        }
    }
    return false;
}


boundBox region::bounds() const
{
    boundBox b = boundBox::invalid();
    for (std::size_t i = 0; i < shapes_.size(); ++i)
    {
        if (ops_[i] == operation::add)
        {
            b.add(shapes_[i]->bounds());
        }
    }
    return b;
}


scalar region::volume() const
{
    std::vector<std::size_t> added, subtracted;
    for (std::size_t i = 0; i < shapes_.size(); ++i)
    {
        if (shapes_[i]->volume() < 0)
        {
            return -1;
        }
        (ops_[i] == operation::add ? added : subtracted).push_back(i);
    }

    const auto disjoint = [&](const std::vector<std::size_t>& list)
    {
        for (std::size_t a = 0; a < list.size(); ++a)
        {
            for (std::size_t b = a + 1; b < list.size(); ++b)
            {
                if
                (
                    shapes_[list[a]]->bounds().overlaps
                    (
                        shapes_[list[b]]->bounds(), nDimensions_
                    )
                )
                {
                    return false;
                }
            }
        }
        return true;
    };
    if (!disjoint(added) || !disjoint(subtracted))
    {
        return -1;
    }

    scalar v = 0;
    for (const std::size_t i : added)
    {
        v += shapes_[i]->volume();
    }
    for (const std::size_t i : subtracted)
    {
        // Only a box's bounds are the box itself, and a box added after
        // the subtraction would fill the hole again.
        bool within = false;
        for (const std::size_t j : added)
        {
            within = within
             || (j < i && shapes_[j]->type() == "box"
              && shapes_[j]->bounds().encloses
                 (
                     shapes_[i]->bounds(), nDimensions_
                 ));
        }
        if (!within)
        {
            return -1;
        }
        v -= shapes_[i]->volume();
    }
    return v;
}

} // End namespace sphvcpm
