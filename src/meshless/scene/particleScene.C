/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "particleScene.H"
#include "openBoundaryFlux.H"
#include "readPeriodicBox.H"
#include "bodyModel.H"
#include "solidModel.H"
#include "lagrangianIO.H"
#include "vtpWriter.H"
#include "restartManifest.H"
#include "Time.H"
#include <cmath>
#ifdef _OPENMP
#include <omp.h>
#endif

Foam::meshless::particleScene::particleScene(const polyMesh& mesh)
:
    mesh_(mesh),
    dict_
    (
        IOobject
        (
            "particleProperties",
            mesh.time().constant(),
            mesh.time(),
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    dim_(mesh.nSolutionD()),
    zPlane_(0.5*(mesh.bounds().min().z() + mesh.bounds().max().z())),
    domain_(mesh.bounds()),
    relations_(),
    bodies_(),
    costs_(),
    relationsCost_(costs_.part("neighbourRelations")),
    exchangeCost_(Pstream::parRun() ? costs_.part("haloExchange") : -1),
    waitCost_(Pstream::parRun() ? costs_.part("imbalanceWait") : -1),
    writeCost_(costs_.part("write")),
    vtp_(dict_.getOrDefault<bool>("vtp", false))
{
    if (dim_ == 2 && mesh.solutionD()[vector::Z] != -1)
    {
        FatalErrorInFunction
            << "2D meshes must have their empty direction along z"
            << exit(FatalError);
    }

    const dictionary& bodiesDict = dict_.subDict("bodies");
    if (bodiesDict.empty())
    {
        FatalIOErrorInFunction(bodiesDict)
            << "No body in 'bodies': expected at least one"
            << exit(FatalIOError);
    }

    scalar maxSpacing = 0;
    for (const entry& e : bodiesDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(bodiesDict)
                << "Entry '" << e.keyword() << "' in 'bodies': expected a"
                << " body dictionary" << exit(FatalIOError);
        }
        bodies_.append
        (
            new particleBody(e.keyword(), e.dict(), dim_, mesh.time())
        );
        maxSpacing = max(maxSpacing, bodies_.last().spacing());
    }
    // Periodic directions: every relation is asked for after this
    readPeriodic();
    // A parallel run's solids are held whole by every processor, in the
    // order of their ids, before their models are made
    if (Pstream::parRun())
    {
        for (particleBody& b : bodies_)
        {
            const word type = b.dict().get<word>("model");
            if
            (
                bodyModel::roleTable().lookup(type, bodyModel::modelRole::wall)
             == bodyModel::modelRole::solid
            )
            {
                particleDistribution::replicate(b.particles());
            }
        }
    }
    for (particleBody& b : bodies_)
    {
        b.select(costs_);
    }
    if (Pstream::parRun()) startParallel(maxSpacing);
    startPeriodic();
    for (particleBody& b : bodies_)
    {
        b.model().connect(*this);
    }
    if (dict_.found("coupling"))
    {
        coupling_ = fsiCoupling::New(dict_.subDict("coupling"), *this);
    }

    if (const dictionary* obDict = dict_.findDict("openBoundaries"))
    {
        for (const entry& e : *obDict)
        {
            if (!e.isDict())
            {
                FatalIOErrorInFunction(*obDict)
                    << "Entry '" << e.keyword() << "' in 'openBoundaries':"
                    << " expected an open boundary dictionary"
                    << exit(FatalIOError);
            }
            openBoundaries_.append
            (
                openBoundary::New(e.keyword(), e.dict(), *this)
            );
        }
    }

    // The models are set up over their halos: their own particles are
    // what the run writes and samples
    detachHalos();

    if (dict_.found("monitors"))
    {
        for (const entry& e : dict_.subDict("monitors"))
        {
            if (!e.isDict())
            {
                FatalIOErrorInFunction(dict_.subDict("monitors"))
                    << "Entry '" << e.keyword() << "' in 'monitors':"
                    << " expected a monitor dictionary" << exit(FatalIOError);
            }
            monitors_.append(monitor::New(e.keyword(), e.dict(), *this));
        }
    }

    if (!openBoundaries_.empty())
    {
        monitors_.append
        (
            new monitors::openBoundaryFlux
            (
                "openBoundaries", dictionary(), *this, openBoundaries_
            )
        );
    }

    // Escape box: the mesh with room for wall layers and a splash, or the
    // scene's own
    domain_.inflate(0.1);
    domain_.min() -= vector::uniform(10*maxSpacing);
    domain_.max() += vector::uniform(10*maxSpacing);
    if (const dictionary* box = dict_.findDict("escapeBox"))
    {
        const boundBox given(box->get<point>("min"), box->get<point>("max"));
        if
        (
            !given.contains(mesh.bounds().min())
         || !given.contains(mesh.bounds().max())
        )
        {
            FatalIOErrorInFunction(*box)
                << "escapeBox " << given << " does not contain the mesh's"
                << " bounds " << mesh.bounds() << ": expected min below and"
                << " max above them" << exit(FatalIOError);
        }
        domain_ = given;
    }
}


void Foam::meshless::particleScene::readPeriodic()
{
    const periodicBox box(readPeriodicBox(dict_, dim_));
    if (!box.any()) return;
    const dictionary* pd = dict_.findDict("periodic");
    const wordList names(dim_ == 2 ? wordList{"x", "y"} : wordList{"x", "y", "z"});

    // A particle must not see two images of the same neighbour
    for (const particleBody& b : bodies_)
    {
        if (!b.hasKernel()) continue;
        const scalar support = b.kernel().radius();
        for (label d = 0; d < dim_; ++d)
        {
            if (box.periodic(d) && !(box.length(d) > 2*support))
            {
                FatalIOErrorInFunction(*pd)
                    << "Periodic direction '" << names[d] << "': period "
                    << box.length(d) << " m, expected more than two kernel"
                    << " supports of body " << b.name() << " (2 x "
                    << support << " m): a particle would see two images of"
                    << " the same neighbour" << exit(FatalIOError);
            }
        }
    }

    relations_.setPeriodic(box, pd);
}


void Foam::meshless::particleScene::startPeriodic()
{
    const periodicBox& box = relations_.periodic();
    if (!box.any()) return;

    const dictionary& pd = dict_.subDict("periodic");
    static const char* const names[3] = {"x", "y", "z"};
    for (particleBody& b : bodies_)
    {
        particleField& x = b.particles().positions();
        if (wrapsPeriodic(b))
        {
            box.wrap(x.data(), x.size(), dim_);
            continue;
        }
        // A body that is not wrapped must lie in the period: a particle
        // beyond it would be a second image of another
        for (label d = 0; d < dim_; ++d)
        {
            if (!box.periodic(d)) continue;
            for (label i = 0; i < x.size(); ++i)
            {
                if (x(i, d) < box.min(d) || x(i, d) >= box.max(d))
                {
                    FatalIOErrorInFunction(pd)
                        << "Body " << b.name() << " (model "
                        << b.dict().get<word>("model") << ", not wrapped):"
                        << " particle id " << b.particles().ids()[i]
                        << " at " << names[d] << " = " << x(i, d)
                        << " is outside the period [" << box.min(d) << ", "
                        << box.max(d) << ") of direction " << names[d]
                        << ": expected every particle of a fixed body or"
                        << " solid within the period (seed it there)"
                        << exit(FatalIOError);
                }
            }
        }
    }
}


bool Foam::meshless::particleScene::wrapsPeriodic(particleBody& b)
{
    // A solid's scheme takes x_j - x_i of its own particles from their
    // positions: it is not split across the period (its contacts still
    // see it through the minimum image)
    return
        b.model().moves()
     && b.model().role() != bodyModel::modelRole::solid;
}


void Foam::meshless::particleScene::wrapPeriodic()
{
    const periodicBox& box = relations_.periodic();
    if (!box.any()) return;
    for (particleBody& b : bodies_)
    {
        if (!wrapsPeriodic(b)) continue;
        particleField& x = b.particles().positions();
        box.wrap(x.data(), x.size(), dim_);
    }
}


Foam::meshless::particleBody& Foam::meshless::particleScene::body
(
    const word& name,
    const dictionary& referrer
)
{
    for (particleBody& b : bodies_)
    {
        if (b.name() == name) return b;
    }
    wordList names(bodies_.size());
    forAll(bodies_, i) names[i] = bodies_[i].name();
    FatalIOErrorInFunction(referrer)
        << "Unknown body '" << name << "': expected one of " << names
        << exit(FatalIOError);
    return bodies_[0];
}


Foam::meshless::particleBody&
Foam::meshless::particleScene::body(const word& name)
{
    return body(name, dict_);
}


Foam::label Foam::meshless::particleScene::nParticles() const
{
    label n = 0;
    label whole = 0;
    for (const particleBody& b : bodies_)
    {
        (b.particles().replicated() ? whole : n) += b.particles().size();
    }
    return returnReduce(n, sumOp<label>()) + whole;
}


Foam::scalar Foam::meshless::particleScene::maxDeltaT(const scalar maxCo) const
{
    scalar dt = GREAT;
    for (const particleBody& b : bodies_)
    {
        if (coupling_.valid() && coupling_->couples(b)) continue;
        dt = min(dt, b.maxDeltaT(maxCo));
    }
    if (coupling_.valid())
    {
        dt = min(dt, coupling_->maxDeltaT(maxCo));
    }
    return returnReduce(dt, minOp<scalar>());
}


void Foam::meshless::particleScene::advance(const scalar t, const scalar dt)
{
    // Wrapped first: a particle belongs to the part it is in
    if (distribution_.valid()) wrapPeriodic();
    attachHalos(false);
    for (particleBody& b : bodies_)
    {
        b.model().beginStep(t);
    }
    {
        costAccounting::scope timer(costs_, relationsCost_);
        wrapPeriodic();
        relations_.update();
    }
    for (particleBody& b : bodies_)
    {
        if (coupling_.valid() && coupling_->couples(b)) continue;
        if (b.model().moves()) b.advance(t, dt, costs_);
    }
    if (coupling_.valid())
    {
        coupling_->advance(t, dt, costs_);
    }
    detachHalos();
    if (!openBoundaries_.empty()) exchangeOpenBoundaries(t + dt);
}


void Foam::meshless::particleScene::startParallel(const scalar maxSpacing)
{
    // What needs more than halos and migration is refused by name
    const char* const notYet =
        " does not run in parallel yet: run the case serially (decomposePar"
        " and reconstructPar carry its clouds)";
    for (const particleBody& b : bodies_)
    {
        if (!b.model().parallelReady())
        {
            FatalIOErrorInFunction(b.dict())
                << "Body " << b.name() << ": model "
                << b.dict().get<word>("model") << notYet
                << exit(FatalIOError);
        }
    }

    // The halo: the widest search of any relation (a kernel's support
    // grown by its model's skin), checked once the models have asked
    scalar radius = 0;
    for (const particleBody& b : bodies_)
    {
        if (!b.hasKernel()) continue;
        const scalar skin =
            b.dict().getOrDefault<scalar>("neighbourSkin", 0.1);
        radius = max(radius, b.kernel().radius()*(1 + max(skin, 0.1)));
    }
    if (radius == 0) radius = 3*maxSpacing;

    std::vector<particleSet*> sets;
    for (particleBody& b : bodies_) sets.push_back(&b.particles());
    distribution_.reset
    (
        new particleDistribution(mesh_, dim_, zPlane_, radius, sets)
    );
    distribution_->setPeriodic(relations_.periodic());
    attachHalos(true);

    for (const particleBody& b : bodies_)
    {
        const particleSet& set = b.particles();
        if (!set.replicated()) continue;
        labelList owned(Pstream::nProcs(), 0);
        label& mine = owned[Pstream::myProcNo()];
        for (label i = 0; i < set.size(); ++i) mine += set.owns(i);
        Pstream::gatherList(owned);
        Pstream::scatterList(owned);
        Info<< "    " << b.name() << ": held whole by every processor,"
            << " owned " << owned << " (the nearest cell's processor)"
            << endl;
    }
}


void Foam::meshless::particleScene::attachHalos(const bool everyBody)
{
    if (!distribution_.valid()) return;

    // A step's (the start's, every body located once, is set-up)
    std::unique_ptr<costAccounting::scope> timer;
    if (!everyBody)
    {
        {
            // The processors meet: the wait for the slowest is imbalance
            costAccounting::scope wait(costs_, waitCost_);
            returnReduce(label(0), sumOp<label>());
        }
        timer.reset(new costAccounting::scope(costs_, exchangeCost_));
    }
    {
        // At the start every body (decomposePar placed the wall layers
        // outside the mesh by the cell nearest them), then the moving ones
        std::vector<bool> move;
        for (particleBody& b : bodies_)
        {
            move.push_back
            (
                !b.particles().replicated()
             && (everyBody || b.model().moves())
            );
        }
        distribution_->migrate(move);
    }
    distribution_->attachHalos();
    for (particleBody& b : bodies_) b.model().resized();

    // Every relation over the new particle order, and wide enough (a
    // relation within the replicated bodies keeps its order)
    std::vector<const particleSet*> whole;
    for (const particleBody& b : bodies_)
    {
        if (b.particles().replicated()) whole.push_back(&b.particles());
    }
    relations_.rebuildEveryUpdate(whole);
    if (relations_.maxRadius() > distribution_->radius())
    {
        FatalErrorInFunction
            << "A neighbour relation searches " << relations_.maxRadius()
            << " m, beyond the halo's " << distribution_->radius() << " m"
            << abort(FatalError);
    }
}


void Foam::meshless::particleScene::detachHalos()
{
    if (!distribution_.valid() || !distribution_->attached()) return;
    costAccounting::scope timer(costs_, exchangeCost_);
    distribution_->detachHalos();
    for (particleBody& b : bodies_) b.model().resized();
}


void Foam::meshless::particleScene::exchangeOpenBoundaries(const scalar t)
{
    // Emit first: an inflow's particles are indices of the step's start,
    // which removals would shift
    label changed = 0;
    for (openBoundary& ob : openBoundaries_) changed += ob.emit(t);
    for (openBoundary& ob : openBoundaries_) changed += ob.remove(t);

    // The models refresh their views (a body with two boundaries twice:
    // resized only re-reads the fields)
    if (!changed) return;
    for (openBoundary& ob : openBoundaries_) ob.body().model().resized();
}


void Foam::meshless::particleScene::checkState
(
    const word& lastWrittenTime
) const
{
    const word now = mesh_.time().timeName();
    for (const particleBody& b : bodies_)
    {
        if (!b.model().moves()) continue;
        const particleSet& set = b.particles();

        const string why = b.model().blowUp();
        if (!why.empty())
        {
            FatalErrorInFunction
                << "Blow-up at time " << now << ": body " << b.name()
                << ", " << why.c_str() << nl
                << "    Last good state on disk: time "
                << lastWrittenTime << exit(FatalError);
        }

        for (const word& name : set.fieldNames())
        {
            const particleField& f = set.field(name);
            if (!f.written()) continue;
            const label nc = f.nComponents();
            label bad = -1;
            #pragma omp parallel for reduction(max:bad)
            for (label i = 0; i < f.size(); ++i)
            {
                for (label c = 0; c < nc; ++c)
                {
                    if (!std::isfinite(f(i, c))) bad = std::max(bad, i);
                }
            }
            if (bad >= 0)
            {
                FatalErrorInFunction
                    << "Blow-up at time " << now << ": body " << b.name()
                    << ", particle id " << set.ids()[bad] << ", field "
                    << name << " is not finite." << nl
                    << "    Likely causes: a time step above the stable one"
                    << " (lower deltaT or maxCo), or a non-physical"
                    << " material constant." << nl
                    << "    Last good state on disk: time "
                    << lastWrittenTime << exit(FatalError);
            }
        }

        const particleField& x = set.positions();
        for (label i = 0; i < set.size(); ++i)
        {
            point p(Zero);
            for (label d = 0; d < dim_; ++d) p[d] = x(i, d);
            if (dim_ == 2) p.z() = zPlane_;
            if (!domain_.contains(p))
            {
                FatalErrorInFunction
                    << "Blow-up at time " << now << ": body " << b.name()
                    << ", particle id " << set.ids()[i] << " at " << p
                    << " has left the domain " << domain_ << nl
                    << "    Likely causes: a leaking wall, or a time step"
                    << " above the stable one." << nl
                    << "    Last good state on disk: time "
                    << lastWrittenTime << exit(FatalError);
            }
        }
    }
}


void Foam::meshless::particleScene::writeState()
{
    costAccounting::scope timer(costs_, writeCost_);
    const Time& runTime = mesh_.time();
    if (!locator_.valid())
    {
        locator_.reset(new lagrangianIO::meshLocator(mesh_));
    }
    UPtrList<const particleSet> sets(bodies_.size());
    // A replicated body (a parallel run's solid) is written whole, with
    // its owners' values, by the master; the other processors write it
    // empty (decomposePar, reconstructPar and a restart see one copy)
    std::vector<std::unique_ptr<particleSet>> empty;
    forAll(bodies_, i)
    {
        particleBody& b = bodies_[i];
        const particleSet* set = &b.particles();
        if (set->replicated())
        {
            particleDistribution::shareAll(b.particles());
            if (!Pstream::master())
            {
                empty.emplace_back(new particleSet(set->name(), dim_));
                particleSet& e = *empty.back();
                b.particles().forEachField([&](const particleField& f)
                {
                    if (f.written()) e.addField(f.name(), f.fieldKind());
                });
                set = &e;
            }
        }
        lagrangianIO::write
        (
            *set,
            runTime,
            runTime.timeName(),
            zPlane_,
            locator_->locate(*set, zPlane_)
        );
        if (set == &b.particles())
        {
            b.model().write(runTime, runTime.timeName());
        }
        sets.set(i, set);
    }
    monitor::writeStates(monitors_, runTime, runTime.timeName());
    if (coupling_.valid()) coupling_->writeState(runTime.timeName());
    restartManifest::write(sets, runTime, runTime.timeName());
}


void Foam::meshless::particleScene::writeVtk()
{
    if (!vtp_) return;
    costAccounting::scope timer(costs_, writeCost_);
    const Time& runTime = mesh_.time();
    for (const particleBody& b : bodies_)
    {
        vtpWriter::write
        (
            b.particles(),
            runTime.path()/"VTK",
            runTime.timeName(),
            zPlane_
        );
    }
}


void Foam::meshless::particleScene::sampleMonitors
(
    const scalar t,
    const bool force
)
{
    for (monitor& m : monitors_)
    {
        m.sample(t, force);
    }
}


void Foam::meshless::particleScene::describe(Ostream& os) const
{
    // A summary: writePrecision (maybe 17, for exact restarts) is too much
    const int oldPrecision = os.precision(6);
    os  << "Scene: " << dim_ << "D, " << bodies_.size() << " bodies, "
        << nParticles() << " particles" << nl;
    // Recorded so that a benchmark's log says what its wall time ran on
    #ifdef _OPENMP
    os  << "    OpenMP threads: " << omp_get_max_threads() << nl;
    #else
    os  << "    OpenMP threads: 1 (built without OpenMP)" << nl;
    #endif
    for (const particleBody& b : bodies_)
    {
        b.describe(os);
    }
    if (coupling_.valid()) coupling_->describe(os);
    const periodicBox& box = relations_.periodic();
    if (box.any())
    {
        static const char* const names[3] = {"x", "y", "z"};
        os  << "    periodic:";
        for (label d = 0; d < dim_; ++d)
        {
            if (!box.periodic(d)) continue;
            os  << ' ' << names[d] << " [" << box.min(d) << ", "
                << box.max(d) << ')';
        }
        os  << nl;
    }
    for (const openBoundary& ob : openBoundaries_)
    {
        os  << "    open boundary " << ob.name() << ": " << ob.type()
            << " of " << ob.body().name() << nl;
    }
    if (vtp_) os << "    output: lagrangian clouds and VTK .vtp" << nl;
    os  << endl;
    os.precision(oldPrecision);
}


void Foam::meshless::particleScene::runCost(dictionary& d) const
{
    dictionary bodies;
    dictionary subSteps;
    auto steps = [](const subStepping& s)
    {
        dictionary c;
        c.add("minSubSteps", s.minSubSteps());
        c.add("most", s.most());
        c.add("mean", s.mean());
        return c;
    };
    for (const particleBody& b : bodies_)
    {
        dictionary e;
        e.add("model", b.dict().get<word>("model"));
        e.add
        (
            "particles",
            particleDistribution::globalSize(b.particles())
        );
        e.add("spacing", b.spacing());
        if (b.hasKernel()) e.add("smoothingLength", b.kernel().h());
        bodies.add(b.name(), e);

        const subStepping* s = b.model().stepCounter();
        if (s && s->most() > 0)
        {
            subSteps.add(b.name(), steps(*s));
        }
    }
    if (coupling_.valid() && coupling_->subSteps())
    {
        subSteps.add("coupling", steps(*coupling_->subSteps()));
    }
    d.add("bodies", bodies);
    d.add("subSteps", subSteps);
    if (distribution_.valid())
    {
        dictionary p;
        distribution_->runCost(p);
        d.add("parallel", p);
    }
}
