/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "bodyModel.H"
#include "dictionaryChecks.H"

Foam::autoPtr<Foam::meshless::bodyModel> Foam::meshless::bodyModel::New
(
    particleBody& body,
    const dictionary& dict
)
{
    const word modelType(dict.get<word>("model"));
    return selectConstructor
    (
        dict, "model", modelType, *dictionaryConstructorTablePtr_
    )(body, dict);
}
