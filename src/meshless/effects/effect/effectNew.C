/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "effect.H"
#include "dictionaryChecks.H"

Foam::autoPtr<Foam::meshless::effect> Foam::meshless::effect::New
(
    const word& name,
    const dictionary& dict,
    particleBody& body
)
{
    const word effectType(dict.getOrDefault<word>("type", name));
    return selectConstructor
    (
        dict, "effect", effectType, *dictionaryConstructorTablePtr_
    )(name, dict, body);
}
