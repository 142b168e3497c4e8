/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "effect.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(effect, 0);
    defineRunTimeSelectionTable(effect, dictionary);
}
}


Foam::meshless::effect::effect
(
    const word& name,
    const dictionary& dict,
    particleBody& body
)
:
    name_(name),
    dict_(dict),
    body_(body)
{}
