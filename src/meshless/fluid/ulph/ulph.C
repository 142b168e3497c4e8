/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ulph.H"
#include "ulphEquations.H"
#include "ghostWall.H"
#include "ghostBoundary.H"
#include "particleScene.H"
#include "effect.H"
#include "gravity.H"
#include "viscosity.H"
#include "dictionaryChecks.H"
#include "StringStream.H"
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
}
}
}

const Foam::Enum<Foam::meshless::bodyModels::ulph::initialStateType>
Foam::meshless::bodyModels::ulph::initialStateNames
({
    { initialStateType::rest, "rest" },
    { initialStateType::hydrostatic, "hydrostatic" },
});


Foam::meshless::bodyModels::ulph::ulph
(
    particleBody& body,
    const dictionary& dict
)
:
    bodyModel(body, dict),
    rho0_(body.density()),
    c0_(readPositive(dict, "soundSpeed")),
    gamma_(readPositiveOrDefault(dict, "gamma", 7)),
    skin_(readPositiveOrDefault(dict, "neighbourSkin", 0.1)),
    initialState_
    (
        initialStateNames.getOrDefault("initialState", dict, initialStateType::rest)
    ),
    freshStart_(!body.particles().found("p")),
    wallNames_(dict.getOrDefault<wordList>("walls", wordList())),
    U_(body.particles().addField("U", particleField::kind::vector)),
    rho_(body.particles().addField("rho", particleField::kind::scalar)),
    p_(body.particles().addField("p", particleField::kind::scalar)),
    mass_(body.requireField("mass", "model ulph")),
    V0_(body.requireField("volume", "model ulph")),
    V_(body.particles().addScratchField("Vcurrent", particleField::kind::scalar)),
    Minv_(body.particles().addScratchField("Minv", particleField::kind::tensor)),
    S_(body.particles().addScratchField("S", particleField::kind::tensor)),
    drho_(body.particles().addScratchField("drho", particleField::kind::scalar)),
    dU_(body.particles().addScratchField("dU", particleField::kind::vector)),
    x0_(body.particles().addScratchField("x0", particleField::kind::vector)),
    U0_(body.particles().addScratchField("U0", particleField::kind::vector)),
    rhoOld_(body.particles().addScratchField("rhoOld", particleField::kind::scalar)),
    tau_(nullptr),
    time_(nullptr),
    g_(Zero),
    mu_(0),
    viscosityEffect_(nullptr),
    neighbourCost_(-1),
    nDegenerate_(0),
    maxDegenerate_(0),
    floorRatio_(dict.getOrDefault<scalar>("shapeTensorFloor", 0.1)),
    lambdaFloor_(0),
    rhoMin_(0),
    emptied_(-1),
    emptiedRho_(0)
{
    if (dict.found("minPressure"))
    {
        // The Tait pressure is bounded below by -B (B = rho0 c0^2/gamma)
        const scalar B = rho0_*c0_*c0_/gamma_;
        const scalar pMin = dict.get<scalar>("minPressure");
        if (pMin <= -B)
        {
            FatalIOErrorInFunction(dict)
                << "minPressure " << pMin << ": expected a pressure above"
                << " -rho0 c0^2/gamma = " << -B << " Pa" << exit(FatalIOError);
        }
        rhoMin_ = ulphEquations::taitDensity(pMin, rho0_, c0_, gamma_);
    }
    if (floorRatio_ < 0 || floorRatio_ >= 1)
    {
        FatalIOErrorInFunction(dict)
            << "shapeTensorFloor " << floorRatio_ << ": expected a fraction"
            << " of the full support's eigenvalue, 0 <= value < 1 (0: off)"
            << exit(FatalIOError);
    }
    body.kernel();      // required: FatalIOError naming the body if absent

    // A cloud seeded without density starts at the reference density
    bool anyRho = false;
    for (label i = 0; i < rho_.size(); ++i) anyRho = anyRho || rho_(i, 0) != 0;
    if (!anyRho) rho_.fill(rho0_);
}


Foam::meshless::bodyModels::ulph::~ulph()
{}


