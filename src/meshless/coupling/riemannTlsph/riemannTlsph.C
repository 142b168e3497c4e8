/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "riemannTlsph.H"
#include "particleScene.H"
#include "fluidModel.H"
#include "solidModel.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace couplings
{
    defineTypeNameAndDebug(riemannTlsph, 0);
    addToRunTimeSelectionTable(fsiCoupling, riemannTlsph, dictionary);
}
}
}


Foam::meshless::couplings::riemannTlsph::riemannTlsph
(
    const dictionary& dict,
    particleScene& scene
)
:
    ghostCoupling(dict, scene),
    wallAcceleration_
    (
        readEnumOrDefault
        (
            dict, "solidAcceleration",
            Enum<bool>({{false, "none"}, {true, "average"}}), false
        )
    ),
    coarseSummation_
    (
        readEnumOrDefault
        (
            dict, "densitySummation",
            Enum<bool>({{true, "cells"}, {false, "particles"}}), true
        )
    ),
    subSteps_
    (
        "coupling riemannTlsph",
        dict.found("minSubSteps") ? readPositiveLabel(dict, "minSubSteps") : 1,
        "solid steps per acoustic step"
    ),
    stepMost_(0),
    costs_(nullptr)
{
    if (!fluid_->hasInnerSteps())
    {
        FatalIOErrorInFunction(dict)
            << "coupling riemannTlsph: fluid " << fluidBody_->name()
            << " has model " << fluidBody_->dict().get<word>("model")
            << ", which takes no acoustic steps: expected a weakly"
            << " compressible fluid with them (riemannWcsph), or coupling"
            << " ulphPd, or isphTlsph for a projection fluid (isph)"
            << exit(FatalIOError);
    }
    for (particleBody* sb : solidBodies_)
    {
        particleSet& set = sb->particles();
        const bool fresh = !set.found("averageVelocity");
        averageU_.push_back
        (
            &set.addField("averageVelocity", particleField::kind::vector)
        );
        averageA_.push_back
        (
            &set.addField("averageAcceleration", particleField::kind::vector)
        );
        if (fresh)
        {
            // At rest or moving as seeded: the solid's own velocity
            const particleField& U = set.field("U");
            std::copy
            (
                U.data(), U.data() + U.size()*U.nComponents(),
                averageU_.back()->data()
            );
        }
        const label nv = set.size()*sb->dim();
        x0_.emplace_back(nv);
        U0_.emplace_back(nv);
        deformingGhost& g = addGhosts
        (
            *sb, wallAcceleration_ ? "averageAcceleration" : "",
            "averageVelocity"
        );
        if (coarseSummation_ && sb->spacing() < 0.999*fluidBody_->spacing())
        {
            g.coarseGrain(fluidBody_->spacing());
        }
    }
    fluid_->setInnerStep
    (
        [this](const scalar t, const scalar dt) { acousticStep(t, dt); }
    );
}


void Foam::meshless::couplings::riemannTlsph::acousticStep
(
    const scalar t,
    const scalar dt
)
{
    // The force of this acoustic step: the reaction of the fluid's pairs
    forAll(solidBodies_, k)
    {
        particleField& fExt = solidBodies_[k]->model().solid()->externalForce();
        const double* R = reaction(k);
        std::copy(R, R + fExt.size()*fExt.nComponents(), fExt.data());
        const particleSet& set = solidBodies_[k]->particles();
        const double* x = set.positions().data();
        const double* U = set.field("U").data();
        std::copy(x, x + x0_[k].size(), x0_[k].begin());
        std::copy(U, U + U0_[k].size(), U0_[k].begin());
    }

    const label nSub = solidSteps(solidBodies_, dt, subSteps_);
    stepMost_ = max(stepMost_, nSub);
    stepSolids(solidBodies_, t, dt, nSub, *costs_);

    // The wall the fluid sees next: the solid's motion over the step
    forAll(solidBodies_, k)
    {
        const particleSet& set = solidBodies_[k]->particles();
        const double* x = set.positions().data();
        const double* U = set.field("U").data();
        double* Ua = averageU_[k]->data();
        double* aa = averageA_[k]->data();
        const std::vector<double>& x0 = x0_[k];
        const std::vector<double>& U0 = U0_[k];
        for (size_t c = 0; c < x0.size(); ++c)
        {
            Ua[c] = (x[c] - x0[c])/dt;
            aa[c] = (U[c] - U0[c])/dt;
        }
    }
}


void Foam::meshless::couplings::riemannTlsph::advance
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    costs_ = &costs;
    stepMost_ = 0;
    fluidBody_->advance(t, dt, costs);
    costs_ = nullptr;
    writeForces(t + dt, stepMost_, solidBodies_, *fluid_, boundaries_);
}


void Foam::meshless::couplings::riemannTlsph::describe(Ostream& os) const
{
    describeBodies(os);
    os  << ", solid particles as the fluid's dummy particles with the"
        << " velocity and acceleration of the acoustic step, the reaction"
        << " of the fluid's pair forces on the solids, solid steps between"
        << " the halves of each acoustic step, minSubSteps "
        << subSteps_.minSubSteps() << ", densitySummation "
        << (coarseSummation_ ? "cells" : "particles") << nl;
}


// ************************************************************************* //
