/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "effect.H"

Foam::autoPtr<Foam::meshless::effect> Foam::meshless::effect::New
(
    const word& name,
    const dictionary& dict,
    particleBody& body
)
{
    const word effectType(dict.getOrDefault<word>("type", name));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(effectType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "effect",
            effectType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(name, dict, body);
}
