/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "nosbPd.H"
#include "dispatchDim.H"
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
    addModelRole(nosbPd, solid);
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
    correspondenceSolid(body, dict),
    rho0_(body.density()),
    Gs_
    (
        (
            checkRenamed
            (
                dict,
                {
                    {"hourglassCoefficient", "hourglassControl"},
                    {"order", "gradientOrder"},
                    {"artificialViscosity", "bondViscosity"}
                }
            ),
            readNonNegative(dict, "hourglassControl")
        )
    ),
    alphaV_
    (
        dict.found("bondViscosity") ? readPositive(dict, "bondViscosity") : 0
    ),
    eta_(0),
    s0_(0),
    C_(0),
    damage_(body.particles().addField("damage", particleField::kind::scalar)),
    m_(body.particles().addScratchField("weightedVolume", particleField::kind::scalar)),
    Ws_(body.particles().addScratchField("Ws", particleField::kind::scalar)),
    nRead_(0)
{
    C_ = Gs_*law_->waveModulus();
    eta_ = alphaV_*rho0_*std::sqrt(law_->waveModulus()/rho0_)
       *body.kernel().h();
    readFailure();
}


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


void Foam::meshless::bodyModels::nosbPd::updateBonds()
{
    nosbPdOperators::weightedVolume
    (
        *ref_, intact_.data(), V0_.data(), m_.data()
    );
    families_->damage(V0_, damage_);
}


template<int Dim>
void Foam::meshless::bodyModels::nosbPd::stabilisationForce(double* f) const
{
    const double* x = body_.particles().positions().data();
    if (C_ > 0)
    {
        nosbPdOperators::stabilisationForce<Dim>
        (
            *ref_, intact_.data(), x, F_.data(), m_.data(), resolved_.data(),
            C_, V0_.data(), f
        );
    }
    if (eta_ > 0)
    {
        nosbPdOperators::bondViscosity<Dim>
        (
            *ref_, intact_.data(), x, U_.data(), m_.data(), eta_,
            body_.kernel().h(), V0_.data(), f
        );
    }
}


template<int Dim>
void Foam::meshless::bodyModels::nosbPd::stabilisationEnergyDensity() const
{
    nosbPdOperators::stabilisationEnergy<Dim>
    (
        *ref_, intact_.data(), body_.particles().positions().data(),
        F_.data(), m_.data(), resolved_.data(), C_, V0_.data(), Ws_.data()
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::bodyModels::nosbPd::setUpPairs(particleScene& scene)
{
    particleSet& set = body_.particles();

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

    families_.reset(new peridynamicFamilies(*ref_, intact_));
    const Time& runTime = scene.time();
    nRead_ = families_->readBroken(set, runTime, runTime.timeName());

    // A state written by this model has these broken already
    if (s0_ > 0) families_->breakBonds(set.positions().data(), s0_);
}


void Foam::meshless::bodyModels::nosbPd::afterFit()
{
    updateBonds();
}


void Foam::meshless::bodyModels::nosbPd::describeModel(Ostream& os) const
{
    os  << ", hourglassControl " << Gs_;
    if (eta_ > 0)
    {
        os  << ", bondViscosity " << alphaV_ << " (eta " << eta_ << " Pa s)";
    }
    if (s0_ > 0)
    {
        os  << ", critical stretch " << s0_ << " (" << nRead_
            << " broken bonds read)";
    }
}


Foam::scalar Foam::meshless::bodyModels::nosbPd::waveSpeed() const
{
    return std::sqrt(law_->waveModulus()*(1 + Gs_)/rho0_);
}


Foam::scalar Foam::meshless::bodyModels::nosbPd::stableDeltaT
(
    const scalar maxCo
) const
{
    scalar dt = correspondenceSolid::stableDeltaT(maxCo);
    if (eta_ > 0)
    {
        // The bond dashpots relax a particle's velocity at a rate of about
        // eta/(rho0 h^2): explicit stepping needs dt below its inverse.
        // Binding only for alpha > 1.
        const scalar h = body_.kernel().h();
        dt = min(dt, maxCo*rho0_*h*h/eta_);
    }
    return dt;
}


void Foam::meshless::bodyModels::nosbPd::addStabilisation(double* f)
{
    if (C_ <= 0 && eta_ <= 0) return;
    dispatchDim(body_.dim(), [&](auto d) { stabilisationForce<d>(f); });
}


Foam::scalar Foam::meshless::bodyModels::nosbPd::stabilisationEnergy() const
{
    dispatchDim(body_.dim(), [&](auto d) { stabilisationEnergyDensity<d>(); });
    scalar E = 0;
    for (label i = 0; i < Ws_.size(); ++i) E += V0_(i, 0)*Ws_(i, 0);
    return E;
}


bool Foam::meshless::bodyModels::nosbPd::commitsState() const
{
    return s0_ > 0 || correspondenceSolid::commitsState();
}


void Foam::meshless::bodyModels::nosbPd::afterCommit()
{
    // Bonds break at the end of an accepted step, the material state of
    // the step committed: the broken bonds change the fit (and F) but not
    // the material, so F and Fold are recomputed over the intact bonds at
    // the same positions and P from the committed stress
    if (s0_ <= 0) return;
    const label nBroken = families_->breakBonds
    (
        body_.particles().positions().data(), s0_
    );
    if (nBroken)
    {
        fit();
        rebase();
    }
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
