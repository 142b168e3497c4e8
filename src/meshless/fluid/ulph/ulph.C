/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ulph.H"
#include "dispatchDim.H"
#include "ulphEquations.H"
#include "particleScene.H"
#include "effect.H"
#include "viscosity.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include <algorithm>
#include <cmath>

namespace Foam
{
namespace meshless
{
namespace bodyModels
{
    defineTypeNameAndDebug(ulph, 0);
    addToRunTimeSelectionTable(bodyModel, ulph, dictionary);
    addModelRole(ulph, fluid);
}
}
}


Foam::meshless::bodyModels::ulph::ulph
(
    particleBody& body,
    const dictionary& dict
)
:
    fluidModel(body, dict),
    c0_(readPositive(dict, "soundSpeed")),
    gamma_(readPositiveOrDefault(dict, "gamma", 7)),
    Minv_(body.particles().addScratchField("Minv", particleField::kind::tensor)),
    S_(body.particles().addScratchField("S", particleField::kind::tensor)),
    drho_(body.particles().addScratchField("drho", particleField::kind::scalar)),
    dU_(body.particles().addScratchField("dU", particleField::kind::vector)),
    x0_(body.particles().addScratchField("x0", particleField::kind::vector)),
    U0_(body.particles().addScratchField("U0", particleField::kind::vector)),
    rhoOld_(body.particles().addScratchField("rhoOld", particleField::kind::scalar)),
    tau_(nullptr),
    mu_(0),
    viscosityEffect_(nullptr),
    degenerate_(body.particles().size(), 0),
    nDegenerate_(0),
    maxDegenerate_(0),
    floorRatio_(dict.getOrDefault<scalar>("shapeTensorFloor", 0.1)),
    lambdaFloor_(0),
    geometryCurrent_(false)
{
    if (floorRatio_ < 0 || floorRatio_ >= 1)
    {
        FatalIOErrorInFunction(dict)
            << "shapeTensorFloor " << floorRatio_ << ": expected a fraction"
            << " of the full support's eigenvalue, 0 <= value < 1 (0: off)"
            << exit(FatalIOError);
    }
}


Foam::scalar Foam::meshless::bodyModels::ulph::pressureOf
(
    const scalar rho
) const
{
    return ulphEquations::taitPressure(rho, rho0_, c0_, gamma_);
}


Foam::scalar Foam::meshless::bodyModels::ulph::densityOf
(
    const scalar p
) const
{
    return ulphEquations::taitDensity(p, rho0_, c0_, gamma_);
}


void Foam::meshless::bodyModels::ulph::connectModel(particleScene& scene)
{
    if (const auto* visc = findEffect<effects::viscosity>(body_))
    {
        mu_ = visc->mu();
        viscosityEffect_ = visc;
        tau_ = &body_.particles().addScratchField
        (
            "tau",
            particleField::kind::tensor
        );
    }
    const smoothingKernel& W = body_.kernel();
    lambdaFloor_ = floorRatio_*dispatchDim(body_.dim(), [&](auto d)
    {
        return correctionMatrix::fullSupportEigenvalue<d>(W, body_.spacing());
    });
}


void Foam::meshless::bodyModels::ulph::setSources()
{
    const size_t nSrc = ctx_.sources.size();
    Ssrc_.resize(nSrc);
    Ucont_.resize(nSrc);
    slipNormal_.assign(nSrc, nullptr);
    Ssrc_[0] = S_.data();
    Ucont_[0] = U_.data();
    for (size_t k = 0; k < boundaries_.size(); ++k)
    {
        const ghostBoundary& g = *boundaries_[k].ghosts;
        Ssrc_[k + 1] = g.S();
        // Continuity sees the ghosts' own velocity; next to a free-slip
        // wall only its normal part (slipNormal_)
        Ucont_[k + 1] = g.U();
        slipNormal_[k + 1] = g.slipNormals();
    }
    ctx_.Minv = Minv_.data();
}


template<int Dim>
void Foam::meshless::bodyModels::ulph::ghostForces()
{
    const label n = body_.particles().size();
    for (size_t k = 0; k < boundaries_.size(); ++k)
    {
        boundary& b = boundaries_[k];
        double* R = b.ghosts->reaction();
        if (!R) continue;
        ghostForce_.resize(size_t(n)*Dim);
        ulphEquations::ghostForceOnFluid<Dim>
        (
            n, V_.data(), S_.data(), ctx_.sources[k + 1], Ssrc_[k + 1],
            ghostForce_.data()
        );
        const vectorD<Dim> f = sumInOrder<Dim>
        (
            ghostForce_.data(), body_.particles().nOwned()
        );
        b.forceOnFluid = Zero;
        for (int d = 0; d < Dim; ++d) b.forceOnFluid[d] = f(d);
        ulphEquations::reactionOnGhosts<Dim>
        (
            *b.fromGhosts, b.ghosts->V(), Ssrc_[k + 1], V_.data(), S_.data(),
            R
        );
    }
}