void Foam::meshless::bodyModels::ulph::connect(particleScene& scene)
{
    time_ = &scene.time();
    neighbourCost_ = scene.costs().part(body_.name() + ": neighbour search");

    if (const auto* grav = findEffect<effects::gravity>(body_))
    {
        g_ = grav->value();
    }
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
    const label dim = body_.dim();
    for (const word& name : wallNames_)
    {
        particleBody& wb = scene.body(name, dict_);
        ghostWall* wall = dynamic_cast<ghostWall*>(&wb.model());
        if (!wall)
        {
            FatalIOErrorInFunction(dict_)
                << "Body '" << name << "' in 'walls' has model "
                << wb.dict().get<word>("model") << ": expected ghostWall"
                << exit(FatalIOError);
        }
        attach(*wall);
    }
    cells_.reset(new cellLinkedList(dim, W.radius()*(1 + skin_)));
    lambdaFloor_ = floorRatio_*
    (
        dim == 3
      ? ulphOperators::fullSupportEigenvalue<3>(W, body_.spacing())
      : ulphOperators::fullSupportEigenvalue<2>(W, body_.spacing())
    );

    // Sound speed against eq. 7 for the column the fluid starts as
    const scalar gMag = mag(g_);
    if (gMag > 0)
    {
        scalar lo, hi;
        heightRange(lo, hi);
        const scalar H = hi - lo + body_.spacing();
        const scalar c0min = 10*std::sqrt(2*gMag*H);
        if (c0_ < c0min)
        {
            WarningInFunction
                << "Body " << body_.name() << ": soundSpeed " << c0_
                << " is below 10 sqrt(2 g H) = " << c0min
                << " for its height H = " << H
                << " (eq. 7): density variations may exceed 1 %" << endl;
        }
    }

    if (initialState_ == initialStateType::hydrostatic && freshStart_)
    {
        if (gMag == 0)
        {
            FatalIOErrorInFunction(dict_)
                << "initialState hydrostatic needs a gravity effect"
                << exit(FatalIOError);
        }
        hydrostaticStart();
    }
    for (label i = 0; i < rho_.size(); ++i)
    {
        p_(i, 0) = ulphEquations::taitPressure(rho_(i, 0), rho0_, c0_, gamma_);
    }
}


Foam::scalar Foam::meshless::bodyModels::ulph::height(const label i) const
{
    const vector up = -g_/mag(g_);
    const particleField& x = body_.particles().positions();
    scalar s = 0;
    for (label d = 0; d < body_.dim(); ++d) s += up[d]*x(i, d);
    return s;
}


void Foam::meshless::bodyModels::ulph::heightRange(scalar& lo, scalar& hi) const
{
    lo = GREAT;
    hi = -GREAT;
    for (label i = 0; i < body_.particles().size(); ++i)
    {
        lo = min(lo, height(i));
        hi = max(hi, height(i));
    }
}


void Foam::meshless::bodyModels::ulph::hydrostaticStart()
{
    scalar lo, top;
    heightRange(lo, top);
    top += 0.5*body_.spacing();
    const particleField& x = body_.particles().positions();

    for (label i = 0; i < x.size(); ++i)
    {
        const scalar p = rho0_*mag(g_)*(top - height(i));
        rho_(i, 0) = ulphEquations::taitDensity(p, rho0_, c0_, gamma_);
        mass_(i, 0) = rho_(i, 0)*V0_(i, 0);
    }
}


void Foam::meshless::bodyModels::ulph::attach(ghostBoundary& ghosts)
{
    const smoothingKernel& W = body_.kernel();
    particleBody& gb = ghosts.ghostBody();
    if (gb.dim() != body_.dim())
    {
        FatalIOErrorInFunction(dict_)
            << "Ghost body '" << gb.name() << "' is " << gb.dim()
            << "D, the fluid " << body_.name() << " " << body_.dim() << "D"
            << exit(FatalIOError);
    }
    ghosts.prepare(W);
    walls_.push_back(&ghosts);
    wallBodies_.push_back(&gb);
    ghostForce_.push_back(Zero);

    // Fixed ghosts: their cell lists are built once
    wallCells_.emplace_back
    (
        new cellLinkedList(body_.dim(), W.radius()*(1 + skin_))
    );
    wallCells_.back()->build
    (
        gb.particles().positions().data(),
        gb.particles().size()
    );
    toWall_.emplace_back(new neighbourList());
    fromWall_.emplace_back(new neighbourList());
}


void Foam::meshless::bodyModels::ulph::addGhosts(ghostBoundary& ghosts)
{
    attach(ghosts);
}


Foam::vector Foam::meshless::bodyModels::ulph::ghostForceOnFluid
(
    const ghostBoundary& ghosts
) const
{
    for (size_t k = 0; k < walls_.size(); ++k)
    {
        if (walls_[k] == &ghosts) return ghostForce_[k];
    }
    FatalErrorInFunction
        << "Fluid " << body_.name() << " has no such ghost set"
        << exit(FatalError);
    return Zero;
}


