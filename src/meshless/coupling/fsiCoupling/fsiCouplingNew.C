/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "fsiCoupling.H"

Foam::autoPtr<Foam::meshless::fsiCoupling> Foam::meshless::fsiCoupling::New
(
    const dictionary& dict,
    particleScene& scene
)
{
    const word type(dict.get<word>("type"));
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(type);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "coupling type",
            type,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }
    return cstrIter()(dict, scene);
}


// ************************************************************************* //
