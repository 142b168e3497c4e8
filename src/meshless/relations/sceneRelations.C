/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "sceneRelations.H"
#include "dictionary.H"

const Foam::Enum<Foam::meshless::sceneRelations::smoothingRule>
Foam::meshless::sceneRelations::smoothingRuleNames
({
    { smoothingRule::own, "own" },
    { smoothingRule::mean, "mean" },
    { smoothingRule::max, "max" },
});


Foam::meshless::sceneRelations::sceneRelations()
:
    periodic_(),
    periodicDict_(nullptr),
    stamp_(0)
{}


void Foam::meshless::sceneRelations::setPeriodic
(
    const periodicBox& box,
    const dictionary* dict
)
{
    if (!relations_.empty() || !cells_.empty())
    {
        FatalErrorInFunction
            << "Periodic directions set after " << relations_.size()
            << " relations were asked for: expected them first"
            << exit(FatalError);
    }
    periodic_ = box;
    periodicDict_ = dict;
}


Foam::meshless::sceneRelations::cells&
Foam::meshless::sceneRelations::cellsOf
(
    const particleField& points,
    const scalar radius,
    const bool moving
)
{
    for (cells& c : cells_)
    {
        if (c.points == &points && c.radius == radius)
        {
            c.moving = c.moving || moving;
            return c;
        }
    }
    cells_.push_back
    (
        cells
        {
            &points, radius, moving, -1,
            std::unique_ptr<cellLinkedList>
            (
                new cellLinkedList(points.nComponents(), radius, periodic_)
            )
        }
    );
    return cells_.back();
}


void Foam::meshless::sceneRelations::updateCells(cells& c)
{
    if (c.stamp >= 0 && (!c.moving || c.stamp == stamp_)) return;
    c.list->build(c.points->data(), c.points->size());
    c.stamp = stamp_;
}


Foam::meshless::neighbourRelation& Foam::meshless::sceneRelations::find
(
    const word& name,
    const particleField& xA,
    const particleField& xB,
    const bool inner,
    const smoothingKernel& W,
    const scalar skin,
    const bool movingA,
    const bool movingB,
    const unsigned geometry
)
{
    const scalar radius = W.radius()*(1 + skin);
    static const char* const dirNames[3] = {"x", "y", "z"};
    for (label d = 0; d < xA.nComponents(); ++d)
    {
        if (!periodic_.periodic(d) || periodic_.length(d) > 2*radius)
        {
            continue;
        }
        const std::string why
        (
            "Relation '" + std::string(name) + "': periodic direction "
          + std::string(dirNames[d]) + " has period "
          + std::to_string(periodic_.length(d))
          + ", expected more than twice its search radius "
          + std::to_string(radius)
          + " (kernel support, grown by the model's skin): a particle would"
            " see two images of a neighbour. Lengthen the period or refine"
            " the body."
        );
        if (periodicDict_)
        {
            FatalIOErrorInFunction(*periodicDict_)
                << why.c_str() << exit(FatalIOError);
        }
        FatalErrorInFunction << why.c_str() << exit(FatalError);
    }
    for (auto& r : relations_)
    {
        if
        (
            &r->pointsA() == &xA && &r->pointsB() == &xB
         && r->inner() == inner
         && &r->kernel() == &W && r->cellsB().radius() == radius
        )
        {
            r->cache(geometry);
            if (movingA || movingB)
            {
                r->setMoving();
                cellsOf(xB, radius, movingB);
            }
            return *r;
        }
    }

    // Cell lists are kept in a vector of structs that may grow: the
    // relation holds the list itself, which never moves (unique_ptr)
    cells& c = cellsOf(xB, radius, movingB);
    relations_.emplace_back
    (
        new neighbourRelation
        (
            name, xA, xB, inner, W, *c.list, geometry,
            !movingA && !movingB
        )
    );
    return *relations_.back();
}


Foam::meshless::neighbourRelation& Foam::meshless::sceneRelations::inner
(
    const word& name,
    const particleField& points,
    const smoothingKernel& W,
    const scalar skin,
    const bool moving,
    const unsigned geometry
)
{
    return find(name, points, points, true, W, skin, moving, moving, geometry);
}


Foam::meshless::neighbourRelation& Foam::meshless::sceneRelations::contact
(
    const word& name,
    const particleField& xA,
    const particleField& xB,
    const smoothingKernel& W,
    const scalar skin,
    const bool movingA,
    const bool movingB,
    const unsigned geometry
)
{
    return find(name, xA, xB, false, W, skin, movingA, movingB, geometry);
}


const Foam::meshless::smoothingKernel&
Foam::meshless::sceneRelations::pairKernel
(
    const dictionary& kernelDictA,
    const smoothingKernel& Wa,
    const smoothingKernel& Wb,
    const smoothingRule rule
)
{
    if
    (
        rule == smoothingRule::own
     || (Wa.h() == Wb.h() && Wa.radius() == Wb.radius())
    )
    {
        return Wa;
    }

    for (const kernel& k : kernels_)
    {
        if (k.a == &Wa && k.b == &Wb && k.rule == rule) return *k.W;
    }
    const scalar h =
        rule == smoothingRule::mean
      ? 0.5*(Wa.h() + Wb.h())
      : Foam::max(Wa.h(), Wb.h());
    dictionary d(kernelDictA);
    d.remove("smoothingLengthRatio");
    d.set("smoothingLength", h);
    kernels_.push_back
    (
        kernel{&Wa, &Wb, rule, smoothingKernel::New(d, Wa.dim(), h)}
    );
    return *kernels_.back().W;
}


void Foam::meshless::sceneRelations::update()
{
    ++stamp_;
    for (auto& r : relations_)
    {
        update(*r);
    }
}


void Foam::meshless::sceneRelations::rebuildEveryUpdate
(
    const std::vector<const particleSet*>& fixedOrder
)
{
    auto fixed = [&](const particleField* f)
    {
        for (const particleSet* s : fixedOrder)
        {
            if (s->holds(f)) return true;
        }
        return false;
    };
    for (auto& r : relations_)
    {
        if (!fixed(&r->pointsA()) || !fixed(&r->pointsB())) r->setMoving();
    }
    for (cells& c : cells_)
    {
        if (!fixed(c.points)) c.moving = true;
    }
}


Foam::scalar Foam::meshless::sceneRelations::maxRadius() const
{
    scalar R = 0;
    for (const cells& c : cells_) R = Foam::max(R, c.radius);
    return R;
}


void Foam::meshless::sceneRelations::update(neighbourRelation& r)
{
    if (r.builds() > 0 && r.isStatic()) return;
    for (cells& c : cells_)
    {
        if (c.list.get() == &r.cellsB())
        {
            updateCells(c);
            break;
        }
    }
    r.update(stamp_);
}


// ************************************************************************* //
