/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "nosbPd.H"
#include "nosbPdOperators.H"
#include "particleScene.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include <cmath>

namespace Foam
{
namespace meshless
{
namespace bodyModels
{
    defineTypeNameAndDebug(nosbPd, 0);
    addToRunTimeSelectionTable(bodyModel, nosbPd, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::bodyModels::nosbPd::nosbPd
(
    particleBody& body,
    const dictionary& dict
)
:
    bodyModel(body, dict),
    rho0_(body.density()),
    Gs_(dict.get<scalar>("hourglassCoefficient")),
    alphaV_
    (
        dict.found("artificialViscosity")
      ? readPositive(dict, "artificialViscosity")
      : 0
    ),
    eta_(0),
    order_(dict.found("order") ? readLabelInRange(dict, "order", 1, 2) : 1),
    s0_(0),
    C_(0),
    U_(body.particles().addField("U", particleField::kind::vector)),
    X0_
    (
        [&]() -> particleField&
        {
            particleSet& set = body.particles();
            const bool fresh = !set.found("X0");
            particleField& X0 = set.addField("X0", particleField::kind::vector);
            if (fresh)
            {
                std::copy
                (
                    set.positions().data(),
                    set.positions().data() + set.size()*set.dim(),
                    X0.data()
                );
            }
            return X0;
        }()
    ),
    damage_(body.particles().addField("damage", particleField::kind::scalar)),
    V0_(body.requireField("volume", "model nosbPd")),
    acc_(body.particles().addScratchField("acc", particleField::kind::vector)),
    F_(body.particles().addScratchField("F", particleField::kind::tensor)),
    Fold_(body.particles().addScratchField("Fold", particleField::kind::tensor)),
    P_(body.particles().addScratchField("P", particleField::kind::tensor)),
    m_(body.particles().addScratchField("weightedVolume", particleField::kind::scalar)),
    Ws_(body.particles().addScratchField("Ws", particleField::kind::scalar)),
    // Written: the first half kick after a restart needs the last force
    fExt_
    (
        body.particles().addField("externalForce", particleField::kind::vector)
    ),
    resolved_(body.particles().size(), 1),
    law_(constitutiveLaw::New(dict, body.dim(), body.particles())),
    nSingular_(0)
{
    if (!(Gs_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "'hourglassCoefficient' = " << Gs_ << ": expected >= 0"
            << " (Silling 2017 stabilisation; 0 = none)"
            << exit(FatalIOError);
    }
    C_ = Gs_*law_->waveModulus();
    eta_ = alphaV_*rho0_*std::sqrt(law_->waveModulus()/rho0_)
       *body.kernel().h();

    families_.reset(new peridynamicFamilies(X0_, V0_, body.kernel()));
    g_.resize(families_->nBonds()*body.dim());
    readFailure();
}


Foam::meshless::bodyModels::nosbPd::~nosbPd()
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::meshless::bodyModels::nosbPd::readFailure()
{
    const dictionary* d = dict_.findDict("failure");
    if (!d) return;

    const bool given = d->found("criticalStretch");
    const bool fromG0 = d->found("energyReleaseRate");
    if (given == fromG0)
    {
        FatalIOErrorInFunction(*d)
            << "failure: expected exactly one of 'criticalStretch' (s0) and"
            << " 'energyReleaseRate' (G0 [J/m^2], eq. 48)"
            << exit(FatalIOError);
    }
    if (given)
    {
        s0_ = readPositive(*d, "criticalStretch");
    }
    else
    {
        const scalar G0 = readPositive(*d, "energyReleaseRate");
        const scalar delta = body_.kernel().radius();
        s0_ = std::sqrt(5*G0/(9*law_->elastic().K()*delta));
    }
}


template<int Dim>
void Foam::meshless::bodyModels::nosbPd::updateBonds()
{
    nSingular_ = nosbPdOperators::bondGradients<Dim>
    (
        *families_, X0_.data(), order_, body_.kernel().radius(), g_.data(),
        m_.data(), resolved_.data()
    );
    families_->damage(V0_, damage_);
}


template<int Dim>
void Foam::meshless::bodyModels::nosbPd::rebase()
{
    const particleSet& set = body_.particles();
    const label n = set.size();
    nosbPdOperators::deformationGradients<Dim>
    (
        *families_, set.positions().data(), g_.data(), resolved_.data(),
        F_.data()
    );
    std::copy(F_.data(), F_.data() + F_.size()*F_.nComponents(), Fold_.data());

    constexpr label nt = Dim*Dim;
    const constitutiveLaw& law = *law_;

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        double* Pi = P_.data() + i*nt;
        if (!resolved_[i])
        {
            for (label c = 0; c < nt; ++c) Pi[c] = 0;
            continue;
        }
        tensor F(tensor::I);
        for (label a = 0; a < Dim; ++a)
        {
            for (label b = 0; b < Dim; ++b) F(a, b) = F_(i, a*Dim + b);
        }
        const tensor P = law.stress(i, F, F);
        for (label a = 0; a < Dim; ++a)
        {
            for (label b = 0; b < Dim; ++b) Pi[a*Dim + b] = P(a, b);
        }
    }
}


template<int Dim>
void Foam::meshless::bodyModels::nosbPd::evaluate
(
    const scalar t,
    const bool commit,
    costAccounting& costs
)
{
    const particleSet& set = body_.particles();
    const label n = set.size();
    const double* x = set.positions().data();

    nosbPdOperators::deformationGradients<Dim>
    (
        *families_, x, g_.data(), resolved_.data(), F_.data()
    );

    constexpr label nt = Dim*Dim;
    constitutiveLaw& law = *law_;

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        double* Pi = P_.data() + i*nt;
        if (!resolved_[i])
        {
            for (label c = 0; c < nt; ++c) Pi[c] = 0;
            continue;
        }
        tensor F(tensor::I), Fold(tensor::I);
        for (label a = 0; a < Dim; ++a)
        {
            for (label b = 0; b < Dim; ++b)
            {
                F(a, b) = F_(i, a*Dim + b);
                Fold(a, b) = Fold_(i, a*Dim + b);
            }
        }
        const tensor P = law.stress(i, Fold, F);
        for (label a = 0; a < Dim; ++a)
        {
            for (label b = 0; b < Dim; ++b) Pi[a*Dim + b] = P(a, b);
        }
        if (commit)
        {
            law.commit(i, Fold, F);
            for (label c = 0; c < nt; ++c) Fold_(i, c) = F_(i, c);
        }
    }

    // Bonds break at the end of an accepted step, the material state of the
    // step committed. The broken bonds change the sums (weights g, F) but not
    // the material: F and Fold are recomputed over the intact bonds at the
    // same positions and P from the committed stress (the step from F to
    // F), so the next step's increment F - Fold holds no jump of the weights
    if (commit && s0_ > 0)
    {
        const label nBroken =
            nosbPdOperators::breakBonds<Dim>(*families_, X0_.data(), x, s0_);
        if (nBroken)
        {
            updateBonds<Dim>();
            rebase<Dim>();
        }
    }

    nosbPdOperators::forceDensity<Dim>
    (
        *families_, X0_.data(), x, P_.data(), g_.data(), F_.data(),
        m_.data(), resolved_.data(), C_, acc_.data()
    );
    if (eta_ > 0)
    {
        nosbPdOperators::bondViscosity<Dim>
        (
            *families_, x, U_.data(), m_.data(), eta_, body_.kernel().h(),
            acc_.data()
        );
    }

    double* a = acc_.data();
    const label nv = n*Dim;
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k) a[k] /= rho0_;
    const double* fExt = fExt_.data();
    const double* V0 = V0_.data();
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k) a[k] += fExt[k]/(rho0_*V0[k/Dim]);

