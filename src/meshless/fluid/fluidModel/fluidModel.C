/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "fluidModel.H"
#include "haloHook.H"
#include "openBoundary.H"
#include "particleScene.H"
#include "effect.H"
#include "gravity.H"
#include "dictionaryChecks.H"
#include "particleExpression.H"
#include "StringStream.H"
#include <algorithm>
#include <cmath>

const Foam::Enum<Foam::meshless::fluidModel::initialStateType>
Foam::meshless::fluidModel::initialStateNames
({
    { initialStateType::rest, "rest" },
    { initialStateType::hydrostatic, "hydrostatic" },
});


Foam::meshless::fluidModel::fluidModel
(
    particleBody& body,
    const dictionary& dict
)
:
    bodyModel(body, dict),
    rho0_(body.density()),
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
    mass_(body.requireField("mass", "a fluid model")),
    V0_(body.requireField("volume", "a fluid model")),
    V_(body.particles().addScratchField("Vcurrent", particleField::kind::scalar)),
    time_(nullptr),
    relations_(nullptr),
    g_(Zero),
    own_(nullptr),
    rhoMin_(0),
    emptied_(-1),
    emptiedRho_(0)
{
    body.kernel();      // required: FatalIOError naming the body if absent

    // A cloud seeded without density starts at the reference density
    bool anyRho = false;
    for (label i = 0; i < rho_.size(); ++i) anyRho = anyRho || rho_(i, 0) != 0;
    if (!anyRho) rho_.fill(rho0_);

    // A fresh cloud's velocity field (a restart reads its own)
    if (freshStart_ && dict.found("initialVelocity"))
    {
        particleExpression::evaluate
        (
            dict.subDict("initialVelocity"),
            body.particles().positions(),
            U_
        );
    }
}


