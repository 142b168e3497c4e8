/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "solidModel.H"
#include "particleScene.H"
#include "particleExpression.H"
#include "smallTensor.H"
#include "dictionaryChecks.H"

const Foam::Enum<Foam::meshless::solidModel::integratorType>
Foam::meshless::solidModel::integratorNames
({
    { integratorType::verlet, "verlet" },
    { integratorType::rk4, "rk4" },
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
    xn_(nullptr),
    Un_(nullptr),
    sumX_(nullptr),
    sumU_(nullptr),
    N0_(nullptr),
    normals_(nullptr)
{
    particleSet& set = body.particles();
    if (integrator_ == integratorType::rk4)
    {
        xn_ = &set.addScratchField("xn", particleField::kind::vector);
        Un_ = &set.addScratchField("Un", particleField::kind::vector);
        sumX_ = &set.addScratchField("sumX", particleField::kind::vector);
        sumU_ = &set.addScratchField("sumU", particleField::kind::vector);
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
    return maxCo*body_.kernel().h()/(waveSpeed() + U_.maxMagnitude());
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
