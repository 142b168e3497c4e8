/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "tlsph.H"
#include "particleScene.H"
#include "particleExpression.H"
#include "tlsphOperators.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace bodyModels
{
    defineTypeNameAndDebug(tlsph, 0);
    addToRunTimeSelectionTable(bodyModel, tlsph, dictionary);
}
}
}

namespace
{
    //- Particle a's dim x dim tensor (row-major) as a 3x3 tensor with
    //  zz = 1 in 2D, as the constitutive laws take it
    inline Foam::tensor particleTensor
    (
        const double* T,
        const Foam::label a,
        const Foam::label dim
    )
    {
        Foam::tensor t(Foam::tensor::I);
        for (Foam::label i = 0; i < dim; ++i)
        {
            for (Foam::label j = 0; j < dim; ++j)
            {
                t[3*i + j] = T[(a*dim + i)*dim + j];
            }
        }
        return t;
    }
}


const Foam::Enum<Foam::meshless::bodyModels::tlsph::integratorType>
Foam::meshless::bodyModels::tlsph::integratorNames
({
    { integratorType::rk4, "rk4" },
    { integratorType::verlet, "verlet" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<int Dim>
void Foam::meshless::bodyModels::tlsph::buildReference()
{
    const label n = body_.particles().size();
    const double* X = X0_.data();

    cellLinkedList cells(Dim, body_.kernel().radius());
    cells.build(X, n);
    pairs_.build(cells, X, n, true);

    const label singular = tlsphOperators::reference<Dim>
    (
        pairs_, body_.kernel(), X, V0_.data(),
        vgradW_, corrGradW_, Wab_, KinvT_, order_,
        taylor_ ? &hessW_ : nullptr
    );
    reverse_ = tlsphOperators::reversePairs(pairs_);

    // Particles whose order 2 fit fell back to order 1 have no strain
    // gradient: no Taylor term, so nothing resists their zero-energy modes
    if (taylor_)
    {
        label flat = 0;
        for (label a = 0; a < n; ++a)
        {
            bool any = false;
            for (label p = pairs_.offset(a); p < pairs_.offset(a + 1); ++p)
            {
                for (int k = 0; k < Dim*Dim; ++k)
                {
                    any = any || hessW_[p*Dim*Dim + k] != 0;
                }
            }
            if (!any) ++flat;
        }
        if (flat)
        {
            WarningInFunction
                << "Body " << body_.name() << ": " << flat << " particles"
                << " without a strain gradient (too few neighbours for the"
                << " order 2 fit): no Taylor term there" << endl;
        }
    }

    if (singular >= 0)
    {
        FatalIOErrorInFunction(dict_)
            << "Body " << body_.name() << ": the correction matrix K (eq. 35)"
            << " of particle " << body_.particles().ids()[singular]
            << " is singular (" << pairs_.nNeighbours(singular)
            << " neighbours): the solid's particles must fill the kernel"
            << " support; check the seeding or the kernel's size"
            << exit(FatalIOError);
    }
}


template<int Dim>
void Foam::meshless::bodyModels::tlsph::computeF(particleField& F) const
{
    tlsphOperators::deformationGradient<Dim>
    (
        pairs_,
        corrGradW_.data(),
        X0_.data(),
        body_.particles().positions().data(),
        F.data()
    );
}


template<int Dim>
Foam::scalar Foam::meshless::bodyModels::tlsph::strainGradientStress() const
{
    const label n = body_.particles().size();
    constexpr int D3 = Dim*Dim*Dim;
    tlsphOperators::strainGradient<Dim>
    (
        pairs_, hessW_.data(), X0_.data(),
        body_.particles().positions().data(), gradEps_.data()
    );

    // The cell's second moment per unit volume, dx^2/12 along each axis
    // (dx from the particle's volume)
    const constitutiveLaw& law = law_();
    const double* G = gradEps_.data();
    double* T = gradStress_.data();
    scalar E = 0;
    #pragma omp parallel for schedule(static) reduction(+:E)
    for (label a = 0; a < n; ++a)
    {
        if (!image_.empty() && image_[a])
        {
            std::fill_n(T + a*D3, D3, 0.0);
            continue;
        }
        const double c = V0_(a, 0)*std::pow(V0_(a, 0), 2.0/Dim)/12;
        for (int k = 0; k < Dim; ++k)
        {
            // The law is linear: C : e is its stress at F = I + e
            tensor Fe(tensor::I);
            const double* e = G + a*D3 + k*Dim*Dim;
            for (int i = 0; i < Dim; ++i)
            {
                for (int j = 0; j < Dim; ++j) Fe[3*i + j] += e[i*Dim + j];
            }
            const tensor s = law.stress(a, tensor::I, Fe);
            double* t = T + a*D3 + k*Dim*Dim;
            for (int i = 0; i < Dim; ++i)
            {
                for (int j = 0; j < Dim; ++j)
                {
                    t[i*Dim + j] = c*s[3*i + j];
                    E += 0.5*t[i*Dim + j]*e[i*Dim + j];
                }
            }
        }
    }
    return E;
}


template<int Dim>
void Foam::meshless::bodyModels::tlsph::evaluate
(
    const scalar t,
    costAccounting& costs
)
{
    const label n = body_.particles().size();
    double* acc = acc_.data();
    {
        costAccounting::scope timer(costs, stressCost_);

        const double* x = body_.particles().positions().data();
        const double* X = X0_.data();
        const double* V = V0_.data();
        const double* F = F_.data();
        const double* Fo = Fold_.data();
        double* P = P_.data();
        const constitutiveLaw& law = law_();

        computeF<Dim>(F_);

        #pragma omp parallel for schedule(static)
        for (label a = 0; a < n; ++a)
        {
            const tensor Pa = law.stress
            (
                a, particleTensor(Fo, a, Dim), particleTensor(F, a, Dim)
            );
            tlsphOperators::stressDim<Dim>(Pa.cdata(), P + a*Dim*Dim);
        }

        tlsphOperators::clearImageStress<Dim>(mirrors_, P);

        tlsphOperators::internalForce<Dim>
        (
            pairs_, corrGradW_.data(), reverse_.data(), V, P, acc
        );
        if (taylor_)
        {
            strainGradientStress<Dim>();
            tlsphOperators::strainGradientForce<Dim>
            (
                pairs_, hessW_.data(), reverse_.data(), gradStress_.data(),
                acc
            );
        }
        if (hourglass_ > 0)
        {
            tlsphOperators::hourglassForce<Dim>
            (
                pairs_, Wab_.data(), V, X, x, F,
                0.5*hourglass_*law.elastic().E(), acc,
                law.geometricallyLinear(),
                image_.empty() ? nullptr : image_.data()
            );
        }

        tlsphOperators::foldImageForces<Dim>(mirrors_, acc);

        const double* m = mass_.data();
        #pragma omp parallel for schedule(static)
        for (label a = 0; a < n; ++a)
        {
            for (int i = 0; i < Dim; ++i) acc[a*Dim + i] /= m[a];
        }
        Fcurrent_ = false;
    }

    body_.addEffectAccelerations(t, acc_, costs);
    constraints_->addLoads(t, acc_);

    for (label a = 0; a < n; ++a)
    {
        if (!constraints_->isFree(a))
        {
            for (int i = 0; i < Dim; ++i) acc[a*Dim + i] = 0;
        }
    }
}


void Foam::meshless::bodyModels::tlsph::evaluateDim
(
    const scalar t,
    costAccounting& costs
)
{
    if (body_.dim() == 2) evaluate<2>(t, costs);
    else evaluate<3>(t, costs);
}


void Foam::meshless::bodyModels::tlsph::computeFDim(particleField& F) const
{
    if (body_.dim() == 2) computeF<2>(F);
    else computeF<3>(F);
}


void Foam::meshless::bodyModels::tlsph::stepRK4
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
    double* xn = xn_.data();
    double* Un = Un_.data();
    double* sx = sumX_.data();
    double* su = sumU_.data();

    std::copy(x, x + nv, xn);
    std::copy(U, U + nv, Un);
    std::fill(sx, sx + nv, 0.0);
    std::fill(su, su + nv, 0.0);

    // Eq. 43-45: stage s at t + c_s dt from the previous stage's rates
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
        evaluateDim(t + c[s]*dt, costs);

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
}


void Foam::meshless::bodyModels::tlsph::stepVerlet
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
        evaluateDim(t, costs);
    }

    // Kick, drift, (forces), kick
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k)
    {
        U[k] += 0.5*dt*acc[k];
        x[k] += dt*U[k];
    }
    constraints_->prescribe(t + dt, X0_, xf, U_);
    evaluateDim(t + dt, costs);

    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k)
    {
        U[k] += 0.5*dt*acc[k];
    }
    constraints_->prescribe(t + dt, X0_, xf, U_);
    accValid_ = true;
}


