/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "constitutiveLaw.H"

Foam::autoPtr<Foam::meshless::constitutiveLaw>
Foam::meshless::constitutiveLaw::New
(
    const dictionary& bodyDict,
    const label dim,
    particleSet& particles
)
{
    const dictionary& dict = bodyDict.subDict("constitutiveLaw");
    const word lawType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "constitutiveLaw",
            lawType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(dict, dim, particles);
}


// ************************************************************************* //
