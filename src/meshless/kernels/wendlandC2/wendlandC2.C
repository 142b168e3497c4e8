/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "wendlandC2.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(wendlandC2, 0);
    addToRunTimeSelectionTable(smoothingKernel, wendlandC2, dictionary);
}
}


Foam::meshless::wendlandC2::wendlandC2
(
    const dictionary& dict,
    const label dim,
    const scalar spacing
)
:
    kernelShape<wendlandC2>(dict, dim, spacing)
{
    using constant::mathematical::pi;
    setNormalisation(dim == 2 ? 7.0/(4.0*pi) : 21.0/(16.0*pi));
}
