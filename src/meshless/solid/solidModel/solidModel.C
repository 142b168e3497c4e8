/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "solidModel.H"
#include "particleDistribution.H"
#include "solidWallContact.H"
#include "ghostBoundary.H"
#include "dispatchDim.H"
#include "particleScene.H"
#include "particleExpression.H"
#include "smallTensor.H"
#include "dictionaryChecks.H"
#include <cmath>

const Foam::Enum<Foam::meshless::solidModel::integratorType>
Foam::meshless::solidModel::integratorNames
({
    { integratorType::verlet, "verlet" },
    { integratorType::rk4, "rk4" },
    { integratorType::implicit, "implicit" },
});


Foam::meshless::solidModel::solidModel
(
    particleBody& body,
    const dictionary& dict
)
:
    bodyModel(body, dict),
    restart_(body.particles().found("X0")),
    accRead_(restart_ && body.particles().found("acceleration")),
    U_(body.particles().addField("U", particleField::kind::vector)),
    X0_(body.particles().addField("X0", particleField::kind::vector)),
    displacement_
    (
        body.particles().addField("displacement", particleField::kind::vector)
    ),
    // Written: the first half kick after a restart needs the last force
    fExt_
    (
        body.particles().addField("externalForce", particleField::kind::vector)
    ),
    mass_(body.requireField("mass", "a solid model")),
    V0_(body.requireField("volume", "a solid model")),
    acc_
    (
        body.particles().addField("acceleration", particleField::kind::vector)
    ),
    law_(constitutiveLaw::New(dict, body.dim(), body.particles())),
    integrator_
    (
        integratorNames.getOrDefault("integrator", dict, integratorType::verlet)
    ),
    subSteps_
    (
        body.name(),
        dict.found("minSubSteps") ? readPositiveLabel(dict, "minSubSteps") : 1
    ),
    maxCo_(0.3),
    accValid_(false),
    accValidSaved_(false),
    xn_(nullptr),
    Un_(nullptr),
    sumX_(nullptr),
    sumU_(nullptr),
    beta_(0.25),
    gamma_(0.5),
    alphaM_(0),
    alphaF_(0),
    newtonTol_(1e-8),
    newtonMaxIter_(20),
    jacobian_(),
    an_(nullptr),
    aNewmark_(nullptr),
    newtonIters_(0),
    newtonResidual_(0),
    failure_(),
    N0_(nullptr),
    normals_(nullptr)
{
    particleSet& set = body.particles();

    // The dynamics take the cloud's masses, the stable step and the wave
    // speed the body's density: they must agree
    const scalar rho = body.density();
    for (label i = 0; i < set.size(); ++i)
    {
        const scalar seeded = mass_(i, 0)/V0_(i, 0);
        if (!(mag(seeded - rho) <= 1e-6*rho))
        {
            FatalIOErrorInFunction(dict)
                << "Body '" << body.name() << "': density " << rho
                << " but its particle id " << set.ids()[i] << " has mass/"
                << "volume " << seeded << " in the cloud: expected the"
                << " density the body was seeded with (seedParticlesDict)"
                << exit(FatalIOError);
        }
    }

    if (integrator_ == integratorType::rk4)
    {
        xn_ = &set.addScratchField("xn", particleField::kind::vector);
        Un_ = &set.addScratchField("Un", particleField::kind::vector);
        sumX_ = &set.addScratchField("sumX", particleField::kind::vector);
        sumU_ = &set.addScratchField("sumU", particleField::kind::vector);
    }
    if (integrator_ == integratorType::implicit)
    {
        xn_ = &set.addScratchField("xn", particleField::kind::vector);
        Un_ = &set.addScratchField("Un", particleField::kind::vector);
        an_ = &set.addScratchField("an", particleField::kind::vector);
        aNewmark_ =
            &set.addScratchField("aNewmark", particleField::kind::vector);
        // Generalised-alpha (Chung and Hulbert 1993), second order, the
        // highest frequencies damped to rhoInfinity per step (default
        // 0.8); or Newmark's average acceleration (no damping)
        const dictionary d
        (
            dict.found("implicit") ? dict.subDict("implicit") : dictionary()
        );
        const word scheme(d.getOrDefault<word>("scheme", "generalisedAlpha"));
        if (scheme == "generalisedAlpha")
        {
            const scalar rho = d.getOrDefault<scalar>("rhoInfinity", 0.8);
            if (!(rho >= 0 && rho <= 1))
            {
                FatalIOErrorInFunction(dict)
                    << "implicit: rhoInfinity " << rho << ": expected"
                    << " 0 <= rhoInfinity <= 1 (the spectral radius at high"
                    << " frequency)" << exit(FatalIOError);
            }
            alphaM_ = (2*rho - 1)/(rho + 1);
            alphaF_ = rho/(rho + 1);
            gamma_ = 0.5 - alphaM_ + alphaF_;
            beta_ = 0.25*sqr(1 - alphaM_ + alphaF_);
        }
        else if (scheme != "newmark")
        {
            FatalIOErrorInFunction(dict)
                << "implicit: scheme " << scheme << ": expected"
                << " generalisedAlpha (the default) or newmark"
                << exit(FatalIOError);
        }
        newtonTol_ = readPositiveOrDefault(d, "tolerance", 1e-8);
        newtonMaxIter_ =
            d.found("maxIter") ? readPositiveLabel(d, "maxIter") : 20;
        const label nv = set.size()*body.dim();
        newtonR_.assign(nv, 0);
        newtonDx_.assign(nv, 0);
        xNext_.assign(nv, 0);
        perturbA_.assign(nv, 0);
    }

    // A fresh start: the seeded state is the reference configuration
    const label nv = set.size()*body.dim();
    if (!restart_)
    {
        std::copy
        (
            set.positions().data(),
            set.positions().data() + nv,
            X0_.data()
        );
        if (dict.found("initialVelocity"))
        {
            particleExpression::evaluate
            (
                dict.subDict("initialVelocity"),
                X0_,
                U_
            );
        }
    }
    updateDisplacement();
}


