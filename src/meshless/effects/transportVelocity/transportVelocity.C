/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "transportVelocity.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace effects
{
    defineTypeNameAndDebug(transportVelocity, 0);
    addToRunTimeSelectionTable(effect, transportVelocity, dictionary);
}
}
}


Foam::meshless::effects::transportVelocity::transportVelocity
(
    const word& name,
    const dictionary& dict,
    particleBody& body
)
:
    effect(name, dict, body),
    coefficient_(readPositiveOrDefault(dict, "coefficient", 0.2))
{}


void Foam::meshless::effects::transportVelocity::describe(Ostream& os) const
{
    os  << "transport velocity, dx = " << coefficient_ << " h^2 Gamma"
        << " per advection step";
}


// ************************************************************************* //
