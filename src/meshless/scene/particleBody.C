/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "particleBody.H"
#include "bodyModel.H"
#include "effect.H"
#include "lagrangianIO.H"
#include "restartManifest.H"
#include "particleDistribution.H"
#include "dictionaryChecks.H"
#include "OSspecific.H"
#include "PstreamCombineReduceOps.H"
#include "HashTable.H"
#include <cmath>

Foam::meshless::particleBody::particleBody
(
    const word& name,
    const dictionary& dict,
    const label dim,
    const Time& runTime
)
:
    name_(name),
    dict_(dict),
    set_(name, dim),
    spacing_(0),
    density_(readPositive(dict, "density")),
    kernel_(),
    model_(),
    effects_(),
    modelCost_(-1),
    effectCosts_()
{
    // A restart: every field and file the time's manifest lists
    restartManifest::checkBody(runTime, runTime.timeName(), name);

    const fileName cloudDir =
        runTime.path()/runTime.timeName()/lagrangianIO::cloudLocal(name);
    // positions (seeded, written) or the exact position field alone (a
    // processor's cloud from decomposePar)
    const bool here =
        isFile(cloudDir/particleSet::positionsName)
     || isFile(cloudDir/lagrangianIO::exactPositionName);

    // In a parallel run a processor holds no cloud of a body none of whose
    // particles is in its part (decomposePar writes none)
    const bool anywhere =
        Pstream::parRun() ? returnReduce(here, orOp<bool>()) : here;
    if (!anywhere)
    {
        FatalIOErrorInFunction(dict)
            << "Body '" << name << "' has no particles at time "
            << runTime.timeName() << " (no " << cloudDir.name()
            << " cloud): expected one of the seeded bodies "
            << lagrangianIO::clouds(runTime, runTime.timeName())
            << ". Run seedParticles, or correct the body name."
            << exit(FatalIOError);
    }
    if (here)
    {
        lagrangianIO::read(set_, runTime, runTime.timeName());
        // A cloud of decomposePar or reconstructPar: ParaView's reader
        // needs the legacy positions these utilities do not write
        lagrangianIO::addLegacyPositions
        (
            runTime, runTime.timeName(), name
        );
    }
    if (Pstream::parRun()) unifyFields();

    if (dict.found("spacing"))
    {
        spacing_ = readPositive(dict, "spacing");
    }
    else if (set_.found("volume"))
    {
        // Seeded volumes are equal: take that value, not a mean whose last
        // bits depend on the count (a restart of a body that gained or
        // lost particles through an open boundary would change h). Over
        // every processor's particles in a parallel run.
        const particleField& V = set_.field("volume");
        scalar sum = 0;
        scalar lo = GREAT;
        scalar hi = -GREAT;
        label n = set_.size();
        for (label i = 0; i < set_.size(); ++i)
        {
            sum += V(i, 0);
            lo = min(lo, V(i, 0));
            hi = max(hi, V(i, 0));
        }
        if (Pstream::parRun())
        {
            reduce(sum, sumOp<scalar>());
            reduce(lo, minOp<scalar>());
            reduce(hi, maxOp<scalar>());
            reduce(n, sumOp<label>());
        }
        if (n == 0)
        {
            FatalIOErrorInFunction(dict)
                << "Body '" << name << "' has an empty cloud: expected"
                << " 'spacing', or particles to derive it from"
                << exit(FatalIOError);
        }
        const scalar mean = hi - lo <= 1e-12*hi ? lo : sum/n;
        spacing_ = std::pow(mean, 1.0/dim);
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Body '" << name << "': no 'spacing' given and its cloud has"
            << " no volume field to derive it from: expected 'spacing'"
            << exit(FatalIOError);
    }

    if (dict.found("kernel"))
    {
        kernel_ = smoothingKernel::New(dict.subDict("kernel"), dim, spacing_);
    }
}


Foam::meshless::particleBody::~particleBody()
{}


void Foam::meshless::particleBody::unifyFields()
{
    // Every processor's fields by name and kind: a processor without a
    // cloud of the body (or without a field another read) adds them empty
    HashTable<label, word> kinds;
    for (const word& f : set_.fieldNames())
    {
        kinds.set(f, label(set_.field(f).fieldKind()));
    }
    Pstream::mapCombineGather(kinds, maxEqOp<label>());
    Pstream::mapCombineScatter(kinds);
    for (const word& f : kinds.sortedToc())
    {
        if (!set_.found(f))
        {
            set_.addField(f, particleField::kind(kinds[f]));
        }
        else if (label(set_.field(f).fieldKind()) != kinds[f])
        {
            FatalIOErrorInFunction(dict_)
                << "Body '" << name_ << "': field " << f << " is a "
                << particleField::kindNames[set_.field(f).fieldKind()]
                << " on processor " << Pstream::myProcNo() << " and a "
                << particleField::kindNames[particleField::kind(kinds[f])]
                << " on another: expected the same cloud fields on every"
                << " processor" << exit(FatalIOError);
        }
    }
}


