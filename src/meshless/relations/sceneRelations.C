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
    stamp_(0)
{}


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
                new cellLinkedList(points.nComponents(), radius)
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
