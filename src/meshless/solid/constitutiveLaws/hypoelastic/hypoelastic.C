/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "hypoelastic.H"
#include "hughesWinget.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace constitutiveLaws
{
    defineTypeNameAndDebug(hypoelastic, 0);
    addToRunTimeSelectionTable(constitutiveLaw, hypoelastic, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::constitutiveLaws::hypoelastic::hypoelastic
(
    const dictionary& dict,
    const label dim,
    particleSet& particles
)
:
    constitutiveLaw(dict, dim),
    sigma_(particles.addField("sigma", particleField::kind::tensor)),
    sigmaZZ_
    (
        dim == 2
      ? &particles.addField("sigmaZZ", particleField::kind::scalar)
      : nullptr
    )
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::tensor Foam::meshless::constitutiveLaws::hypoelastic::cauchy
(
    const label i
) const
{
    if (dim_ == 3)
    {
        tensor s;
        for (direction c = 0; c < 9; ++c) s[c] = sigma_(i, c);
        return s;
    }
    return tensor
    (
        sigma_(i, 0), sigma_(i, 1), 0,
        sigma_(i, 2), sigma_(i, 3), 0,
        0, 0, (*sigmaZZ_)(i, 0)
    );
}


Foam::tensor Foam::meshless::constitutiveLaws::hypoelastic::trial
(
    const label i,
    const tensor& Fold,
    const tensor& F
) const
{
    const hughesWinget::increment inc = hughesWinget::update(Fold, F);
    return hughesWinget::rotate(inc.R, cauchy(i)) + elasticIncrement(inc.gamma);
}


Foam::tensor Foam::meshless::constitutiveLaws::hypoelastic::returnMap
(
    const tensor& sigmaTrial,
    scalar& dLambda
) const
{
    dLambda = 0;
    return sigmaTrial;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tensor Foam::meshless::constitutiveLaws::hypoelastic::elasticIncrement
(
    const tensor& gamma
) const
{
    const scalar G = elastic_.G();
    if (dim_ == 3)
    {
        return hooke(elastic_.lambda(), G, gamma);
    }

    // 2D: gamma has no zz part; the in-plane response is the plane model's
    const scalar trg = gamma.xx() + gamma.yy();
    const scalar lp = planeLambda();
    tensor d = 2*G*gamma;
    d.xx() += lp*trg;
    d.yy() += lp*trg;
    d.zz() = plane_ == planeModel::strain ? elastic_.lambda()*trg : 0;
    return d;
}


Foam::tensor Foam::meshless::constitutiveLaws::hypoelastic::stress
(
    const label i,
    const tensor& Fold,
    const tensor& F
) const
{
    scalar dLambda;
    return hughesWinget::piola(F, returnMap(trial(i, Fold, F), dLambda));
}


void Foam::meshless::constitutiveLaws::hypoelastic::commit
(
    const label i,
    const tensor& Fold,
    const tensor& F
)
{
    scalar dLambda;
    const tensor s = returnMap(trial(i, Fold, F), dLambda);
    if (dim_ == 3)
    {
        for (direction c = 0; c < 9; ++c) sigma_(i, c) = s[c];
    }
    else
    {
        sigma_(i, 0) = s.xx();
        sigma_(i, 1) = s.xy();
        sigma_(i, 2) = s.yx();
        sigma_(i, 3) = s.yy();
        (*sigmaZZ_)(i, 0) = s.zz();
    }
    commitPlastic(i, dLambda);
}


Foam::scalar Foam::meshless::constitutiveLaws::hypoelastic::energyDensity
(
    const label i,
    const tensor&
) const
{
    const tensor s = cauchy(i);
    const scalar E = elastic_.E();
    const scalar nu = elastic_.nu();
    const tensor eps = ((1 + nu)*s - nu*tr(s)*tensor::I)/E;
    return 0.5*(s && eps);
}


// ************************************************************************* //