void Foam::meshless::solidModel::connect(particleScene& scene)
{
    constraints_.reset
    (
        new solidConstraints
        (
            dict_,
            body_.particles(),
            X0_,
            scene.mesh(),
            &body_.kernel()
        )
    );

    // Contact with walls: the solid's particles among each wall's, within
    // the solid's kernel support grown to reach the face particles of the
    // wall (half the wall's spacing behind the face and along it) from a
    // particle a spacing off the face, and the step's motion (a half)
    contactWalls_.clear();
    for (const word& name : dict_.getOrDefault<wordList>("walls", wordList()))
    {
        particleBody& wb = scene.body(name, dict_);
        ghostBoundary* wall = dynamic_cast<ghostBoundary*>(&wb.model());
        if (!wall || wb.model().role() != modelRole::wall)
        {
            FatalIOErrorInFunction(dict_)
                << "Entry 'walls': body '" << name << "' is not a wall"
                << " (expected a ghostWall body)" << exit(FatalIOError);
        }
        if (!wall->contactNormals() || !wall->contactDepth())
        {
            FatalIOErrorInFunction(dict_)
                << "Entry 'walls': wall '" << name << "' has no normals and"
                << " wall distances (expected a wall seeded as wall layers"
                << " by seedParticles)" << exit(FatalIOError);
        }
        if (wb.dim() != body_.dim())
        {
            FatalIOErrorInFunction(dict_)
                << "Entry 'walls': wall '" << name << "' is " << wb.dim()
                << "D, the solid " << body_.dim() << "D"
                << exit(FatalIOError);
        }
        const smoothingKernel& W = body_.kernel();
        const scalar reach =
            Foam::sqrt
            (
                sqr(0.5*wb.spacing())
              + sqr(body_.spacing() + 0.5*wb.spacing())
            );
        const scalar skin = max(0.5, 1.5*reach/W.radius() - 1);
        contactWalls_.push_back
        (
            contactWall
            {
                wall,
                &scene.relations().contact
                (
                    body_.name() + " to " + name + " (contact)",
                    body_.particles().positions(), wb.particles().positions(),
                    W, skin, true, wall->moving(),
                    neighbourRelation::separation
                ),
                std::vector<double>()
            }
        );
    }
}


