/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "correspondenceSolid.H"
#include "dispatchDim.H"
#include "correspondenceOperators.H"
#include "particleScene.H"
#include "dictionaryChecks.H"



Foam::meshless::correspondenceSolid::correspondenceSolid
(
    particleBody& body,
    const dictionary& dict
)
:
    solidModel(body, dict),
    order_
    (
        dict.found("gradientOrder")
      ? readLabelInRange(dict, "gradientOrder", 1, 2)
      : 1
    ),
    ref_(nullptr),
    resolved_(body.particles().size(), 1),
    F_(body.particles().addScratchField("F", particleField::kind::tensor)),
    Fold_(body.particles().addScratchField("Fold", particleField::kind::tensor)),
    P_(body.particles().addScratchField("P", particleField::kind::tensor)),
    secondDerivatives_(false),
    stressCost_(-1)
{}


void Foam::meshless::correspondenceSolid::connect(particleScene& scene)
{
    solidModel::connect(scene);
    stressCost_ = scene.costs().part(body_.name() + ".stress");

    sceneRelations& relations = scene.relations();
    ref_ = &relations.inner
    (
        body_.name() + " (reference)", X0_, body_.kernel(), 0, false,
        neighbourRelation::separation | neighbourRelation::kernelValue
      | neighbourRelation::kernelGradient | neighbourRelation::reversePairs
    );
    relations.update(*ref_);
    setUpPairs(scene);

    const label nSingular = fit();
    if (nSingular)
    {
        WarningInFunction
            << "Body " << body_.name() << ": " << nSingular << " particles"
            << " with fewer reference neighbours than the fit needs: they"
            << " carry no stress" << endl;
    }

    // The state read is the committed one (the step's start for
    // incremental laws); the accelerations of the start state for the
    // first half kick, those of the last step on a restart that wrote them
    const scalar t = scene.time().value();
    constraints_->prescribe(t, X0_, body_.particles().positions(), U_);
    computeF(F_);
    std::copy(F_.data(), F_.data() + F_.size()*F_.nComponents(), Fold_.data());
    const label nAcc = acc_.size()*acc_.nComponents();
    std::vector<double> accRead
    (
        accRead_ ? acc_.data() : nullptr,
        accRead_ ? acc_.data() + nAcc : nullptr
    );
    evaluate(t, false, scene.costs());
    std::copy(accRead.begin(), accRead.end(), acc_.data());
    accValid_ = true;

    Info<< "    " << body_.name() << ": " << type() << ", "
        << integratorNames[integrator_] << ", wave speed " << waveSpeed()
        << " m/s, " << ref_->nPairs() << " reference pairs, gradientOrder "
        << order_ << ", law " << law_->type();
    describeModel(Info);
    Info<< nl;
    constraints_->describe(Info);
}


Foam::label Foam::meshless::correspondenceSolid::fit()
{
    const label dim = body_.dim();
    const label np = ref_->nPairs();
    G_.resize(size_t(np)*dim);
    if (secondDerivatives_) H_.resize(size_t(np)*dim*dim);
    double* H = secondDerivatives_ ? H_.data() : nullptr;
    const char* intact = intact_.empty() ? nullptr : intact_.data();
    const scalar L = fitLength();
    const double* V = V0_.data();

    using namespace correctionMatrix;
    char* ok = resolved_.data();
    const auto fitWith = [&](auto w)
    {
        return dispatchDim(dim, [&](auto d)
        {
            return fitWeights<d>(*ref_, V, w, order_, L, intact, G_.data(), H, ok);
        });
    };
    const label nSingular = weights() == weighting::kernel
        ? fitWith(kernelWeight())
        : fitWith(gradientWeight());
    afterFit();
    return nSingular;
}


void Foam::meshless::correspondenceSolid::computeF(particleField& F) const
{
    const double* x = body_.particles().positions().data();
    dispatchDim(body_.dim(), [&](auto d)
    {
        correspondence::deformationGradient<d>(*ref_, G_.data(), X0_.data(), x, F.data());
    });
}