void Foam::meshless::bodyModels::tlsph::commit()
{
    // Only incremental laws need F of the end state now (Verlet's last
    // evaluation had it already); the strain energy computes it on demand
    if (!law_->incremental()) return;

    if (integrator_ == integratorType::rk4 || !accValid_)
    {
        computeFDim(F_);
    }
    Fcurrent_ = true;

    const label n = body_.particles().size();
    const label dim = body_.dim();
    {
        for (label a = 0; a < n; ++a)
        {
            law_->commit
            (
                a,
                particleTensor(Fold_.data(), a, dim),
                particleTensor(F_.data(), a, dim)
            );
        }
    }
    std::copy(F_.data(), F_.data() + n*dim*dim, Fold_.data());
}


Foam::scalar Foam::meshless::bodyModels::tlsph::stableDeltaT
(
    const scalar maxCo
) const
{
    return maxCo*body_.kernel().h()/(c_ + U_.maxMagnitude());
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::bodyModels::tlsph::tlsph
(
    particleBody& body,
    const dictionary& dict
)
:
    bodyModel(body, dict),
    restart_(body.particles().found("X0")),
    U_(body.particles().addField("U", particleField::kind::vector)),
    X0_(body.particles().addField("X0", particleField::kind::vector)),
    displacement_
    (
        body.particles().addField("displacement", particleField::kind::vector)
    ),
    mass_(body.requireField("mass", "model tlsph")),
    V0_(body.requireField("volume", "model tlsph")),
    acc_(body.particles().addScratchField("acc", particleField::kind::vector)),
    F_(body.particles().addScratchField("F", particleField::kind::tensor)),
    Fold_(body.particles().addScratchField("Fold", particleField::kind::tensor)),
    P_(body.particles().addScratchField("P", particleField::kind::tensor)),
    xn_(body.particles().addScratchField("xn", particleField::kind::vector)),
    Un_(body.particles().addScratchField("Un", particleField::kind::vector)),
    sumX_(body.particles().addScratchField("sumX", particleField::kind::vector)),
    sumU_(body.particles().addScratchField("sumU", particleField::kind::vector)),
    law_(constitutiveLaw::New(dict, body.dim(), body.particles())),
    integrator_(integratorNames.get("integrator", dict)),
    hourglass_(dict.getOrDefault<scalar>("hourglassControl", 0)),
    order_(dict.getOrDefault<label>("gradientOrder", 1)),
    taylor_(false),
    minSubSteps_
    (
        dict.found("subSteps") ? readPositiveLabel(dict, "subSteps") : 1
    ),
    c_(std::sqrt(law_->waveModulus()/body.density())),
    maxCo_(0.3),
    lastSubSteps_(1),
    accValid_(false),
    Fcurrent_(false),
    stressCost_(-1)
{
    if (hourglass_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "hourglassControl " << hourglass_ << ": expected a coefficient"
            << " >= 0 (0: off; the tutorials use 10)"
            << exit(FatalIOError);
    }

    if (order_ != 1 && order_ != 2)
    {
        FatalIOErrorInFunction(dict)
            << "gradientOrder " << order_ << ": expected 1 (eq. 35-36, the"
            << " default) or 2 (with the quadratic terms)"
            << exit(FatalIOError);
    }

    const word integration =
        dict.getOrDefault<word>("nodalIntegration", "midpoint");
    if (integration == "taylor")
    {
        taylor_ = true;
        if
        (
            order_ != 2
         || !law_->geometricallyLinear()
         || law_->incremental()
        )
        {
            FatalIOErrorInFunction(dict)
                << "nodalIntegration taylor: needs gradientOrder 2 (the"
                << " strain gradient comes from its fit) and a linear law"
                << " with small kinematics (linearElastic, kinematics small)"
                << exit(FatalIOError);
        }
    }
    else if (integration != "midpoint")
    {
        FatalIOErrorInFunction(dict)
            << "nodalIntegration " << integration << ": expected midpoint"
            << " (the default) or taylor" << exit(FatalIOError);
    }

    particleSet& set = body.particles();
    const label nv = set.size()*body.dim();
    if (taylor_)
    {
        const label d3 = body.dim()*body.dim()*body.dim();
        gradEps_.assign(set.size()*d3, 0);
        gradStress_.assign(set.size()*d3, 0);
    }

    // A fresh start: the seeded state is the reference configuration
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

    if (body.dim() == 2) buildReference<2>();
    else buildReference<3>();

    // The current F is the step's start for incremental laws
    computeFDim(F_);
    std::copy(F_.data(), F_.data() + F_.size()*F_.nComponents(), Fold_.data());
    for (label k = 0; k < nv; ++k)
    {
        displacement_.data()[k] = set.positions().data()[k] - X0_.data()[k];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::bodyModels::tlsph::connect(particleScene& scene)
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
    stressCost_ = scene.costs().part(body_.name() + ": tlsph stress");

    const label n = body_.particles().size();
    image_.clear();
    mirrors_.clear();
    for (label i = 0; i < n; ++i)
    {
        const label m = constraints_->partner(i);
        if (m < 0) continue;
        if (image_.empty()) image_.assign(n, 0);
        image_[i] = 1;
        mirrors_.emplace_back(i, m);
    }

    Info<< "    " << body_.name() << ": tlsph, "
        << integratorNames[integrator_] << ", wave speed " << c_ << " m/s, "
        << pairs_.nPairs() << " reference pairs, gradientOrder " << order_
        << ", hourglassControl " << hourglass_ << nl;
    constraints_->describe(Info);
}


Foam::scalar Foam::meshless::bodyModels::tlsph::maxDeltaT
(
    const scalar maxCo
) const
{
    maxCo_ = maxCo;
    return minSubSteps_*stableDeltaT(maxCo);
}


void Foam::meshless::bodyModels::tlsph::advance
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    const label nSub = max
    (
        minSubSteps_,
        label(std::ceil(dt/stableDeltaT(maxCo_)*(1 - 1e-12)))
    );
    if (nSub != lastSubSteps_)
    {
        Info<< "    " << body_.name() << ": " << nSub
            << " solid sub-steps per step" << endl;
        lastSubSteps_ = nSub;
    }

    const scalar h = dt/nSub;
    for (label k = 0; k < nSub; ++k)
    {
        if (integrator_ == integratorType::rk4)
        {
            stepRK4(t + k*h, h, costs);
        }
        else
        {
            stepVerlet(t + k*h, h, costs);
        }
    }
    commit();

    particleSet& set = body_.particles();
    const label nv = set.size()*body_.dim();
    for (label k = 0; k < nv; ++k)
    {
        displacement_.data()[k] = set.positions().data()[k] - X0_.data()[k];
    }
}


Foam::scalar Foam::meshless::bodyModels::tlsph::strainEnergy() const
{
    if (!Fcurrent_)
    {
        computeFDim(F_);
        Fcurrent_ = true;
    }
    const label n = body_.particles().size();
    const label dim = body_.dim();
    scalar W = 0;
    for (label a = 0; a < n; ++a)
    {
        if (isImage(a)) continue;
        W += V0_(a, 0)
            *law_->energyDensity(a, particleTensor(F_.data(), a, dim));
    }

    // The strain gradient's energy over the cells (Taylor integration)
    if (taylor_)
    {
        W += dim == 2 ? strainGradientStress<2>() : strainGradientStress<3>();
    }

    // The hourglass control's springs store energy too
    if (hourglass_ > 0)
    {
        const double c = 0.5*hourglass_*law_->elastic().E();
        const double* x = body_.particles().positions().data();
        const char* img = image_.empty() ? nullptr : image_.data();
        W +=
            dim == 2
          ? tlsphOperators::hourglassEnergy<2>
            (
                pairs_, Wab_.data(), V0_.data(), X0_.data(), x, F_.data(), c,
                law_->geometricallyLinear(), img
            )
          : tlsphOperators::hourglassEnergy<3>
            (
                pairs_, Wab_.data(), V0_.data(), X0_.data(), x, F_.data(), c,
                law_->geometricallyLinear(), img
            );
    }
    return W;
}


// ************************************************************************* //