void Foam::meshless::solidModel::addWallContact(particleField& acc) const
{
    if (contactWalls_.empty()) return;
    const scalar dx = body_.spacing();
    const scalar c = waveSpeed();
    const particleSet& set = body_.particles();
    const double* x = set.positions().data();

    // A parallel run: every processor holds the whole solid but the walls
    // near its own part; a particle's contact is its owner's (whose part
    // holds all its wall neighbours), the same on every processor
    const bool shared = Pstream::parRun() && set.replicated();
    const size_t nv = size_t(acc.size())*acc.nComponents();
    double* out = acc.data();
    if (shared)
    {
        contactAcc_.assign(nv, 0);
        out = contactAcc_.data();
    }
    for (contactWall& w : contactWalls_)
    {
        const particleBody& wb = w.wall->ghostBody();
        const double* xw = wb.particles().positions().data();
        dispatchDim(body_.dim(), [&](auto d)
        {
            if (w.active.empty())
            {
                // The particles that start against the wall (their
                // reference positions; on a restart they have not moved
                // far from them) take no contact with it
                std::vector<double> gap0;
                solidWallContact::gaps<d>
                (
                    *w.rel, X0_.data(), xw, w.wall->contactNormals(),
                    w.wall->contactDepth(), wb.spacing(), 0.5*dx, gap0
                );
                w.active.resize(gap0.size());
                for (size_t i = 0; i < gap0.size(); ++i)
                {
                    w.active[i] = gap0[i] > 0.25*dx ? 1 : 0;
                }
                // (none before the relation's first build)
                if (shared && label(w.active.size()) == set.size())
                {
                    particleDistribution::share(set, w.active.data(), 1);
                }
            }
            solidWallContact::addAccelerations<d>
            (
                *w.rel, x, xw, w.wall->contactNormals(),
                w.wall->contactDepth(), wb.spacing(), 0.5*dx, c*c/(dx*dx),
                w.active.data(), out
            );
        });
    }
    if (shared)
    {
        particleDistribution::share(set, out, acc.nComponents());
        double* a = acc.data();
        for (size_t k = 0; k < nv; ++k) a[k] += out[k];
    }
}


void Foam::meshless::solidModel::updateDisplacement()
{
    const particleSet& set = body_.particles();
    const label nv = set.size()*body_.dim();
    const double* x = set.positions().data();
    const double* X = X0_.data();
    double* d = displacement_.data();
    for (label k = 0; k < nv; ++k) d[k] = x[k] - X[k];
}


Foam::scalar Foam::meshless::solidModel::stableDeltaT
(
    const scalar maxCo
) const
{
    // Newmark's average acceleration is unconditionally stable: the step
    // is the scene's (the fluid's, or controlDict's deltaT or maxDeltaT)
    if (implicit()) return GREAT;
    return min
    (
        maxCo*body_.kernel().h()/(waveSpeed() + U_.maxMagnitude()),
        viscousDeltaT()
    );
}


Foam::scalar Foam::meshless::solidModel::stepLimit(const scalar maxCo) const
{
    return min(stableDeltaT(maxCo), body_.effectsDeltaT());
}


Foam::scalar Foam::meshless::solidModel::maxDeltaT(const scalar maxCo) const
{
    maxCo_ = maxCo;
    return subSteps_.minSubSteps()*stableDeltaT(maxCo);
}


void Foam::meshless::solidModel::stepRK4
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    particleField& xf = body_.particles().positions();
    const label nv = xf.size()*body_.dim();
    double* x = xf.data();
    double* U = U_.data();
    const double* acc = acc_.data();
    double* xn = xn_->data();
    double* Un = Un_->data();
    double* sx = sumX_->data();
    double* su = sumU_->data();

    std::copy(x, x + nv, xn);
    std::copy(U, U + nv, Un);
    std::fill(sx, sx + nv, 0.0);
    std::fill(su, su + nv, 0.0);

    // Stage s at t + c_s dt from the previous stage's rates
    static const double c[4] = {0, 0.5, 0.5, 1};
    static const double w[4] = {1, 2, 2, 1};

    for (int s = 0; s < 4; ++s)
    {
        if (s > 0)
        {
            #pragma omp parallel for schedule(static)
            for (label k = 0; k < nv; ++k)
            {
                x[k] = xn[k] + c[s]*dt*U[k];
                U[k] = Un[k] + c[s]*dt*acc[k];
            }
        }
        constraints_->prescribe(t + c[s]*dt, X0_, xf, U_);
        evaluate(t + c[s]*dt, false, costs);

        #pragma omp parallel for schedule(static)
        for (label k = 0; k < nv; ++k)
        {
            sx[k] += w[s]*U[k];
            su[k] += w[s]*acc[k];
        }
    }

    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k)
    {
        x[k] = xn[k] + dt/6*sx[k];
        U[k] = Un[k] + dt/6*su[k];
    }
    constraints_->prescribe(t + dt, X0_, xf, U_);
    accValid_ = false;
    endStep(costs);
}


