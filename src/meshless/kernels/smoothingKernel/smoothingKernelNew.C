/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "smoothingKernel.H"
#include "dictionaryChecks.H"

Foam::autoPtr<Foam::meshless::smoothingKernel>
Foam::meshless::smoothingKernel::New
(
    const dictionary& dict,
    const label dim,
    const scalar spacing
)
{
    const word kernelType(dict.get<word>("type"));
    return selectConstructor
    (
        dict, "kernel", kernelType, *dictionaryConstructorTablePtr_
    )(dict, dim, spacing);
}
