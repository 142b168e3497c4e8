/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "constitutiveLaw.H"
#include "dictionaryChecks.H"

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
    return selectConstructor
    (
        dict, "constitutiveLaw", lawType, *dictionaryConstructorTablePtr_
    )(dict, dim, particles);
}


// ************************************************************************* //
