/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "tlsph.H"
#include "dispatchDim.H"
#include "tlsphOperators.H"
#include "particleScene.H"
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
    addModelRole(tlsph, solid);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::bodyModels::tlsph::tlsph
(
    particleBody& body,
    const dictionary& dict
)
:
    correspondenceSolid(body, dict),
    hourglass_
    (
        (
            checkRenamed(dict, {{"subSteps", "minSubSteps"}}),
            readNonNegativeOrDefault(dict, "hourglassControl", 0)
        )
    ),
    viscosity_(readNonNegativeOrDefault(dict, "viscosity", 0)),
    taylor_(false),
    c_(std::sqrt(law_->waveModulus()/body.density()))
{
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
        const label d3 = body.dim()*body.dim()*body.dim();
        gradEps_.assign(body.particles().size()*d3, 0);
        gradStress_.assign(body.particles().size()*d3, 0);
        secondDerivatives_ = true;
    }
    else if (integration != "midpoint")
    {
        FatalIOErrorInFunction(dict)
            << "nodalIntegration " << integration << ": expected midpoint"
            << " (the default) or taylor" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::meshless::bodyModels::tlsph::setUpPairs(particleScene&)
{
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
}


void Foam::meshless::bodyModels::tlsph::afterFit()
{
    // Particles whose order 2 fit fell back to order 1 have no strain
    // gradient: no Taylor term, so nothing resists their zero-energy modes
    if (!taylor_) return;
    const label dim = body_.dim();
    label flat = 0;
    for (label a = 0; a < ref_->size(); ++a)
    {
        bool any = false;
        for (label q = ref_->offset(a); q < ref_->offset(a + 1); ++q)
        {
            for (label k = 0; k < dim*dim; ++k) any = any || H_[q*dim*dim + k] != 0;
        }
        if (!any) ++flat;
    }
    if (flat)
    {
        WarningInFunction
            << "Body " << body_.name() << ": " << flat << " particles"
            << " without a second-order fit (too few neighbours off a line):"
            << " the Taylor integration does not stabilise them" << endl;
    }
}


template<int Dim>
Foam::scalar Foam::meshless::bodyModels::tlsph::strainGradientStress() const
{
    const label n = body_.particles().size();
    constexpr label D3 = Dim*Dim*Dim;
    tlsphOperators::strainGradient<Dim>
    (
        *ref_, H_.data(), X0_.data(), body_.particles().positions().data(),
        gradEps_.data()
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
void Foam::meshless::bodyModels::tlsph::stabilisation(double* f)
{
    if (taylor_)
    {
        strainGradientStress<Dim>();
        tlsphOperators::strainGradientForce<Dim>
        (
            *ref_, H_.data(), gradStress_.data(), f
        );
    }
    if (viscosity_ > 0)
    {
        tlsphOperators::viscousForce<Dim>
        (
            *ref_, V0_.data(), body_.particles().positions().data(),
            U_.data(), viscosity_, f,
            image_.empty() ? nullptr : image_.data()
        );
    }
    if (hourglass_ > 0)
    {
        tlsphOperators::hourglassForce<Dim>
        (
            *ref_, V0_.data(), body_.particles().positions().data(),
            F_.data(), 0.5*hourglass_*law_->elastic().E(), f,
            law_->geometricallyLinear(),
            image_.empty() ? nullptr : image_.data()
        );
    }
}


template<int Dim>
Foam::scalar Foam::meshless::bodyModels::tlsph::hourglassEnergy() const
{
    energy_.resize(body_.particles().size());
    return tlsphOperators::hourglassEnergy<Dim>
    (
        *ref_, V0_.data(), body_.particles().positions().data(), F_.data(),
        0.5*hourglass_*law_->elastic().E(), energy_.data(),
        law_->geometricallyLinear(), image_.empty() ? nullptr : image_.data()
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::bodyModels::tlsph::addStabilisation(double* f)
{
    dispatchDim(body_.dim(), [&](auto d) { stabilisation<d>(f); });
}


Foam::scalar Foam::meshless::bodyModels::tlsph::stabilisationEnergy() const
{
    // F_ holds F of the current positions (strainEnergy computed it)
    const label dim = body_.dim();
    scalar W = 0;
    if (taylor_)
    {
        W += dispatchDim(dim, [&](auto d) { return strainGradientStress<d>(); });
    }
    if (hourglass_ > 0)
    {
        W += dispatchDim(dim, [&](auto d) { return hourglassEnergy<d>(); });
    }
    return W;
}


void Foam::meshless::bodyModels::tlsph::adjustStress()
{
    dispatchDim(body_.dim(), [&](auto d)
    {
        tlsphOperators::clearImageStress<d>(mirrors_, P_.data());
    });
}


void Foam::meshless::bodyModels::tlsph::adjustForce(double* f)
{
    dispatchDim(body_.dim(), [&](auto d)
    {
        tlsphOperators::foldImageForces<d>(mirrors_, f);
    });
}


Foam::scalar Foam::meshless::bodyModels::tlsph::viscousDeltaT() const
{
    if (viscosity_ <= 0) return GREAT;
    const scalar h = body_.kernel().h();
    return 0.125*body_.density()*h*h/((body_.dim() + 2)*viscosity_);
}


void Foam::meshless::bodyModels::tlsph::describeModel(Ostream& os) const
{
    os  << ", hourglassControl " << hourglass_;
    if (viscosity_ > 0) os << ", viscosity " << viscosity_ << " Pa s";
    if (taylor_) os << ", Taylor nodal integration";
}


// ************************************************************************* //