void Foam::meshless::solidModel::stepVerlet
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    particleField& xf = body_.particles().positions();
    const label nv = xf.size()*body_.dim();
    double* x = xf.data();
    double* U = U_.data();
    const double* acc = acc_.data();

    if (!accValid_)
    {
        constraints_->prescribe(t, X0_, xf, U_);
        evaluate(t, false, costs);
    }

    // Kick, drift, (forces), kick
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k)
    {
        U[k] += 0.5*dt*acc[k];
        x[k] += dt*U[k];
    }
    constraints_->prescribe(t + dt, X0_, xf, U_);
    evaluate(t + dt, true, costs);

    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k)
    {
        U[k] += 0.5*dt*acc[k];
    }
    constraints_->prescribe(t + dt, X0_, xf, U_);
    accValid_ = true;
}


void Foam::meshless::solidModel::assembleJacobian
(
    const scalar t,
    costAccounting& costs
)
{
    particleSet& set = body_.particles();
    const label n = set.size();
    const label dim = body_.dim();
    const label nv = n*dim;
    if (!jacobian_)
    {
        const neighbourRelation* pairs = referencePairs();
        if (!pairs)
        {
            FatalIOErrorInFunction(dict_)
                << "integrator implicit: model " << type() << " has no"
                << " reference pairs to build its tangent from: expected a"
                << " correspondence solid (tlsph, nosbPd)" << exit(FatalIOError);
        }
        std::vector<char> free(n);
        std::vector<label> mirror(n, -1);
        for (label i = 0; i < n; ++i)
        {
            free[i] = constraints_->isFree(i);
            mirror[i] = constraints_->partner(i);
        }
        jacobian_.reset
        (
            new solidJacobian(*pairs, dim, free, mirror, pairDamping())
        );
    }

    particleField& xf = set.positions();
    double* x = xf.data();
    double* U = U_.data();
    const double* acc = acc_.data();

    // The state: its accelerations a0, positions and velocities kept
    std::vector<double> a0(acc, acc + nv);
    std::vector<double> x0(x, x + nv);
    std::vector<double> U0(U, U + nv);

    const bool linear = law_->geometricallyLinear() && !law_->incremental();
    const scalar h = body_.kernel().h();
    const double eps = (linear ? 1e-3 : 1e-6)*h;
    const double epsU =
        (linear ? 1e-3 : 1e-6)*max(U_.maxMagnitude(), waveSpeed()*1e-3);

    solidJacobian::perturbed perturb =
        [&](const std::vector<label>& members, int d, double e)
        -> const double*
    {
        std::copy(x0.begin(), x0.end(), x);
        std::copy(U0.begin(), U0.end(), U);
        if (d < 0)
        {
            for (label k = 0; k < nv; ++k) U[k] += e;
        }
        else if (d >= dim)
        {
            for (const label k : members) U[k*dim + d - dim] += e;
        }
        else
        {
            for (const label k : members) x[k*dim + d] += e;
        }
        constraints_->prescribe(t, X0_, xf, U_);
        evaluate(t, false, costs);
        std::copy(acc, acc + nv, perturbA_.begin());
        return perturbA_.data();
    };
    jacobian_->assemble(a0.data(), eps, epsU, perturb);

    // Back to the state
    std::copy(x0.begin(), x0.end(), x);
    std::copy(U0.begin(), U0.end(), U);
    constraints_->prescribe(t, X0_, xf, U_);
    std::copy(a0.begin(), a0.end(), acc_.data());
}


