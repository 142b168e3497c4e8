/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ulphPd.H"
#include "particleScene.H"
#include "fluidModel.H"
#include "solidModel.H"
#include "dictionaryChecks.H"
#include "OSspecific.H"
#include "addToRunTimeSelectionTable.H"
#include <cmath>

namespace Foam
{
namespace meshless
{
namespace couplings
{
    defineTypeNameAndDebug(ulphPd, 0);
    addToRunTimeSelectionTable(fsiCoupling, ulphPd, dictionary);
}
}
}


Foam::meshless::couplings::ulphPd::ulphPd
(
    const dictionary& dict,
    particleScene& scene
)
:
    fsiCoupling(dict, scene),
    fluidBody_(&fluidBody("fluid")),
    fluid_(fluidBody_->model().fluid()),
    subSteps_
    (
        "coupling ulphPd",
        dict.found("minSubSteps") ? readPositiveLabel(dict, "minSubSteps") : 1,
        "solid sub-steps per fluid step"
    )
{
    const word accType
    (
        dict.getOrDefault<word>("solidAcceleration", "none")
    );
    if (accType != "none" && accType != "step")
    {
        FatalIOErrorInFunction(dict)
            << "coupling ulphPd: solidAcceleration " << accType
            << ": expected none or step" << exit(FatalIOError);
    }
    const bool stepAcc = accType == "step";
    const wordList solids(dict.get<wordList>("solids"));
    if (solids.empty())
    {
        FatalIOErrorInFunction(dict)
            << "coupling ulphPd: 'solids' is empty: expected at least one"
            << " solid body (" << bodyModel::modelsOf(bodyModel::modelRole::solid)
            << ")" << exit(FatalIOError);
    }
    for (const word& name : solids)
    {
        particleBody& sb = solidBody(name);
        solidBodies_.append(&sb);
        // Written when used (restart state of the solid's ghosts)
        stepAcceleration_.push_back
        (
            stepAcc
          ? &sb.particles().addField
            (
                "stepAcceleration",
                particleField::kind::vector
            )
          : &sb.particles().addScratchField
            (
                "stepAcceleration",
                particleField::kind::vector
            )
        );
        U0_.emplace_back(sb.particles().size()*sb.dim());
        ghosts_.emplace_back
        (
            new deformingGhost(sb, stepAcc ? "stepAcceleration" : "")
        );
        ghosts_.back()->requestReaction();
        fluid_->addBoundary(*ghosts_.back());
    }
}


bool Foam::meshless::couplings::ulphPd::couples(const particleBody& b) const
{
    if (&b == fluidBody_) return true;
    for (const particleBody* s : solidBodies_)
    {
        if (&b == s) return true;
    }
    return false;
}


Foam::scalar Foam::meshless::couplings::ulphPd::maxDeltaT
(
    const scalar maxCo
) const
{
    maxCo_ = maxCo;
    return fluidBody_->maxDeltaT(maxCo);
}


Foam::vector Foam::meshless::couplings::ulphPd::total(const particleField& f)
{
    vector s(Zero);
    for (label i = 0; i < f.size(); ++i)
    {
        for (label d = 0; d < f.nComponents(); ++d) s[d] += f(i, d);
    }
    return s;
}


void Foam::meshless::couplings::ulphPd::writeForces
(
    const scalar t,
    const label nSub
)
{
    if (!forces_.valid())
    {
        const Time& runTime = scene_.time();
        const fileName dir =
            runTime.globalPath()/"postProcessing"/"coupling"
           /runTime.timeName(runTime.startTime().value());
        mkDir(dir);
        forces_.reset(new OFstream(dir/"forces.dat"));
        OFstream& os = forces_();
        os  << "# ulphPd coupling: per solid, the fluid's force on the solid"
            << " and the solid's force on the fluid (fluid's sum)" << nl
            << "# time";
        for (const particleBody* s : solidBodies_)
        {
            os  << tab << s->name() << ":onSolid(x y z)" << tab
                << s->name() << ":onFluid(x y z)";
        }
        os  << tab << "subSteps" << endl;
    }
    OFstream& os = forces_();
    os  << t;
    forAll(solidBodies_, k)
    {
        const vector onSolid =
            total(solidBodies_[k]->model().solid()->externalForce());
        const vector onFluid = fluid_->forceOnFluid(*ghosts_[k]);
        for (direction d = 0; d < 3; ++d) os << tab << onSolid[d];
        for (direction d = 0; d < 3; ++d) os << tab << onFluid[d];
    }
    os  << tab << nSub << endl;
}


void Foam::meshless::couplings::ulphPd::advance
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    // Fluid over [t, t + dt] against the solids at t
    for (auto& g : ghosts_) g->update();
    fluidBody_->advance(t, dt, costs);

    // Solids over the same interval, with the fluid's force of the
    // corrector (the one that moved the fluid)
    forAll(solidBodies_, k)
    {
        particleField& fExt = solidBodies_[k]->model().solid()->externalForce();
        const double* R = ghosts_[k]->reaction();
        std::copy(R, R + fExt.size()*fExt.nComponents(), fExt.data());
    }
    const label nSub = solidSteps(solidBodies_, dt, subSteps_);

    forAll(solidBodies_, k)
    {
        const particleField& U = solidBodies_[k]->particles().field("U");
        std::vector<double>& U0 = U0_[k];
        std::copy(U.data(), U.data() + U0.size(), U0.begin());
    }
    stepSolids(solidBodies_, t, dt, nSub, costs);
    forAll(solidBodies_, k)
    {
        const particleField& U = solidBodies_[k]->particles().field("U");
        const std::vector<double>& U0 = U0_[k];
        double* a = stepAcceleration_[k]->data();
        for (size_t c = 0; c < U0.size(); ++c)
        {
            a[c] = (U.data()[c] - U0[c])/dt;
        }
    }
    writeForces(t + dt, nSub);
}


void Foam::meshless::couplings::ulphPd::describe(Ostream& os) const
{
    os  << "    coupling ulphPd: fluid " << fluidBody_->name()
        << ", solids (";
    forAll(solidBodies_, k)
    {
        os  << (k ? " " : "") << solidBodies_[k]->name();
    }
    os  << "), solid particles as the fluid's ghosts, reaction of eq. 58 on"
        << " the solids, minSubSteps " << subSteps_.minSubSteps() << nl;
}


// ************************************************************************* //
