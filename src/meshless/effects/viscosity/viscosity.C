/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "viscosity.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace effects
{
    defineTypeNameAndDebug(viscosity, 0);
    addToRunTimeSelectionTable(effect, viscosity, dictionary);
}
}
}


Foam::meshless::effects::viscosity::viscosity
(
    const word& name,
    const dictionary& dict,
    particleBody& body
)
:
    effect(name, dict, body),
    mu_(0)
{
    if (dict.found("mu") == dict.found("nu"))
    {
        FatalIOErrorInFunction(dict)
            << "Effect " << name << ": expected exactly one of 'mu' (dynamic,"
            << " Pa s) and 'nu' (kinematic, m^2/s)" << exit(FatalIOError);
    }
    mu_ = dict.found("mu")
        ? readPositive(dict, "mu")
        : readPositive(dict, "nu")*body.density();
}


Foam::scalar Foam::meshless::effects::viscosity::maxDeltaT() const
{
    const scalar h = body_.hasKernel() ? body_.kernel().h() : body_.spacing();
    return 0.125*h*h*body_.density()/mu_;
}


void Foam::meshless::effects::viscosity::describe(Ostream& os) const
{
    os  << "Newtonian viscosity, mu " << mu_ << " Pa s";
}
