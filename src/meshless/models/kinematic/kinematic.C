/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "kinematic.H"
#include "addToRunTimeSelectionTable.H"
#include <cmath>

namespace Foam
{
namespace meshless
{
namespace bodyModels
{
    defineTypeNameAndDebug(kinematic, 0);
    addToRunTimeSelectionTable(bodyModel, kinematic, dictionary);
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
    const label np = U_.size();
    const label dim = U_.nComponents();
    const double* U = U_.data();
    double maxU2 = 0;

    #pragma omp parallel for reduction(max:maxU2)
    for (label i = 0; i < np; ++i)
    {
        double u2 = 0;
        for (label d = 0; d < dim; ++d) u2 += U[i*dim + d]*U[i*dim + d];
        maxU2 = std::max(maxU2, u2);
    }
    return maxU2 > 0 ? maxCo*body_.spacing()/std::sqrt(maxU2) : GREAT;
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