    constraints_->addLoads(t, acc_);
    body_.addEffectAccelerations(t, acc_, costs);
}


void Foam::meshless::bodyModels::nosbPd::evaluateDim
(
    const scalar t,
    const bool commit,
    costAccounting& costs
)
{
    if (body_.dim() == 2) evaluate<2>(t, commit, costs);
    else evaluate<3>(t, commit, costs);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::bodyModels::nosbPd::connect(particleScene& scene)
{
    particleSet& set = body_.particles();
    const Time& runTime = scene.time();

    constraints_.reset
    (
        new solidConstraints
        (
            dict_, set, X0_, scene.mesh(), &body_.kernel()
        )
    );
    // The mirrored clamp is made variational by tlsph's force; here it
    // would be a ghost condition that does not conserve energy
    for (label i = 0; i < set.size(); ++i)
    {
        if (constraints_->mirrored(i))
        {
            FatalIOErrorInFunction(dict_.subDict("constraints"))
                << "Body " << body_.name() << ": a clamped constraint with"
                << " a 'face' (mirrored clamp) is for model tlsph; remove"
                << " the face to hold the clamped particles where they are"
                << exit(FatalIOError);
        }
    }

    const label nRead =
        families_->readBroken(set, runTime, runTime.timeName());
    if (s0_ > 0)
    {
        // A state written by this model has these broken already
        if (body_.dim() == 2)
        {
            nosbPdOperators::breakBonds<2>
            (
                *families_, X0_.data(), set.positions().data(), s0_
            );
        }
        else
        {
            nosbPdOperators::breakBonds<3>
            (
                *families_, X0_.data(), set.positions().data(), s0_
            );
        }
    }
    if (body_.dim() == 2) updateBonds<2>();
    else updateBonds<3>();

    constraints_->prescribe(runTime.value(), X0_, set.positions(), U_);

    // The state read is the committed one: the first evaluation is the
    // step from F to F
    if (body_.dim() == 2)
    {
        nosbPdOperators::deformationGradients<2>
        (
            *families_, set.positions().data(), g_.data(), resolved_.data(),
            F_.data()
        );
    }
    else
    {
        nosbPdOperators::deformationGradients<3>
        (
            *families_, set.positions().data(), g_.data(), resolved_.data(),
            F_.data()
        );
    }
    std::copy(F_.data(), F_.data() + F_.size()*F_.nComponents(), Fold_.data());
    evaluateDim(runTime.value(), false, scene.costs());

    Info<< "nosbPd " << body_.name() << ": "
        << families_->nBonds()/max(set.size(), label(1))
        << " bonds per particle, horizon " << body_.kernel().radius()
        << ", F of order " << order_ << ", law " << law_->type()
        << ", hourglassCoefficient " << Gs_;
    if (eta_ > 0)
    {
        Info<< ", artificialViscosity " << alphaV_ << " (eta " << eta_
            << " Pa s)";
    }
    if (s0_ > 0)
    {
        Info<< ", critical stretch " << s0_ << " (" << nRead
            << " broken bonds read)";
    }
    Info<< ", " << nSingular_ << " singular shape tensors" << nl;
    constraints_->describe(Info);
}


Foam::scalar Foam::meshless::bodyModels::nosbPd::maxDeltaT
(
    const scalar maxCo
) const
{
    const scalar h = body_.kernel().h();
    const scalar c = std::sqrt(law_->waveModulus()*(1 + Gs_)/rho0_);
    scalar dt = maxCo*h/(c + U_.maxMagnitude());
    if (eta_ > 0)
    {
        // The bond dashpots relax a particle's velocity at a rate of about
        // eta/(rho0 h^2): explicit stepping needs dt below its inverse.
        // Binding only for alpha > 1.
        dt = min(dt, maxCo*rho0_*h*h/eta_);
    }
    return dt;
}


Foam::scalar Foam::meshless::bodyModels::nosbPd::strainEnergy() const
{
    const particleSet& set = body_.particles();
    const label n = set.size();
    const label dim = body_.dim();
    if (dim == 2)
    {
        nosbPdOperators::stabilisationEnergy<2>
        (
            *families_, X0_.data(), set.positions().data(), F_.data(),
            m_.data(), resolved_.data(), C_, Ws_.data()
        );
    }
    else
    {
        nosbPdOperators::stabilisationEnergy<3>
        (
            *families_, X0_.data(), set.positions().data(), F_.data(),
            m_.data(), resolved_.data(), C_, Ws_.data()
        );
    }

    scalar E = 0;
    for (label i = 0; i < n; ++i)
    {
        tensor F(tensor::I);
        for (label a = 0; a < dim; ++a)
        {
            for (label b = 0; b < dim; ++b) F(a, b) = F_(i, a*dim + b);
        }
        E += V0_(i, 0)*(law_->energyDensity(i, F) + Ws_(i, 0));
    }
    return E;
}


void Foam::meshless::bodyModels::nosbPd::advance
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    particleSet& set = body_.particles();
    const label n = set.size();
    const label dim = body_.dim();
    double* x = set.positions().data();
    double* U = U_.data();
    const double* a = acc_.data();
    const solidConstraints& bc = *constraints_;

    // Half kick of the free particles, and their drift by dtDrift
    auto kick = [&](const scalar dtDrift)
    {
        #pragma omp parallel for schedule(static)
        for (label i = 0; i < n; ++i)
        {
            if (!bc.isFree(i)) continue;
            for (label k = i*dim; k < (i + 1)*dim; ++k)
            {
                U[k] += 0.5*dt*a[k];
                x[k] += dtDrift*U[k];
            }
        }
    };

    // Velocity Verlet (eq. 55): half kick and drift, forces at the new
    // positions, half kick
    kick(dt);
    bc.prescribe(t + dt, X0_, set.positions(), U_);
    evaluateDim(t + dt, true, costs);
    kick(0);
}


void Foam::meshless::bodyModels::nosbPd::write
(
    const Time& runTime,
    const word& timeName
) const
{
    if (s0_ > 0)
    {
        families_->writeBroken(body_.particles(), runTime, timeName);
        Info<< "    nosbPd " << body_.name() << ": "
            << families_->nBrokenSides()/2 << " broken bonds" << endl;
    }
}


// ************************************************************************* //
