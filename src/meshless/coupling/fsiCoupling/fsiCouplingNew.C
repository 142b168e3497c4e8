/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "fsiCoupling.H"
#include "dictionaryChecks.H"

Foam::autoPtr<Foam::meshless::fsiCoupling> Foam::meshless::fsiCoupling::New
(
    const dictionary& dict,
    particleScene& scene
)
{
    const word type(dict.get<word>("type"));
    return selectConstructor
    (
        dict, "coupling type", type, *dictionaryConstructorTablePtr_
    )(dict, scene);
}


// ************************************************************************* //
