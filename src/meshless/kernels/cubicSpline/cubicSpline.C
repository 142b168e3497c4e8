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
    smoothingKernel(dict, dim, spacing)
{
    using constant::mathematical::pi;
    setNormalisation(dim == 2 ? 10.0/(7.0*pi) : 1.0/pi);
}


Foam::scalar Foam::meshless::cubicSpline::f(const scalar q) const
{
    if (q < 1) return 1 - 1.5*q*q + 0.75*q*q*q;
    if (q < 2)
    {
        const scalar a = 2 - q;
        return 0.25*a*a*a;
    }
    return 0;
}


Foam::scalar Foam::meshless::cubicSpline::dfdq(const scalar q) const
{
    if (q < 1) return -3*q + 2.25*q*q;
    if (q < 2)
    {
        const scalar a = 2 - q;
        return -0.75*a*a;
    }
    return 0;
}


void Foam::meshless::cubicSpline::evaluate
(
    const double* r,
    const label n,
    double* w,
    double* dw
) const
{
    evaluateShape(*this, r, n, w, dw);
}
