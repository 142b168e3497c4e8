/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "druckerPrager.H"
#include "dictionaryChecks.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace constitutiveLaws
{
    defineTypeNameAndDebug(druckerPrager, 0);
    addToRunTimeSelectionTable(constitutiveLaw, druckerPrager, dictionary);
}
}
}


namespace
{

//- An angle in [0, 90) degrees, in radians
Foam::scalar readAngle(const Foam::dictionary& dict, const Foam::word& key)
{
    const Foam::scalar deg = dict.get<Foam::scalar>(key);
    if (!(deg >= 0 && deg < 90))
    {
        FatalIOErrorInFunction(dict)
            << "'" << key << "' = " << deg << ": expected an angle in"
            << " degrees in [0, 90)" << Foam::exit(Foam::FatalIOError);
    }
    return deg*Foam::constant::mathematical::pi/180;
}

Foam::scalar coneSlope(const Foam::scalar angle)
{
    const Foam::scalar t = std::tan(angle);
    return t/std::sqrt(9 + 12*t*t);
}

}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::constitutiveLaws::druckerPrager::druckerPrager
(
    const dictionary& dict,
    const label dim,
    particleSet& particles
)
:
    hypoelastic(dict, dim, particles),
    aPhi_(0),
    kc_(0),
    aPsi_(0),
    plasticStrain_
    (
        particles.addField("plasticStrain", particleField::kind::scalar)
    )
{
    if (plane_ == planeModel::stress)
    {
        FatalIOErrorInFunction(dict)
            << "druckerPrager: 'plane stress' is not supported (the return"
            << " mapping needs sigma_zz free); expected 'plane strain'"
            << exit(FatalIOError);
    }
    const scalar phi = readAngle(dict, "frictionAngle");
    const scalar psi = readAngle(dict, "dilationAngle");
    if (psi > phi)
    {
        FatalIOErrorInFunction(dict)
            << "'dilationAngle' exceeds 'frictionAngle': expected psi <= phi"
            << exit(FatalIOError);
    }
    const scalar c = readPositive(dict, "cohesion");
    const scalar t = std::tan(phi);
    aPhi_ = coneSlope(phi);
    aPsi_ = coneSlope(psi);
    kc_ = 3*c/std::sqrt(9 + 12*t*t);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::meshless::constitutiveLaws::druckerPrager::yieldFunction
(
    const tensor& sigma
) const
{
    const tensor s = dev(sigma);
    return std::sqrt(0.5*(s && s)) + aPhi_*tr(sigma) - kc_;
}


Foam::tensor Foam::meshless::constitutiveLaws::druckerPrager::returnMap
(
    const tensor& sigmaTrial,
    scalar& dLambda
) const
{
    dLambda = 0;
    const scalar f = yieldFunction(sigmaTrial);
    if (f <= 0) return sigmaTrial;

    const scalar G = elastic_.G();
    const scalar K = elastic_.K();
    const tensor s = dev(sigmaTrial);
    const scalar q = std::sqrt(0.5*(s && s));

    dLambda = f/(G + 9*K*aPhi_*aPsi_);
    if (q - G*dLambda > 0)
    {
        return sigmaTrial - dLambda*(G/q*s + 3*K*aPsi_*tensor::I);
    }

    // Beyond the apex (a_phi > 0 here: a cone with q <= G dLambda)
    return kc_/(3*aPhi_)*tensor::I;
}


void Foam::meshless::constitutiveLaws::druckerPrager::commitPlastic
(
    const label i,
    const scalar dLambda
)
{
    // |dg/dsigma|^2 = 1/2 + 3 a_psi^2
    plasticStrain_(i, 0) +=
        dLambda*std::sqrt(2.0/3.0*(0.5 + 3*aPsi_*aPsi_));
}


// ************************************************************************* //
