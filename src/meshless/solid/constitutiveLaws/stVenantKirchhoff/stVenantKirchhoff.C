/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "stVenantKirchhoff.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace constitutiveLaws
{
    defineTypeNameAndDebug(stVenantKirchhoff, 0);
    addToRunTimeSelectionTable
    (
        constitutiveLaw,
        stVenantKirchhoff,
        dictionary
    );
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::constitutiveLaws::stVenantKirchhoff::stVenantKirchhoff
(
    const dictionary& dict,
    const label dim,
    particleSet&
)
:
    constitutiveLaw(dict, dim),
    lambda_(planeLambda()),
    G_(elastic_.G())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tensor Foam::meshless::constitutiveLaws::stVenantKirchhoff::stress
(
    const label,
    const tensor&,
    const tensor& F
) const
{
    const tensor E = 0.5*((F.T() & F) - tensor::I);
    return F & hooke(lambda_, G_, E);
}


Foam::scalar
Foam::meshless::constitutiveLaws::stVenantKirchhoff::energyDensity
(
    const label,
    const tensor& F
) const
{
    const tensor E = 0.5*((F.T() & F) - tensor::I);
    return 0.5*(hooke(lambda_, G_, E) && E);
}


// ************************************************************************* //
