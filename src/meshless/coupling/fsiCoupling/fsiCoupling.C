/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "fsiCoupling.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(fsiCoupling, 0);
    defineRunTimeSelectionTable(fsiCoupling, dictionary);
}
}


Foam::meshless::fsiCoupling::fsiCoupling
(
    const dictionary& dict,
    particleScene& scene
)
:
    dict_(dict),
    scene_(scene)
{}


// ************************************************************************* //
