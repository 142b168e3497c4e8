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
    autoPtr<smoothingKernel> kernel = selectConstructor
    (
        dict, "kernel", kernelType, *dictionaryConstructorTablePtr_
    )(dict, dim, spacing);
    if (!(kernel->support_ > 0 && kernel->norm_ > 0))
    {
        FatalErrorInFunction
            << "Kernel " << kernelType << ": support " << kernel->support_
            << " and normalisation " << kernel->norm_ << ", expected both"
            << " > 0 (its constructor must call setNormalisation)"
            << abort(FatalError);
    }
    return kernel;
}
