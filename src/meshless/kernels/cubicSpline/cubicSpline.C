/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "cubicSpline.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(cubicSpline, 0);
    addToRunTimeSelectionTable(smoothingKernel, cubicSpline, dictionary);
}
}


Foam::meshless::cubicSpline::cubicSpline
(
    const dictionary& dict,
    const label dim,
    const scalar spacing
)
:
    kernelShape<cubicSpline>(dict, dim, spacing)
{
    using constant::mathematical::pi;
    setNormalisation(dim == 2 ? 10.0/(7.0*pi) : 1.0/pi);
}
