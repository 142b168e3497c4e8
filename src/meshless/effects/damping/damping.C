/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "damping.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace effects
{
    defineTypeNameAndDebug(damping, 0);
    addToRunTimeSelectionTable(effect, damping, dictionary);
}
}
}


Foam::meshless::effects::damping::damping
(
    const word& name,
    const dictionary& dict,
    particleBody& body
)
:
    effect(name, dict, body),
    c_(readPositive(dict, "coefficient")),
    U_(body.requireField("U", "effect " + name))
{}


void Foam::meshless::effects::damping::addAcceleration
(
    const scalar,
    particleField& acc
) const
{
    const label n = acc.size()*acc.nComponents();
    double* a = acc.data();
    const double* U = U_.data();

    #pragma omp parallel for schedule(static)
    for (label k = 0; k < n; ++k)
    {
        a[k] -= c_*U[k];
    }
}


void Foam::meshless::effects::damping::describe(Ostream& os) const
{
    os  << "damping, coefficient " << c_ << " 1/s";
}