bool Foam::meshless::solidModel::newmarkStep
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    particleSet& set = body_.particles();
    particleField& xf = set.positions();
    const label n = set.size();
    const label dim = body_.dim();
    const label nv = n*dim;
    double* x = xf.data();
    double* U = U_.data();
    double* acc = acc_.data();
    double* xn = xn_->data();
    double* Un = Un_->data();
    double* an = an_->data();
    double* aS = aNewmark_->data();
    double* r = newtonR_.data();
    double* dx = newtonDx_.data();
    double* xe = xNext_.data();

    if (!accValid_)
    {
        constraints_->prescribe(t, X0_, xf, U_);
        evaluate(t, false, costs);
        accValid_ = true;
    }
    std::copy(x, x + nv, xn);
    std::copy(U, U + nv, Un);
    std::copy(acc, acc + nv, an);

    // Generalised-alpha (Newmark: alphaM = alphaF = 0): with a(x, u) the
    // model's accelerations, solve for x^{n+1}
    //   (1 - aM) a^{n+1} + aM a^n = a(x^{n+1-aF}, u^{n+1-aF}),
    //   a^{n+1} = (x^{n+1} - x^n - dt u^n)/(beta dt^2) - (1/(2 beta) - 1) a^n,
    //   u^{n+1} = u^n + dt ((1 - gamma) a^n + gamma a^{n+1}),
    //   y^{n+1-aF} = (1 - aF) y^{n+1} + aF y^n
    const double b = beta_, g = gamma_, aM = alphaM_, aF = alphaF_;
    const double cx = 1/(b*dt*dt);
    const double cu = g/(b*dt);
    const double ca = 1/(2*b) - 1;
    const double wF = 1 - aF;
    const scalar tAlpha = t + wF*dt;
    const bool linear = law_->geometricallyLinear() && !law_->incremental();
    const scalar tolX = newtonTol_*body_.kernel().h();

    // Predictor: the accelerations of t kept
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k) xe[k] = xn[k] + dt*Un[k] + 0.5*dt*dt*an[k];

    label iters = 0, refreshes = 0;
    double lastR = GREAT, lastDx = GREAT;
    bool converged = false;
    for (;;)
    {
        // a^{n+1}, u^{n+1} of x^{n+1}; the model at the alpha point
        #pragma omp parallel for schedule(static)
        for (label k = 0; k < nv; ++k)
        {
            aS[k] = cx*(xe[k] - xn[k] - dt*Un[k]) - ca*an[k];
            const double u = Un[k] + dt*((1 - g)*an[k] + g*aS[k]);
            x[k] = wF*xe[k] + aF*xn[k];
            U[k] = wF*u + aF*Un[k];
        }
        constraints_->prescribe(tAlpha, X0_, xf, U_);
        evaluate(tAlpha, false, costs);

        // Residual over (1 - aF): the Newton matrix is then
        // (1 - aM)/(1 - aF) cx I - da/dx - cu da/du
        double rn = 0, scale = 0;
        for (label i = 0; i < n; ++i)
        {
            const bool free = constraints_->isFree(i);
            for (label e = 0; e < dim; ++e)
            {
                const label k = i*dim + e;
                const double lhs = (1 - aM)*aS[k] + aM*an[k];
                r[k] = free ? (acc[k] - lhs)/wF : 0;
                rn = max(rn, mag(acc[k] - lhs));
                if (free) scale = max(scale, max(mag(acc[k]), mag(lhs)));
            }
        }
        if (rn <= newtonTol_*scale || lastDx <= tolX)
        {
            lastR = rn;
            converged = true;
            break;
        }
        if (iters == newtonMaxIter_ || !std::isfinite(rn)) break;

        // The tangent: once for a linear law (a new one only if Newton
        // stalls); for any other law again whenever its iterations
        // contract slowly (modified Newton)
        const bool slow = iters > 0 && rn > 0.5*lastR;
        if
        (
            !jacobian_ || !jacobian_->assembled()
         || (slow && (!linear || refreshes == 0) && refreshes < 3)
        )
        {
            assembleJacobian(tAlpha, costs);
            ++refreshes;
        }
        const double shift = (1 - aM)/wF*cx;
        if
        (
            !jacobian_->factorised()
         || mag(shift/jacobian_->shiftX() - 1) > (slow ? 0 : 0.01)
        )
        {
            if (!jacobian_->factorise(shift, cu)) break;
        }
        jacobian_->solve(r, dx);
        double dn = 0;
        for (label k = 0; k < nv; ++k) dn = max(dn, mag(dx[k]));
        lastR = rn;
        ++iters;

        // A correction beyond the kernel's support is a diverging Newton
        // (evaluating it could overflow the law): the step is halved
        if (!(dn <= 2*body_.kernel().h())) break;
        for (label k = 0; k < nv; ++k) xe[k] += dx[k];
        lastDx = dn;
    }
    newtonIters_ += iters;
    newtonResidual_ = lastR;

    if (!converged)
    {
        // Back to the step's start
        std::copy(xn, xn + nv, x);
        std::copy(Un, Un + nv, U);
        std::copy(an, an + nv, acc);
        constraints_->prescribe(t, X0_, xf, U_);
        return false;
    }

    // The step's end. Newmark (aF = aM = 0): a^{n+1} the model's a(x) at
    // x^{n+1}; otherwise the algorithmic a^{n+1}
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k)
    {
        const double a = (aF == 0 && aM == 0) ? acc[k] : aS[k];
        x[k] = xe[k];
        U[k] = Un[k] + dt*((1 - g)*an[k] + g*a);
        acc[k] = a;
    }
    constraints_->prescribe(t + dt, X0_, xf, U_);
    endStep(costs);
    return true;
}


