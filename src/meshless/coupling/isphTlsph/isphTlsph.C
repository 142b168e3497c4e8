/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "isphTlsph.H"
#include "fluidModel.H"
#include "particleBody.H"
#include "solidModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace couplings
{
    defineTypeNameAndDebug(isphTlsph, 0);
    addToRunTimeSelectionTable(fsiCoupling, isphTlsph, dictionary);
}
}
}


Foam::meshless::couplings::isphTlsph::isphTlsph
(
    const dictionary& dict,
    particleScene& scene
)
:
    ulphPd(dict, scene)
{
    if (fluid_->hasInnerSteps() || fluid_->soundSpeed() < GREAT)
    {
        FatalIOErrorInFunction(dict)
            << "coupling isphTlsph: fluid " << fluidBody_->name()
            << " has model " << fluidBody_->dict().get<word>("model")
            << ", a weakly compressible fluid: expected a projection fluid"
            << " (isph), or coupling riemannTlsph (riemannWcsph) or ulphPd"
            << exit(FatalIOError);
    }
    // A free-surface particle does not run into a structure (the fluid's
    // wallContact)
    for (auto& g : ghosts_) g->enableContact();
    if (dict.found("iterations"))
    {
        iterations_.reset
        (
            new interfaceQuasiNewton(dict.subDict("iterations"))
        );
        solidStates_.resize(solidBodies_.size());
        for (const particleBody* sb : solidBodies_)
        {
            if (!sb->model().stateInFields())
            {
                FatalIOErrorInFunction(dict)
                    << "coupling isphTlsph: iterations: solid " << sb->name()
                    << " has model " << sb->dict().get<word>("model")
                    << ", whose state is not all in its fields (it cannot"
                    << " be set back to a step's start): expected a solid"
                    << " such as tlsph, or no 'iterations' (staggered)"
                    << exit(FatalIOError);
            }
        }
    }
}


Foam::meshless::couplings::isphTlsph::~isphTlsph()
{
    if (!iterations_) return;
    Info<< "coupling isphTlsph: " << iterations_->meanIterations()
        << " iterations per step on average, at most "
        << iterations_->mostIterations() << ", "
        << iterations_->unconvergedSteps() << " steps stopped at"
        << " maxIterations " << iterations_->maxIterations() << ", "
        << iterations_->restarts() << " restarts" << endl;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::meshless::couplings::isphTlsph::stepSolidsUnder
(
    const std::vector<double>& x,
    const scalar t,
    const scalar dt,
    const label n,
    costAccounting& costs
)
{
    size_t offset = 0;
    forAll(solidBodies_, k)
    {
        solidStates_[k].restore();
        solidBodies_[k]->model().restored();
        particleField& fExt = solidBodies_[k]->model().solid()->externalForce();
        const size_t m = size_t(fExt.size())*fExt.nComponents();
        std::copy(x.begin() + offset, x.begin() + offset + m, fExt.data());
        offset += m;
    }
    stepSolids(solidBodies_, t, dt, n, costs);
    storeStepAccelerations(dt);
}


void Foam::meshless::couplings::isphTlsph::evaluate
(
    const scalar t,
    const scalar dt,
    const label n,
    costAccounting& costs,
    const bool restore
)
{
    stepSolidsUnder(x_, t, dt, n, costs);
    if (restore) fluidState_.restore();
    fluidBody_->model().restored();
    updateGhosts();
    fluidBody_->advance(t, dt, costs);
    gatherReactions(xt_);
}


void Foam::meshless::couplings::isphTlsph::gatherReactions
(
    std::vector<double>& x
)
{
    size_t offset = 0;
    forAll(solidBodies_, k)
    {
        const label m =
            solidBodies_[k]->particles().size()*solidBodies_[k]->dim();
        const double* R = reaction(k);
        std::copy(R, R + m, x.begin() + offset);
        offset += m;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::couplings::isphTlsph::advance
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    if (!iterations_)
    {
        ulphPd::advance(t, dt, costs);
        return;
    }

    // The state at t, and x^0: the fluid's force of the last step
    fluidState_.save(fluidBody_->particles());
    fluidBody_->model().stateSaved();
    size_t nx = 0;
    forAll(solidBodies_, k)
    {
        // The fluid's fields on the solid (its pressure, the reaction) are
        // not the solid's state
        particleBody& sb = *solidBodies_[k];
        solidStates_[k].save(sb.particles(), ghosts_[k]->ownFields());
        sb.model().stateSaved();
        nx += size_t(sb.particles().size())*sb.dim();
    }
    storeStepStartVelocities();
    x_.resize(nx);
    xt_.resize(nx);
    {
        size_t offset = 0;
        for (particleBody* sbp : solidBodies_)
        {
            const particleField& fExt = sbp->model().solid()->externalForce();
            const size_t m = size_t(fExt.size())*fExt.nComponents();
            std::copy(fExt.data(), fExt.data() + m, x_.begin() + offset);
            offset += m;
        }
    }
    const label nSub = solidSteps(solidBodies_, dt, subSteps_);

    // x~ = H(x^k): the solids under x^k, the fluid against them at t + dt
    iterations_->beginStep();
    for (label k = 0; ; ++k)
    {
        evaluate(t, dt, nSub, costs, k > 0);
        const bool done = iterations_->update(x_, xt_, k);
        if (debug)
        {
            Info<< "      coupling isphTlsph: iteration " << k + 1
                << ", residual " << iterations_->residual() << endl;
        }
        if (done) break;
    }
    // (leastIterate keeps residual(): the last iterate's)
    const bool converged =
        iterations_->residual() <= iterations_->tolerance();
    const bool least = !converged && iterations_->leastIterate(x_);
    if (least)
    {
        // Not converged: the step ends at its least iterate, not its last
        evaluate(t, dt, nSub, costs);
    }
    iterations_->endStep();
    Info<< "    coupling isphTlsph: " << iterations_->iterations()
        << " iterations, residual " << iterations_->residual();
    if (!converged)
    {
        Info<< ", not converged (maxIterations "
            << iterations_->maxIterations() << ")";
        if (least)
        {
            Info<< ", ended at iteration " << iterations_->leastIteration()
                << " (residual " << iterations_->leastResidual() << ")";
        }
    }
    Info<< endl;

    // The solids take the force the fluid felt: momentum balances to
    // round-off, the solids' motion differs from the one the fluid saw by
    // the iteration's residual
    stepSolidsUnder(xt_, t, dt, nSub, costs);
    writeForces(t + dt, nSub, solidBodies_, *fluid_, boundaries_);
}


void Foam::meshless::couplings::isphTlsph::describe(Ostream& os) const
{
    describeBodies(os);
    os  << ", solid particles in the fluid's Poisson equation and"
        << " projection, the pressure's exchange pair by pair, minSubSteps "
        << subSteps_.minSubSteps() << nl;
}


// ************************************************************************* //