namespace
{

template<int Dim>
void stressOf
(
    const Foam::meshless::constitutiveLaw& law,
    const Foam::label n,
    const char* resolved,
    const double* F,
    const double* Fo,
    double* P
)
{
    using namespace Foam::meshless;
    #pragma omp parallel for schedule(static)
    for (Foam::label a = 0; a < n; ++a)
    {
        if (!resolved[a])
        {
            std::fill_n(P + a*Dim*Dim, Dim*Dim, 0.0);
            continue;
        }
        fromTensor<Dim>
        (
            law.stress(a, toTensor<Dim>(Fo, a), toTensor<Dim>(F, a)), a, P
        );
    }
}

} // End anonymous namespace


void Foam::meshless::correspondenceSolid::computeStress()
{
    const label n = body_.particles().size();
    const constitutiveLaw& law = law_();
    dispatchDim(body_.dim(), [&](auto d)
    {
        stressOf<d>(law, n, resolved_.data(), F_.data(), Fold_.data(), P_.data());
    });
    adjustStress();
}


void Foam::meshless::correspondenceSolid::commitLaw()
{
    const label n = body_.particles().size();
    const label dim = body_.dim();
    if (law_->incremental())
    {
        constitutiveLaw& law = law_();
        const double* F = F_.data();
        const double* Fo = Fold_.data();
        #pragma omp parallel for schedule(static)
        for (label a = 0; a < n; ++a)
        {
            if (resolved_[a])
            {
                law.commit(a, toTensor(Fo, a, dim), toTensor(F, a, dim));
            }
        }
    }
    std::copy(F_.data(), F_.data() + n*dim*dim, Fold_.data());
}


void Foam::meshless::correspondenceSolid::rebase()
{
    computeF(F_);
    std::copy(F_.data(), F_.data() + F_.size()*F_.nComponents(), Fold_.data());
    computeStress();
}


void Foam::meshless::correspondenceSolid::internalForce(double* f) const
{
    const double* V = V0_.data();
    dispatchDim(body_.dim(), [&](auto d)
    {
        correspondence::internalForce<d>(*ref_, G_.data(), V, P_.data(), f);
    });
}


bool Foam::meshless::correspondenceSolid::commitsState() const
{
    return law_->incremental();
}


void Foam::meshless::correspondenceSolid::evaluate
(
    const scalar t,
    const bool atEnd,
    costAccounting& costs
)
{
    const label n = body_.particles().size();
    const label dim = body_.dim();
    double* acc = acc_.data();
    {
        costAccounting::scope timer(costs, stressCost_);

        computeF(F_);
        computeStress();
        if (atEnd)
        {
            commitLaw();
            afterCommit();
        }
        internalForce(acc);
        addStabilisation(acc);
        adjustForce(acc);

        const double* fExt = fExt_.data();
        const double* m = mass_.data();
        #pragma omp parallel for schedule(static)
        for (label a = 0; a < n; ++a)
        {
            for (label i = 0; i < dim; ++i)
            {
                acc[a*dim + i] = (acc[a*dim + i] + fExt[a*dim + i])/m[a];
            }
        }
    }

    body_.addEffectAccelerations(t, acc_, costs);
    addWallContact(acc_);
    constraints_->addLoads(t, acc_);

    for (label a = 0; a < n; ++a)
    {
        if (!constraints_->isFree(a))
        {
            for (label i = 0; i < dim; ++i) acc[a*dim + i] = 0;
        }
    }
}


void Foam::meshless::correspondenceSolid::endStep(costAccounting& costs)
{
    if (!commitsState()) return;
    costAccounting::scope timer(costs, stressCost_);
    computeF(F_);
    computeStress();
    commitLaw();
    afterCommit();
}


void Foam::meshless::correspondenceSolid::referenceNormals
(
    particleField& N
) const
{
    dispatchDim(body_.dim(), [&](auto d)
    {
        correspondence::surfaceNormals<d>(*ref_, V0_.data(), N.data());
    });
}


void Foam::meshless::correspondenceSolid::deformationGradient
(
    particleField& F
) const
{
    computeF(F);
}


Foam::scalar Foam::meshless::correspondenceSolid::strainEnergy() const
{
    computeF(F_);
    const label n = body_.particles().size();
    const label dim = body_.dim();
    scalar W = 0;
    for (label a = 0; a < n; ++a)
    {
        if (isImage(a)) continue;
        W += V0_(a, 0)*law_->energyDensity(a, toTensor(F_.data(), a, dim));
    }
    return W + stabilisationEnergy();
}


// ************************************************************************* //