template<int Dim>
void Foam::meshless::bodyModels::ulph::ghostForces()
{
    const double* x = body_.particles().positions().data();
    for (size_t k = 0; k < walls_.size(); ++k)
    {
        double* R = walls_[k]->reaction();
        if (!R) continue;
        const particleSet& gs = wallBodies_[k]->particles();
        ghostForce_[k] = ulphEquations::ghostForceOnFluid<Dim>
        (
            ctx_.n, x, V_.data(), S_.data(), ctx_.sources[k + 1],
            Ssrc_[k + 1], body_.kernel()
        );
        ulphEquations::reactionOnGhosts<Dim>
        (
            gs.size(), gs.positions().data(), walls_[k]->V(), Ssrc_[k + 1],
            *fromWall_[k], x, V_.data(), S_.data(), body_.kernel(), R
        );
    }
}


void Foam::meshless::bodyModels::ulph::buildNeighbours()
{
    const particleSet& set = body_.particles();
    const double* x = set.positions().data();
    cells_->build(x, set.size());
    own_.build(*cells_, x, set.size(), true);
    for (size_t k = 0; k < walls_.size(); ++k)
    {
        const particleSet& ws = wallBodies_[k]->particles();
        if (walls_[k]->moving())
        {
            wallCells_[k]->build(ws.positions().data(), ws.size());
        }
        toWall_[k]->build(*wallCells_[k], x, set.size(), false);
        fromWall_[k]->build
        (
            *cells_,
            ws.positions().data(),
            ws.size(),
            false
        );
    }
}


void Foam::meshless::bodyModels::ulph::setContext()
{
    const particleSet& set = body_.particles();
    ctx_.dim = body_.dim();
    ctx_.W = &body_.kernel();
    ctx_.n = set.size();
    ctx_.x = set.positions().data();
    ctx_.U = U_.data();
    ctx_.rho = rho_.data();
    ctx_.mass = mass_.data();
    ctx_.Minv = Minv_.data();
    ctx_.rho0 = rho0_;
    ctx_.c0 = c0_;

    const size_t nSrc = 1 + walls_.size();
    ctx_.sources.resize(nSrc);
    ctx_.Usrc.resize(nSrc);
    ctx_.massSrc.resize(nSrc);
    Ssrc_.resize(nSrc);
    Ucont_.resize(nSrc);
    slipNormal_.assign(nSrc, nullptr);
    ctx_.wallSource.assign(nSrc, false);

    ctx_.sources[0] = {&own_, ctx_.x, V_.data()};
    ctx_.Usrc[0] = U_.data();
    ctx_.massSrc[0] = mass_.data();
    Ssrc_[0] = S_.data();
    Ucont_[0] = U_.data();
    for (size_t k = 0; k < walls_.size(); ++k)
    {
        const particleSet& ws = wallBodies_[k]->particles();
        ctx_.sources[k + 1] =
            {toWall_[k].get(), ws.positions().data(), walls_[k]->V()};
        ctx_.Usrc[k + 1] = walls_[k]->Uvisc();
        ctx_.massSrc[k + 1] = walls_[k]->mass();
        Ssrc_[k + 1] = walls_[k]->S();
        // Continuity sees the ghosts' own velocity; next to a free-slip
        // wall only its normal part (slipNormal_)
        Ucont_[k + 1] = walls_[k]->U();
        slipNormal_[k + 1] = walls_[k]->slipNormals();
        // A wall of the fluid's 'walls', not a coupled body's ghosts
        ctx_.wallSource[k + 1] =
            dynamic_cast<const ghostWall*>(walls_[k]) != nullptr;
    }
}


