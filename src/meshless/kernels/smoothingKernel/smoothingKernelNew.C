/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "smoothingKernel.H"

Foam::autoPtr<Foam::meshless::smoothingKernel>
Foam::meshless::smoothingKernel::New
(
    const dictionary& dict,
    const label dim,
    const scalar spacing
)
{
    const word kernelType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(kernelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "kernel",
            kernelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(dict, dim, spacing);
}
