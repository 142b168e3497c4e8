/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "gravity.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace effects
{
    defineTypeNameAndDebug(gravity, 0);
    addToRunTimeSelectionTable(effect, gravity, dictionary);
}
}
}


Foam::meshless::effects::gravity::gravity
(
    const word& name,
    const dictionary& dict,
    particleBody& body
)
:
    effect(name, dict, body),
    g_(dict.get<vector>("value"))
{
    if (body.dim() == 2 && g_.z() != 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'value' is " << g_ << ": a 2D body takes gravity in"
            << " the x-y plane, expected a zero z component"
            << exit(FatalIOError);
    }
}


void Foam::meshless::effects::gravity::addAcceleration
(
    const scalar,
    particleField& acc
) const
{
    const label dim = body_.dim();
    const label n = acc.size();
    double* a = acc.data();

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        for (label d = 0; d < dim; ++d) a[i*dim + d] += g_[d];
    }
}


Foam::scalar Foam::meshless::effects::gravity::maxDeltaT() const
{
    const scalar gMag = mag(g_);
    if (gMag == 0) return GREAT;
    const scalar h = body_.hasKernel() ? body_.kernel().h() : body_.spacing();
    return 0.25*std::sqrt(h/gMag);
}


void Foam::meshless::effects::gravity::describe(Ostream& os) const
{
    os  << "gravity " << g_ << " m/s^2";
}