template<int Dim>
void Foam::meshless::bodyModels::ulph::cachePairKernels()
{
    const smoothingKernel& W = body_.kernel();
    const double* x = ctx_.x;
    pairW_.resize(ctx_.sources.size());

    for (size_t k = 0; k < ctx_.sources.size(); ++k)
    {
        neighbourSource& s = ctx_.sources[k];
        std::vector<double>& w = pairW_[k];
        w.resize(s.list->nPairs());
        const label* idx = s.list->indexData();

        #pragma omp parallel for schedule(static)
        for (label i = 0; i < ctx_.n; ++i)
        {
            for (label q = s.list->offset(i); q < s.list->offset(i + 1); ++q)
            {
                const double r2 = distanceSqr<Dim>
                (
                    s.x + size_t(idx[q])*Dim,
                    x + size_t(i)*Dim
                );
                w[q] = W.W(std::sqrt(r2));
            }
        }
        s.w = w.data();
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
    const double* x = set.positions().data();
    const smoothingKernel& W = body_.kernel();

    double* rho = rho_.data();
    double* p = p_.data();
    double* V = V_.data();
    const double* m = mass_.data();

    for (ghostBoundary* wall : walls_) wall->moveTo(t);

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        V[i] = m[i]/rho[i];
        p[i] = ulphEquations::taitPressure(rho[i], rho0_, c0_, gamma_);
    }

    for (size_t k = 0; k < walls_.size(); ++k)
    {
        walls_[k]->interpolate
        (
            *fromWall_[k], x, p, rho, U_.data(), V, W, g_, c0_, rho0_
        );
    }

    setContext();
    cachePairKernels<Dim>();

    nDegenerate_ = ulphOperators::shapeTensorInverse<Dim>
    (
        x, n, ctx_.sources, W, Minv_, lambdaFloor_
    );
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
            n, x, U_.data(), Minv_.data(), ctx_.sources, ctx_.Usrc, W, mu_,
            tau_->data()
        );
    }

    ulphEquations::stressTimesMinv<Dim>
    (
        n, p, tau_ ? tau_->data() : nullptr, Minv_.data(), S_.data()
    );
    ulphEquations::continuity<Dim>
    (
        n, x, U_.data(), rho, Minv_.data(), ctx_.sources, Ucont_, W,
        drho_.data(), slipNormal_
    );
    ulphEquations::momentum<Dim>
    (
        n, x, rho, S_.data(), ctx_.sources, Ssrc_, W, dU_.data()
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
    if (body_.dim() == 2) evaluate<2>(t, costs);
    else evaluate<3>(t, costs);
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


void Foam::meshless::bodyModels::ulph::updateDensity
(
    const double* rho0,
    const double* drho,
    const scalar dt,
    double* rho
)
{
    // A million-fold expansion is as much a blow-up as a zero density
    // (V = m/rho would overflow); a NaN passes to the scene's check of
    // non-finite fields
    const label n = rho_.size();
    const double floor = 1e-6*rho0_;
    label bad = -1;
    #pragma omp parallel for schedule(static) reduction(max:bad)
    for (label i = 0; i < n; ++i)
    {
        const double r = std::max(rho0[i] + dt*drho[i], rhoMin_);
        if (!(r <= floor))
        {
            rho[i] = r;
        }
        else
        {
            rho[i] = rho0[i];
            bad = std::max(bad, i);
        }
    }
    if (bad >= 0 && emptied_ < 0)
    {
        emptied_ = bad;
        emptiedRho_ = rho0[bad] + dt*drho[bad];
    }
}


Foam::string Foam::meshless::bodyModels::ulph::blowUp() const
{
    if (emptied_ < 0) return string::null;

    const particleSet& set = body_.particles();
    const particleField& x = set.positions();
    OStringStream os;
    os  << "particle id " << set.ids()[emptied_] << " at (";
    for (label d = 0; d < body_.dim(); ++d)
    {
        os  << (d ? " " : "") << x(emptied_, d);
    }
    os  << ") would have density " << emptiedRho_ << " kg/m^3 (continuity,"
        << " eq. 16): its neighbours move apart faster than the step"
        << " follows, as when a particle is thrown out with too few"
        << " neighbours." << nl
        << "    Likely causes: a time step above the stable one (lower"
        << " deltaT or maxCo), too little artificial viscosity; a"
        << " 'minPressure' bounds the density from below.";
    return os.str();
}


void Foam::meshless::bodyModels::ulph::advance
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    emptied_ = -1;

    for (ghostBoundary* wall : walls_) wall->moveTo(t);
    {
        costAccounting::scope timer(costs, neighbourCost_);
        buildNeighbours();
    }

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
    double* rho0 = rhoOld_.data();

    std::copy(x, x + nv, x0);
    std::copy(U, U + nv, U0);
    std::copy(rho, rho + n, rho0);

    // Predictor (eq. 56, left)
    evaluateDim(t, costs);
    updateDensity(rho0, drho, 0.5*dt, rho);
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k)
    {
        U[k] = U0[k] + 0.5*dt*dU[k];
        x[k] = x0[k] + 0.5*dt*U[k];
    }

    // Corrector (eq. 56, right)
    evaluateDim(t + 0.5*dt, costs);
    updateDensity(rho0, drho, dt, rho);
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k)
    {
        U[k] = U0[k] + dt*dU[k];
        x[k] = x0[k] + dt*U[k];
    }

    // Walls at the end of the step, as written
    for (ghostBoundary* wall : walls_) wall->moveTo(t + dt);

    setContext();
    body_.correctEffects(ctx_, time_->timeIndex(), costs);

    double* p = p_.data();
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        p[i] = ulphEquations::taitPressure(rho[i], rho0_, c0_, gamma_);
    }
}