void Foam::meshless::solidModel::stepImplicit
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    // Newton that does not converge over dt: the step in halves, down to
    // 1/16 of it
    newtonIters_ = 0;
    label parts = 1;
    const label maxParts = 16;
    label done = 0;
    while (done < parts)
    {
        const scalar h = dt/parts;
        if (newmarkStep(t + done*h, h, costs))
        {
            ++done;
        }
        else if (2*parts <= maxParts)
        {
            parts *= 2;
            done *= 2;
        }
        else
        {
            OStringStream os;
            os  << "integrator implicit: Newton did not converge for body "
                << body_.name() << " over a step of " << dt << " s, nor"
                << " in " << maxParts << " parts of it (" << newtonMaxIter_
                << " iterations each, implicit maxIter; residual "
                << newtonResidual_ << " m/s^2, tolerance " << newtonTol_
                << " relative)";
            failure_ = os.str();
            break;
        }
    }
    accValid_ = true;

    Info<< "    " << body_.name() << ": Newton " << newtonIters_
        << " iterations";
    if (parts > 1) Info<< " in " << parts << " parts of the step";
    Info<< ", residual " << newtonResidual_ << " m/s^2";
    if (jacobian_)
    {
        Info<< ", tangents " << jacobian_->assemblies() << " ("
            << jacobian_->nColours() << " colours), factorisations "
            << jacobian_->factorisations();
    }
    Info<< endl;
}


void Foam::meshless::solidModel::step
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    if (integrator_ == integratorType::rk4)
    {
        stepRK4(t, dt, costs);
    }
    else if (integrator_ == integratorType::implicit)
    {
        stepImplicit(t, dt, costs);
    }
    else
    {
        stepVerlet(t, dt, costs);
    }
    updateDisplacement();
}


void Foam::meshless::solidModel::advance
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    const label n = subSteps_(dt, stepLimit(maxCo_));
    const scalar h = dt/n;
    for (label k = 0; k < n; ++k)
    {
        step(t + k*h, h, costs);
    }
}


const Foam::meshless::particleField&
Foam::meshless::solidModel::normals() const
{
    particleSet& set = body_.particles();
    const label dim = body_.dim();
    const label n = set.size();
    if (!N0_)
    {
        // The reference normals, once
        solidModel& self = const_cast<solidModel&>(*this);
        self.N0_ = &set.addScratchField("N0", particleField::kind::vector);
        normals_ = &set.addScratchField("normal", particleField::kind::vector);
        referenceNormals(*self.N0_);
        scalar most = 0;
        for (label i = 0; i < n; ++i)
        {
            scalar s = 0;
            for (label d = 0; d < dim; ++d) s += sqr((*N0_)(i, d));
            most = max(most, s);
        }
        // Interior particles (a full support: zero up to the lattice's
        // irregularity) have none
        for (label i = 0; i < n; ++i)
        {
            scalar s = 0;
            for (label d = 0; d < dim; ++d) s += sqr((*N0_)(i, d));
            if (s < 0.25*most)
            {
                for (label d = 0; d < dim; ++d) (*self.N0_)(i, d) = 0;
            }
        }
    }

    // Nanson: n ~ F^-T N
    particleField& F = set.field("F");
    deformationGradient(F);
    for (label i = 0; i < n; ++i)
    {
        const tensor Fi = toTensor(F.data(), i, dim);
        vector N(Zero);
        for (label d = 0; d < dim; ++d) N[d] = (*N0_)(i, d);
        vector ni = inv(Fi).T() & N;
        const scalar m = mag(ni);
        if (m > 0) ni /= m;
        for (label d = 0; d < dim; ++d) (*normals_)(i, d) = ni[d];
    }
    return *normals_;
}


// ************************************************************************* //
