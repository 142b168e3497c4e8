/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ulphPd.H"
#include "particleScene.H"
#include "fluidModel.H"
#include "solidModel.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include <cmath>

namespace Foam
{
namespace meshless
{
namespace couplings
{
    defineTypeNameAndDebug(ulphPd, 0);
    addToRunTimeSelectionTable(fsiCoupling, ulphPd, dictionary);
}
}
}


Foam::meshless::couplings::ulphPd::ulphPd
(
    const dictionary& dict,
    particleScene& scene
)
:
    ghostCoupling(dict, scene),
    subSteps_
    (
        "coupling " + dict.get<word>("type"),
        dict.found("minSubSteps") ? readPositiveLabel(dict, "minSubSteps") : 1,
        "solid sub-steps per fluid step"
    )
{
    const word accType
    (
        dict.getOrDefault<word>("solidAcceleration", "none")
    );
    if (accType != "none" && accType != "step")
    {
        FatalIOErrorInFunction(dict)
            << "coupling " << dict.get<word>("type") << ": solidAcceleration "
            << accType
            << ": expected none or step" << exit(FatalIOError);
    }
    const bool stepAcc = accType == "step";
    for (particleBody* sbp : solidBodies_)
    {
        particleBody& sb = *sbp;
        // Written when used (restart state of the solid's ghosts)
        stepAcceleration_.push_back
        (
            stepAcc
          ? &sb.particles().addField
            (
                "stepAcceleration",
                particleField::kind::vector
            )
          : &sb.particles().addScratchField
            (
                "stepAcceleration",
                particleField::kind::vector
            )
        );
        U0_.emplace_back(sb.particles().size()*sb.dim());
        addGhosts(sb, stepAcc ? "stepAcceleration" : "");
    }
}


void Foam::meshless::couplings::ulphPd::storeStepStartVelocities()
{
    forAll(solidBodies_, k)
    {
        const particleField& U = solidBodies_[k]->particles().field("U");
        std::vector<double>& U0 = U0_[k];
        std::copy(U.data(), U.data() + U0.size(), U0.begin());
    }
}


void Foam::meshless::couplings::ulphPd::storeStepAccelerations
(
    const scalar dt
)
{
    forAll(solidBodies_, k)
    {
        const particleField& U = solidBodies_[k]->particles().field("U");
        const std::vector<double>& U0 = U0_[k];
        double* a = stepAcceleration_[k]->data();
        for (size_t c = 0; c < U0.size(); ++c)
        {
            a[c] = (U.data()[c] - U0[c])/dt;
        }
    }
}


void Foam::meshless::couplings::ulphPd::advance
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    // Fluid over [t, t + dt] against the solids at t
    updateGhosts();
    fluidBody_->advance(t, dt, costs);

    // Solids over the same interval, with the fluid's force of the
    // corrector (the one that moved the fluid)
    forAll(solidBodies_, k)
    {
        particleField& fExt = solidBodies_[k]->model().solid()->externalForce();
        const double* R = reaction(k);
        std::copy(R, R + fExt.size()*fExt.nComponents(), fExt.data());
    }
    const label nSub = solidSteps(solidBodies_, dt, subSteps_);

    storeStepStartVelocities();
    stepSolids(solidBodies_, t, dt, nSub, costs);
    storeStepAccelerations(dt);
    writeForces(t + dt, nSub, solidBodies_, *fluid_, boundaries_);
}


void Foam::meshless::couplings::ulphPd::describe(Ostream& os) const
{
    describeBodies(os);
    os  << ", solid particles as the fluid's ghosts, reaction of eq. 58 on"
        << " the solids, minSubSteps " << subSteps_.minSubSteps() << nl;
}


// ************************************************************************* //
