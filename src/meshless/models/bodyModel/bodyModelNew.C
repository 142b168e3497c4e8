/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "bodyModel.H"

Foam::autoPtr<Foam::meshless::bodyModel> Foam::meshless::bodyModel::New
(
    particleBody& body,
    const dictionary& dict
)
{
    const word modelType(dict.get<word>("model"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "model",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(body, dict);
}
