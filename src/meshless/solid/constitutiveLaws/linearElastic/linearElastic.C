/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "linearElastic.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace constitutiveLaws
{
    defineTypeNameAndDebug(linearElastic, 0);
    addToRunTimeSelectionTable(constitutiveLaw, linearElastic, dictionary);
}
}
}

const Foam::Enum
<
    Foam::meshless::constitutiveLaws::linearElastic::kinematicsType
>
Foam::meshless::constitutiveLaws::linearElastic::kinematicsNames
({
    { kinematicsType::small, "small" },
    { kinematicsType::finite, "finite" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::constitutiveLaws::linearElastic::linearElastic
(
    const dictionary& dict,
    const label dim,
    particleSet&
)
:
    constitutiveLaw(dict, dim),
    kinematics_(kinematicsNames.get("kinematics", dict)),
    lambda_(planeLambda()),
    G_(elastic_.G())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tensor Foam::meshless::constitutiveLaws::linearElastic::stress
(
    const label,
    const tensor&,
    const tensor& F
) const
{
    if (kinematics_ == kinematicsType::small)
    {
        return hooke(lambda_, G_, symm(F) - tensor::I);
    }

    const tensor E = 0.5*((F.T() & F) - tensor::I);
    const tensor Finv = inv(F);
    const tensor e = Finv.T() & E & Finv;
    return det(F)*(hooke(lambda_, G_, e) & Finv.T());
}


Foam::scalar Foam::meshless::constitutiveLaws::linearElastic::energyDensity
(
    const label,
    const tensor& F
) const
{
    if (kinematics_ == kinematicsType::small)
    {
        const tensor e = symm(F) - tensor::I;
        return 0.5*(hooke(lambda_, G_, e) && e);
    }

    const tensor E = 0.5*((F.T() & F) - tensor::I);
    const tensor Finv = inv(F);
    const tensor e = Finv.T() & E & Finv;
    const tensor S = det(F)*(Finv & hooke(lambda_, G_, e) & Finv.T());
    return 0.5*(S && E);
}


// ************************************************************************* //
