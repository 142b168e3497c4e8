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
    smoothingKernel(dict, dim, spacing)
{
    using constant::mathematical::pi;
    setNormalisation(dim == 2 ? 7.0/(4.0*pi) : 21.0/(16.0*pi));
}


Foam::scalar Foam::meshless::wendlandC2::f(const scalar q) const
{
    if (q >= 2) return 0;
    const scalar a = 1 - 0.5*q;
    const scalar a2 = a*a;
    return a2*a2*(2*q + 1);
}


Foam::scalar Foam::meshless::wendlandC2::dfdq(const scalar q) const
{
    if (q >= 2) return 0;
    const scalar a = 1 - 0.5*q;
    return -5*q*a*a*a;
}


void Foam::meshless::wendlandC2::evaluate
(
    const double* r,
    const label n,
    double* w,
    double* dw
) const
{
    evaluateShape(*this, r, n, w, dw);
}
