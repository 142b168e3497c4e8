/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "energy.H"
#include "particleScene.H"
#include "bodyModel.H"
#include "gravity.H"
#include "restartManifest.H"
#include "ghostWall.H"
#include "particleDistribution.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace monitors
{
    defineTypeNameAndDebug(energy, 0);
    addToRunTimeSelectionTable(monitor, energy, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::monitors::energy::energy
(
    const word& name,
    const dictionary& dict,
    const particleScene& scene
)
:
    monitor(name, dict, scene),
    frame_(nullptr),
    frameWork_(0),
    framePower_(0),
    frameTime_(-GREAT)
{
    particleScene& s = const_cast<particleScene&>(scene);
    if (dict.found("frame"))
    {
        const word f = dict.get<word>("frame");
        frame_ = dynamic_cast<bodyModels::ghostWall*>(&s.body(f, dict).model());
        if (!frame_ || !frame_->moving())
        {
            FatalIOErrorInFunction(dict)
                << "frame " << f << ": expected a moving wall (model"
                << " ghostWall with a motion dictionary), whose frame the"
                << " energies are seen from" << exit(FatalIOError);
        }
        if (dict.getOrDefault<label>("interval", 1) != 1)
        {
            FatalIOErrorInFunction(dict)
                << "interval " << dict.get<label>("interval")
                << ": the frame's work is integrated over the samples,"
                << " expected interval 1 (every step) with frame" << nl
                << exit(FatalIOError);
        }
    }
    if (dict.found("bodies"))
    {
        for (const word& b : dict.get<wordList>("bodies"))
        {
            bodies_.append(&s.body(b, dict));
        }
    }
    else
    {
        for (const particleBody& b : scene.bodies())
        {
            if (b.model().moves()) bodies_.append(&b);
        }
    }
    potential0_ = scalarList(bodies_.size(), Zero);
    forAll(bodies_, k)
    {
        potential0_[k] = potential(*bodies_[k]);
    }

    // A restart: the references of the run's first sample
    const Time& runTime = scene.time();
    const dictionary* state = restartState();
    const dictionary* refs = state ? state->findDict("potential0") : nullptr;
    if (frame_ && state && state->found("frameWork"))
    {
        frameWork_ = state->get<scalar>("frameWork");
        framePower_ = state->get<scalar>("framePower");
        frameTime_ = state->get<scalar>("frameTime");
    }
    if (refs)
    {
        forAll(bodies_, k)
        {
            const word& b = bodies_[k]->name();
            if (refs->found(b))
            {
                potential0_[k] = refs->get<scalar>(b);
            }
            else
            {
                WarningInFunction
                    << "Monitor " << name << ": no potential energy"
                    << " reference of body " << b << " in "
                    << runTime.timeName()/"uniform"/stateName
                    << ": its potential starts from zero at time "
                    << runTime.timeName() << endl;
            }
        }
    }
    else if (restartManifest::found(runTime, runTime.timeName()))
    {
        WarningInFunction
            << "Monitor " << name << ": the restart time "
            << runTime.timeName() << " holds no potential energy reference"
            << " (written before monitors kept one): the potential starts"
            << " from zero at the restart time" << endl;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::meshless::monitors::energy::potential
(
    const particleBody& b
) const
{
    const effects::gravity* g = findEffect<effects::gravity>(b);
    if (!g) return 0;

    const particleSet& set = b.particles();
    const particleField& m = set.field("mass");
    const particleField& x = set.positions();
    scalar E = 0;
    for (label i = 0; i < set.size(); ++i)
    {
        if (b.model().isImage(i)) continue;
        for (label c = 0; c < set.dim(); ++c)
        {
            E -= m(i, 0)*g->value()[c]*x(i, c);
        }
    }
    return particleDistribution::globalSum(set, E);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::monitors::energy::writeState(dictionary& dict) const
{
    dictionary refs;
    forAll(bodies_, k)
    {
        refs.add(bodies_[k]->name(), potential0_[k]);
    }
    dict.add("potential0", refs);
    if (frame_)
    {
        dict.add("frameWork", frameWork_);
        dict.add("framePower", framePower_);
        dict.add("frameTime", frameTime_);
    }
}


Foam::wordList Foam::meshless::monitors::energy::columns() const
{
    DynamicList<word> c;
    for (const particleBody* b : bodies_)
    {
        c.append(b->name() + ":kinetic");
        c.append(b->name() + ":strain");
        c.append(b->name() + ":potential");
    }
    if (frame_) c.append("frame:work");
    c.append("total");
    return wordList(c);
}


void Foam::meshless::monitors::energy::writeValues(Ostream& os)
{
    const scalar t = scene_.time().value();
    scalar total = 0, power = 0;
    forAll(bodies_, k)
    {
        const particleBody& b = *bodies_[k];
        const particleSet& set = b.particles();
        const label n = set.size();
        const label dim = set.dim();
        const bool hasU = set.found("U");

        // The tank's velocity and acceleration at the particles
        const double* vw = nullptr;
        if (frame_)
        {
            vFrame_.resize(n*dim);
            aFrame_.resize(n*dim);
            frame_->frameKinematics
            (
                t, n, dim, set.positions().data(), vFrame_.data(),
                aFrame_.data()
            );
            vw = vFrame_.data();
        }
        const effects::gravity* grav = findEffect<effects::gravity>(b);

        scalar kinetic = 0, bodyPower = 0;
        if (hasU || frame_)
        {
            const particleField* U = hasU ? &set.field("U") : nullptr;
            const particleField& m = set.field("mass");
            for (label i = 0; i < n; ++i)
            {
                if (b.model().isImage(i)) continue;
                scalar u2 = 0, p = 0;
                for (label c = 0; c < dim; ++c)
                {
                    const scalar u = U ? (*U)(i, c) : 0;
                    const scalar ur = vw ? u - vw[i*dim + c] : u;
                    u2 += sqr(ur);
                    if (vw)
                    {
                        p -= aFrame_[i*dim + c]*ur;
                        if (grav) p -= grav->value()[c]*vw[i*dim + c];
                    }
                }
                kinetic += 0.5*m(i, 0)*u2;
                bodyPower += m(i, 0)*p;
            }
        }
        kinetic = particleDistribution::globalSum(set, kinetic);
        power += particleDistribution::globalSum(set, bodyPower);
        const scalar strain =
            particleDistribution::globalSum(set, b.model().strainEnergy());
        const scalar pot = potential(b) - potential0_[k];
        os << tab << kinetic << tab << strain << tab << pot;
        total += kinetic + strain + pot;
    }
    if (frame_)
    {
        if (frameTime_ > -GREAT && t > frameTime_)
        {
            frameWork_ += 0.5*(framePower_ + power)*(t - frameTime_);
        }
        framePower_ = power;
        frameTime_ = t;
        os << tab << frameWork_;
        total -= frameWork_;
    }
    os << tab << total;
}


// ************************************************************************* //
