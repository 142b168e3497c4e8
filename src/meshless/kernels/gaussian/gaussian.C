/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "gaussian.H"
#include "dictionaryChecks.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"
#include <cmath>

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(gaussian, 0);
    addToRunTimeSelectionTable(smoothingKernel, gaussian, dictionary);
}
}


Foam::meshless::gaussian::gaussian
(
    const dictionary& dict,
    const label dim,
    const scalar spacing
)
:
    kernelShape<gaussian>(dict, dim, spacing),
    qMax_(readPositiveOrDefault(dict, "horizon", 3)),
    C_(std::exp(-qMax_*qMax_))
{
    using constant::mathematical::pi;
    const scalar Q = qMax_;
    const scalar Q2 = Q*Q;

    // Integral of f over the support in units of h^dim
    const scalar integral =
        dim == 2
      ? pi*(1 - C_*(1 + Q2))
      : std::pow(pi, 1.5)*std::erf(Q) - 2*pi*Q*C_ - (4.0/3.0)*pi*Q2*Q*C_;

    setNormalisation(1/integral);
}
