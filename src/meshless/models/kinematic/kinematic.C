/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "kinematic.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace bodyModels
{
    defineTypeNameAndDebug(kinematic, 0);
    addToRunTimeSelectionTable(bodyModel, kinematic, dictionary);
    addModelRole(kinematic, kinematic);
}
}
}


Foam::meshless::bodyModels::kinematic::kinematic
(
    particleBody& body,
    const dictionary& dict
)
:
    bodyModel(body, dict),
    U_(body.particles().addField("U", particleField::kind::vector)),
    acc_(body.particles().addField("acceleration", particleField::kind::vector))
{}


Foam::scalar Foam::meshless::bodyModels::kinematic::maxDeltaT
(
    const scalar maxCo
) const
{
    const scalar maxU = U_.maxMagnitude();
    return maxU > 0 ? maxCo*body_.spacing()/maxU : GREAT;
}


void Foam::meshless::bodyModels::kinematic::advance
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    acc_.fill(0);
    body_.addEffectAccelerations(t, acc_, costs);

    const label n = U_.size()*U_.nComponents();
    double* U = U_.data();
    double* x = body_.particles().positions().data();
    const double* a = acc_.data();

    #pragma omp parallel for schedule(static)
    for (label k = 0; k < n; ++k)
    {
        U[k] += dt*a[k];
        x[k] += dt*U[k];
    }
}
