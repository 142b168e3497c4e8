/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "fsiCoupling.H"
#include "particleScene.H"
#include "solidModel.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(fsiCoupling, 0);
    defineRunTimeSelectionTable(fsiCoupling, dictionary);
}
}


Foam::meshless::fsiCoupling::fsiCoupling
(
    const dictionary& dict,
    particleScene& scene
)
:
    dict_(dict),
    scene_(scene),
    maxCo_(0.25)
{}


Foam::meshless::particleBody& Foam::meshless::fsiCoupling::fluidBody
(
    const word& keyword
) const
{
    particleBody& b = scene_.body(dict_.get<word>(keyword), dict_);
    if (!b.model().fluid())
    {
        FatalIOErrorInFunction(dict_)
            << "coupling " << type() << ": '" << keyword << "' "
            << b.name() << " has model " << b.dict().get<word>("model")
            << ": expected a fluid model ("
            << bodyModel::modelsOf(bodyModel::modelRole::fluid) << ")"
            << exit(FatalIOError);
    }
    return b;
}


Foam::meshless::particleBody& Foam::meshless::fsiCoupling::solidBody
(
    const word& name
) const
{
    particleBody& b = scene_.body(name, dict_);
    if (!b.model().solid())
    {
        FatalIOErrorInFunction(dict_)
            << "coupling " << type() << ": solid '" << name << "' has model "
            << b.dict().get<word>("model") << ": expected a solid model ("
            << bodyModel::modelsOf(bodyModel::modelRole::solid) << ")"
            << exit(FatalIOError);
    }
    return b;
}


Foam::label Foam::meshless::fsiCoupling::solidSteps
(
    const UList<particleBody*>& solids,
    const scalar dt,
    subStepping& counter
) const
{
    scalar dtSolid = GREAT;
    for (particleBody* b : solids)
    {
        dtSolid = min(dtSolid, b->model().solid()->stepLimit(maxCo_));
    }
    return counter(dt, dtSolid);
}


void Foam::meshless::fsiCoupling::stepSolids
(
    const UList<particleBody*>& solids,
    const scalar t,
    const scalar dt,
    const label n,
    costAccounting& costs
) const
{
    const scalar h = dt/n;
    for (particleBody* b : solids)
    {
        solidModel& s = *b->model().solid();
        costAccounting::scope timer(costs, b->modelCostPart());
        for (label j = 0; j < n; ++j)
        {
            s.step(t + j*h, h, costs);
        }
    }
}


// ************************************************************************* //