void Foam::meshless::particleBody::select(costAccounting& costs)
{
    model_ = bodyModel::New(*this, dict_);
    modelCost_ = costs.part(name_ + "." + dict_.get<word>("model"));

    if (dict_.found("effects"))
    {
        const dictionary& effectsDict = dict_.subDict("effects");
        for (const entry& e : effectsDict)
        {
            if (!e.isDict())
            {
                FatalIOErrorInFunction(effectsDict)
                    << "Entry '" << e.keyword() << "' in 'effects': expected"
                    << " a dictionary, e.g. " << e.keyword() << " { ... }"
                    << exit(FatalIOError);
            }
            effects_.append(effect::New(e.keyword(), e.dict(), *this));
            effectCosts_.append(costs.part(name_ + "." + e.keyword()));

            const List<bodyModel::modelRole> roles = effects_.last().roles();
            const bodyModel::modelRole role = model_->role();
            wordList models = effects_.last().models();
            const word modelType = dict_.get<word>("model");
            if
            (
                !roles.found(role)
             || (models.size() && !models.found(modelType))
            )
            {
                if (models.empty())
                {
                    for (const bodyModel::modelRole r : roles)
                    {
                        models.append(bodyModel::modelsOf(r));
                    }
                }
                FatalIOErrorInFunction(e.dict())
                    << "Effect '" << e.keyword() << "' of body '" << name_
                    << "' does not apply to its model "
                    << dict_.get<word>("model") << " (a "
                    << bodyModel::modelRoleNames[role] << "): expected a body of"
                    << " one of the models " << models << exit(FatalIOError);
            }
        }
    }
}


Foam::meshless::bodyModel& Foam::meshless::particleBody::model()
{
    return *model_;
}


const Foam::meshless::bodyModel& Foam::meshless::particleBody::model() const
{
    return *model_;
}


const Foam::meshless::smoothingKernel&
Foam::meshless::particleBody::kernel() const
{
    if (!kernel_.valid())
    {
        FatalIOErrorInFunction(dict_)
            << "Body '" << name_ << "': its model needs a smoothing kernel;"
            << " expected a 'kernel' dictionary (type, smoothingLengthRatio)"
            << exit(FatalIOError);
    }
    return *kernel_;
}


Foam::meshless::particleField& Foam::meshless::particleBody::requireField
(
    const word& fieldName,
    const word& requester
)
{
    if (!set_.found(fieldName))
    {
        FatalIOErrorInFunction(dict_)
            << "Body '" << name_ << "': " << requester << " needs the field "
            << fieldName << ", which model " << dict_.get<word>("model")
            << " does not provide (fields: " << set_.fieldNames() << ")"
            << exit(FatalIOError);
    }
    return set_.field(fieldName);
}


void Foam::meshless::particleBody::addEffectAccelerations
(
    const scalar t,
    particleField& acc,
    costAccounting& costs
) const
{
    forAll(effects_, i)
    {
        costAccounting::scope timer(costs, effectCosts_[i]);
        effects_[i].addAcceleration(t, acc);
    }
}


void Foam::meshless::particleBody::addPairEffectAccelerations
(
    const pairContext& ctx,
    particleField& acc,
    costAccounting& costs
) const
{
    forAll(effects_, i)
    {
        costAccounting::scope timer(costs, effectCosts_[i]);
        effects_[i].addPairAcceleration(ctx, acc);
    }
}


bool Foam::meshless::particleBody::correctsAt(const label timeIndex) const
{
    for (const effect& e : effects_)
    {
        if (e.correctsAt(timeIndex)) return true;
    }
    return false;
}


void Foam::meshless::particleBody::correctEffects
(
    const pairContext& ctx,
    const label timeIndex,
    costAccounting& costs
) const
{
    forAll(effects_, i)
    {
        costAccounting::scope timer(costs, effectCosts_[i]);
        effects_[i].correct(ctx, timeIndex);
    }
}


Foam::label Foam::meshless::particleBody::costPart(const effect& e) const
{
    forAll(effects_, i)
    {
        if (&effects_[i] == &e) return effectCosts_[i];
    }
    FatalErrorInFunction
        << "Effect " << e.name() << " is not one of body " << name_
        << exit(FatalError);
    return -1;
}


Foam::scalar Foam::meshless::particleBody::maxDeltaT(const scalar maxCo) const
{
    return min(model_->maxDeltaT(maxCo), effectsDeltaT());
}


Foam::scalar Foam::meshless::particleBody::effectsDeltaT() const
{
    scalar dt = GREAT;
    for (const effect& e : effects_)
    {
        dt = min(dt, e.maxDeltaT());
    }
    return dt;
}


void Foam::meshless::particleBody::advance
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    costAccounting::scope timer(costs, modelCost_);
    model_->advance(t, dt, costs);
}


void Foam::meshless::particleBody::describe(Ostream& os) const
{
    os  << "    " << name_ << ": "
        << particleDistribution::globalSize(set_) << " particles, spacing "
        << spacing_ << ", density " << density_ << ", model "
        << dict_.get<word>("model");
    if (kernel_.valid())
    {
        os  << ", kernel " << dict_.subDict("kernel").get<word>("type")
            << " (h " << kernel_->h() << ")";
    }
    os  << nl;
    if (effects_.empty())
    {
        os  << "        effects: none" << nl;
    }
    for (const effect& e : effects_)
    {
        os  << "        effect " << e.name() << ": ";
        e.describe(os);
        os  << nl;
    }
}