template<int Dim>
void Foam::meshless::bodyModels::ulph::evaluate
(
    const scalar t,
    costAccounting& costs
)
{
    particleSet& set = body_.particles();
    const label n = set.size();

    double* rho = rho_.data();
    double* p = p_.data();
    double* V = V_.data();
    const double* m = mass_.data();

    moveBoundaries(t);
    if (!geometryCurrent_) updateGeometry();
    geometryCurrent_ = false;

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        V[i] = m[i]/rho[i];
        p[i] = ulphEquations::taitPressure(rho[i], rho0_, c0_, gamma_);
    }

    interpolateBoundaries();
    setSources();

    ulphOperators::shapeTensorInverse<Dim>
    (
        n, ctx_.sources, Minv_.data(), lambdaFloor_, degenerate_.data()
    );
    // Counted over the own particles (and every processor's)
    nDegenerate_ = 0;
    for (label i = 0; i < set.nOwned(); ++i) nDegenerate_ += degenerate_[i];
    if (Pstream::parRun()) reduce(nDegenerate_, sumOp<label>());
    if (nDegenerate_ > maxDegenerate_)
    {
        maxDegenerate_ = nDegenerate_;
        Info<< "    ulph " << body_.name() << ": " << nDegenerate_
            << " particles with a shape tensor at its floor or singular"
            << " (most so far)" << endl;
    }

    if (tau_)
    {
        costAccounting::scope timer(costs, body_.costPart(*viscosityEffect_));
        ulphEquations::viscousStress<Dim>
        (
            n, U_.data(), Minv_.data(), ctx_.sources, ctx_.Usrc, mu_,
            tau_->data()
        );
    }

    ulphEquations::stressTimesMinv<Dim>
    (
        n, p, tau_ ? tau_->data() : nullptr, Minv_.data(), S_.data()
    );
    ulphEquations::continuity<Dim>
    (
        n, U_.data(), rho, Minv_.data(), ctx_.sources, Ucont_, drho_.data(),
        slipNormal_
    );
    ulphEquations::momentum<Dim>
    (
        n, rho, S_.data(), ctx_.sources, Ssrc_, dU_.data()
    );

    ghostForces<Dim>();

    body_.addEffectAccelerations(t, dU_, costs);
    body_.addPairEffectAccelerations(ctx_, dU_, costs);
}


void Foam::meshless::bodyModels::ulph::evaluateDim
(
    const scalar t,
    costAccounting& costs
)
{
    dispatchDim(body_.dim(), [&](auto d) { evaluate<d>(t, costs); });
}


Foam::scalar Foam::meshless::bodyModels::ulph::maxDeltaT
(
    const scalar maxCo
) const
{
    const scalar h = body_.kernel().h();
    const scalar maxA = dU_.maxMagnitude();
    scalar dt = maxCo*h/(c0_ + U_.maxMagnitude());
    if (maxA > 0)
    {
        dt = min(dt, 0.25*std::sqrt(h/maxA));
    }
    return dt;
}


void Foam::meshless::bodyModels::ulph::advance
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    emptied_ = -1;

    // The scene built the relations at the step's start, at the current
    // positions of the fluid and its boundaries (moved to t)
    moveBoundaries(t);
    geometryCurrent_ = true;

    particleSet& set = body_.particles();
    const label n = set.size();
    const label nv = n*body_.dim();
    double* x = set.positions().data();
    double* U = U_.data();
    double* rho = rho_.data();
    const double* dU = dU_.data();
    const double* drho = drho_.data();
    double* x0 = x0_.data();
    double* U0 = U0_.data();
    double* rhoOld = rhoOld_.data();

    std::copy(x, x + nv, x0);
    std::copy(U, U + nv, U0);
    std::copy(rho, rho + n, rhoOld);

    // Predictor (eq. 56, left)
    evaluateDim(t, costs);
    updateDensity(rhoOld, drho, 0.5*dt, rho);
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k)
    {
        U[k] = U0[k] + 0.5*dt*dU[k];
        x[k] = x0[k] + 0.5*dt*U[k];
    }

    // Corrector (eq. 56, right)
    evaluateDim(t + 0.5*dt, costs);
    updateDensity(rhoOld, drho, dt, rho);
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k)
    {
        U[k] = U0[k] + dt*dU[k];
        x[k] = x0[k] + dt*U[k];
    }

    // Boundaries at the end of the step, as written; effects that correct
    // the state see the pairs there
    moveBoundaries(t + dt);
    if (body_.correctsAt(time_->timeIndex())) updateGeometry();
    body_.correctEffects(ctx_, time_->timeIndex(), costs);

    double* p = p_.data();
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        p[i] = ulphEquations::taitPressure(rho[i], rho0_, c0_, gamma_);
    }
    releaseSplash();
}


// ************************************************************************* //