void Foam::meshless::fluidModel::connect(particleScene& scene)
{
    time_ = &scene.time();
    relations_ = &scene.relations();

    if (const auto* grav = findEffect<effects::gravity>(body_))
    {
        g_ = grav->value();
    }

    // An incompressible fluid's density does not follow its pressure: it
    // takes minPressure as a floor of its own (isph)
    if (dict_.found("minPressure") && soundSpeed() < GREAT)
    {
        // The pressure of an empty particle bounds the equation of state
        const scalar pMin = dict_.get<scalar>("minPressure");
        const scalar pEmpty = pressureOf(0);
        if (pMin <= pEmpty)
        {
            FatalIOErrorInFunction(dict_)
                << "minPressure " << pMin << ": expected a pressure above"
                << " that of zero density, " << pEmpty << " Pa"
                << exit(FatalIOError);
        }
        rhoMin_ = densityOf(pMin);
    }

    own_ = &relations_->inner
    (
        body_.name(), body_.particles().positions(), body_.kernel(), skin_,
        true, neighbourRelation::separation | neighbourRelation::kernelValue
    );
    for (const word& name : wallNames_)
    {
        particleBody& wb = scene.body(name, dict_);
        ghostBoundary* wall = dynamic_cast<ghostBoundary*>(&wb.model());
        if (!wall || wb.model().role() != modelRole::wall)
        {
            FatalIOErrorInFunction(dict_)
                << "Body '" << name << "' in 'walls' has model "
                << wb.dict().get<word>("model") << ": expected ghostWall"
                << exit(FatalIOError);
        }
        attach(*wall, true);
    }
    setContext();

    connectModel(scene);

    // Sound speed against c0 >= 10 sqrt(2 g H) (ULPH-NOSBPD eq. 7) for the
    // column the fluid starts as
    const scalar gMag = mag(g_);
    if (gMag > 0 && soundSpeed() < GREAT)
    {
        scalar lo, hi;
        heightRange(lo, hi);
        const scalar H = hi - lo + body_.spacing();
        const scalar c0min = 10*std::sqrt(2*gMag*H);
        if (soundSpeed() < c0min)
        {
            WarningInFunction
                << "Body " << body_.name() << ": soundSpeed " << soundSpeed()
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
    // A weakly compressible fluid's pressure follows from its density; an
    // incompressible one keeps its own (hydrostatic, or a restart's)
    if (soundSpeed() < GREAT)
    {
        for (label i = 0; i < rho_.size(); ++i)
        {
            p_(i, 0) = pressureOf(rho_(i, 0));
        }
    }
}


void Foam::meshless::fluidModel::attach(ghostBoundary& ghosts, const bool wall)
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
    ghosts.prepare(W, *relations_);

    const unsigned geometry =
        neighbourRelation::separation | neighbourRelation::kernelValue;
    const particleField& x = body_.particles().positions();
    const particleField& xg = gb.particles().positions();
    boundaries_.push_back
    (
        boundary
        {
            &ghosts,
            &relations_->contact
            (
                body_.name() + " to " + gb.name(), x, xg, W, skin_,
                true, ghosts.moving(), geometry
            ),
            &relations_->contact
            (
                gb.name() + " to " + body_.name(), xg, x, W, skin_,
                ghosts.moving(), true, geometry
            ),
            wall,
            Zero
        }
    );
}


void Foam::meshless::fluidModel::addBoundary(ghostBoundary& ghosts)
{
    attach(ghosts, false);
    boundaryAdded(boundaries_.back());
    setContext();
}


Foam::vector Foam::meshless::fluidModel::forceOnFluid
(
    const ghostBoundary& ghosts
) const
{
    for (const boundary& b : boundaries_)
    {
        if (b.ghosts == &ghosts) return b.forceOnFluid;
    }
    FatalErrorInFunction
        << "Fluid " << body_.name() << " has no such boundary"
        << exit(FatalError);
    return Zero;
}


void Foam::meshless::fluidModel::addOpenBoundary(openBoundary& ob)
{
    if (!takesOpenBoundaries())
    {
        FatalIOErrorInFunction(body_.dict())
            << "Fluid " << body_.name() << " (model " << type()
            << ") takes no open boundary (open boundary " << ob.name()
            << "): expected a model that does (riemannWcsph)"
            << exit(FatalIOError);
    }
    openBoundaries_.push_back(&ob);
}


void Foam::meshless::fluidModel::resized()
{
    setContext();
    resizedModel();
}


void Foam::meshless::fluidModel::selectOpenBoundaries(const scalar t)
{
    for (openBoundary* ob : openBoundaries_) ob->select(t);
}


void Foam::meshless::fluidModel::constrainOpenBoundaries(const scalar t)
{
    for (openBoundary* ob : openBoundaries_)
    {
        ob->constrain(t, U_.data(), rho_.data());
    }
}


void Foam::meshless::fluidModel::setContext()
{
    const particleSet& set = body_.particles();
    ctx_.dim = body_.dim();
    ctx_.W = &body_.kernel();
    ctx_.n = set.size();
    ctx_.U = U_.data();
    ctx_.rho = rho_.data();
    ctx_.mass = mass_.data();
    ctx_.rho0 = rho0_;
    ctx_.c0 = soundSpeed();

    const size_t nSrc = 1 + boundaries_.size();
    ctx_.sources.resize(nSrc);
    ctx_.Usrc.resize(nSrc);
    ctx_.massSrc.resize(nSrc);
    ctx_.wallSource.assign(nSrc, false);
    ctx_.Uown.resize(nSrc);
    ctx_.noSlip.assign(nSrc, true);

    ctx_.sources[0] = {own_, V_.data()};
    ctx_.Usrc[0] = U_.data();
    ctx_.massSrc[0] = mass_.data();
    ctx_.Uown[0] = U_.data();
    for (size_t k = 0; k < boundaries_.size(); ++k)
    {
        const ghostBoundary& g = *boundaries_[k].ghosts;
        ctx_.sources[k + 1] = {boundaries_[k].toGhosts, g.V()};
        ctx_.Usrc[k + 1] = g.Uvisc();
        ctx_.massSrc[k + 1] = g.mass();
        ctx_.wallSource[k + 1] = boundaries_[k].wall;
        ctx_.Uown[k + 1] = g.U();
        ctx_.noSlip[k + 1] = g.slipNormals() == nullptr;
    }
}


void Foam::meshless::fluidModel::moveBoundaries(const scalar t)
{
    for (boundary& b : boundaries_) b.ghosts->moveTo(t);
}


void Foam::meshless::fluidModel::updateGeometry()
{
    // The halo particles where their processors moved them
    refreshHalos();
    own_->updateGeometry();
    for (boundary& b : boundaries_)
    {
        b.toGhosts->updateGeometry();
        b.fromGhosts->updateGeometry();
    }
}


Foam::label Foam::meshless::fluidModel::releaseSplash()
{
    refreshHalos();
    const label n = p_.size();
    const label dim = body_.dim();
    const label* off = own_->offsetData();
    const label* idx = own_->indexData();
    const double* x = body_.particles().positions().data();
    const double R2 = sqr(body_.kernel().radius());
    const bool compressible = soundSpeed() < GREAT;
    const double rhoAmbient = compressible ? densityOf(0) : rho0_;
    const double* m = mass_.data();
    double* p = p_.data();
    double* rho = rho_.data();
    double* V = V_.data();
    label released = 0;

    #pragma omp parallel for schedule(static) reduction(+:released)
    for (label i = 0; i < n; ++i)
    {
        if (p[i] == 0 && (!compressible || rho[i] == rhoAmbient)) continue;
        bool alone = true;
        for (label q = off[i]; q < off[i + 1] && alone; ++q)
        {
            const label j = idx[q];
            double d2 = 0;
            for (label c = 0; c < dim; ++c)
            {
                d2 += sqr(x[j*dim + c] - x[i*dim + c]);
            }
            alone = !(d2 < R2);
        }
        if (!alone) continue;
        p[i] = 0;
        if (compressible)
        {
            rho[i] = rhoAmbient;
            V[i] = m[i]/rhoAmbient;
        }
        ++released;
    }
    return released;
}


void Foam::meshless::fluidModel::interpolateBoundaries()
{
    for (boundary& b : boundaries_)
    {
        b.ghosts->interpolate
        (
            *b.fromGhosts, p_.data(), rho_.data(), U_.data(), V_.data(), g_,
            soundSpeed(), rho0_
        );
    }
}


Foam::scalar Foam::meshless::fluidModel::height(const label i) const
{
    const vector up = -g_/mag(g_);
    const particleField& x = body_.particles().positions();
    scalar s = 0;
    for (label d = 0; d < body_.dim(); ++d) s += up[d]*x(i, d);
    return s;
}


void Foam::meshless::fluidModel::heightRange(scalar& lo, scalar& hi) const
{
    lo = GREAT;
    hi = -GREAT;
    for (label i = 0; i < body_.particles().size(); ++i)
    {
        lo = min(lo, height(i));
        hi = max(hi, height(i));
    }
    // Over every processor's particles (its halo holds others' own)
    reduce(lo, minOp<scalar>());
    reduce(hi, maxOp<scalar>());
}


void Foam::meshless::fluidModel::hydrostaticStart()
{
    scalar lo, top;
    heightRange(lo, top);
    top += 0.5*body_.spacing();
    const particleField& x = body_.particles().positions();

    for (label i = 0; i < x.size(); ++i)
    {
        const scalar p = rho0_*mag(g_)*(top - height(i));
        p_(i, 0) = p;
        rho_(i, 0) = densityOf(p);
        mass_(i, 0) = rho_(i, 0)*V0_(i, 0);
    }
}


void Foam::meshless::fluidModel::updateDensity
(
    const double* rhoOld,
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
    const double rhoMin = rhoMin_;
    label bad = -1;
    #pragma omp parallel for schedule(static) reduction(max:bad)
    for (label i = 0; i < n; ++i)
    {
        const double r = std::max(rhoOld[i] + dt*drho[i], rhoMin);
        if (!(r <= floor))
        {
            rho[i] = r;
        }
        else
        {
            rho[i] = rhoOld[i];
            bad = std::max(bad, i);
        }
    }
    if (bad >= 0 && emptied_ < 0)
    {
        emptied_ = bad;
        emptiedRho_ = rhoOld[bad] + dt*drho[bad];
    }
}


Foam::string Foam::meshless::fluidModel::blowUp() const
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
    os  << ") would have density " << emptiedRho_ << " kg/m^3 (continuity):"
        << " its neighbours move apart faster than the step follows, as"
        << " when a particle is thrown out with too few neighbours." << nl
        << "    Likely causes: a time step above the stable one (lower"
        << " deltaT or maxCo), too little artificial viscosity; a"
        << " 'minPressure' bounds the density from below.";
    return os.str();
}


// ************************************************************************* //
