/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "fsiCoupling.H"
#include "OSspecific.H"
#include "ghostBoundary.H"
#include "fluidModel.H"
#include "particleScene.H"
#include "solidModel.H"
#include "atomicTimeWriter.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(fsiCoupling, 0);
    defineRunTimeSelectionTable(fsiCoupling, dictionary);
}
}


Foam::meshless::fsiCoupling::fsiCoupling
(
    const dictionary& dict,
    particleScene& scene
)
:
    dict_(dict),
    scene_(scene),
    maxCo_(0.25)
{
    // The solids' positions at the start (the clouds are read), and the
    // work a restart continues
    startWork(solidBodies());
}


Foam::meshless::particleBody& Foam::meshless::fsiCoupling::fluidBody
(
    const word& keyword
) const
{
    particleBody& b = scene_.body(dict_.get<word>(keyword), dict_);
    if (!b.model().fluid())
    {
        FatalIOErrorInFunction(dict_)
            << "coupling " << type() << ": '" << keyword << "' "
            << b.name() << " has model " << b.dict().get<word>("model")
            << ": expected a fluid model ("
            << bodyModel::modelsOf(bodyModel::modelRole::fluid) << ")"
            << exit(FatalIOError);
    }
    return b;
}


Foam::meshless::particleBody& Foam::meshless::fsiCoupling::solidBody
(
    const word& name
) const
{
    particleBody& b = scene_.body(name, dict_);
    if (!b.model().solid())
    {
        FatalIOErrorInFunction(dict_)
            << "coupling " << type() << ": solid '" << name << "' has model "
            << b.dict().get<word>("model") << ": expected a solid model ("
            << bodyModel::modelsOf(bodyModel::modelRole::solid) << ")"
            << exit(FatalIOError);
    }
    return b;
}


Foam::List<Foam::meshless::particleBody*>
Foam::meshless::fsiCoupling::solidBodies() const
{
    const wordList names(dict_.get<wordList>("solids"));
    if (names.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "coupling " << type() << ": 'solids' is empty: expected at"
            << " least one solid body ("
            << bodyModel::modelsOf(bodyModel::modelRole::solid) << ")"
            << exit(FatalIOError);
    }
    List<particleBody*> solids;
    for (const word& name : names) solids.append(&solidBody(name));
    return solids;
}


Foam::vector Foam::meshless::fsiCoupling::total(const particleField& f)
{
    vector s(Zero);
    for (label i = 0; i < f.size(); ++i)
    {
        for (label d = 0; d < f.nComponents(); ++d) s[d] += f(i, d);
    }
    return s;
}


void Foam::meshless::fsiCoupling::writeForces
(
    const scalar t,
    const label nSub,
    const UList<particleBody*>& solids,
    const fluidModel& fluid,
    const UList<const ghostBoundary*>& ghosts
)
{
    // The work of the step on each solid (every processor holds every
    // solid whole) and the fluid's sums over every processor's particles
    forAll(solids, k)
    {
        const particleField& x = solids[k]->particles().positions();
        const particleField& f = solids[k]->model().solid()->externalForce();
        const size_t m = size_t(x.size())*x.nComponents();
        std::vector<double>& x0 = workPositions_[k];
        if (x0.size() == m)
        {
            scalar w = 0;
            for (size_t c = 0; c < m; ++c)
            {
                w += f.data()[c]*(x.data()[c] - x0[c]);
            }
            work_[k] += w;
        }
        x0.assign(x.data(), x.data() + m);
    }
    List<vector> onFluid(solids.size());
    forAll(solids, k)
    {
        onFluid[k] =
            returnReduce(fluid.forceOnFluid(*ghosts[k]), sumOp<vector>());
    }
    if (!Pstream::master()) return;

    if (!forces_.valid())
    {
        const Time& runTime = scene_.time();
        const fileName dir =
            runTime.globalPath()/"postProcessing"/"coupling"
           /runTime.timeName(runTime.startTime().value());
        mkDir(dir);
        forces_.reset(new OFstream(dir/"forces.dat"));
        OFstream& os = forces_();
        os  << "# " << type() << " coupling: per solid, the fluid's force on"
            << " the solid and the solid's force on the fluid (fluid's sum);"
            << " the sub-steps; per solid the work of the fluid's force on it"
            << " since the run's start (sum F.dx)" << nl << "# time";
        for (const particleBody* s : solids)
        {
            os  << tab << s->name() << ":onSolid(x y z)" << tab
                << s->name() << ":onFluid(x y z)";
        }
        os  << tab << "subSteps";
        for (const particleBody* s : solids)
        {
            os  << tab << s->name() << ":work";
        }
        os  << endl;
    }
    OFstream& os = forces_();
    os  << t;
    forAll(solids, k)
    {
        const vector onSolid = total(solids[k]->model().solid()->externalForce());
        for (direction d = 0; d < 3; ++d) os << tab << onSolid[d];
        for (direction d = 0; d < 3; ++d) os << tab << onFluid[k][d];
    }
    os  << tab << nSub;
    forAll(solids, k)
    {
        os  << tab << work_[k];
    }
    os  << endl;
}


void Foam::meshless::fsiCoupling::startWork
(
    const UList<particleBody*>& solids
)
{
    work_.assign(solids.size(), 0);
    workPositions_.assign(solids.size(), std::vector<double>());
    forAll(solids, k)
    {
        const particleField& x = solids[k]->particles().positions();
        workPositions_[k].assign
        (
            x.data(), x.data() + size_t(x.size())*x.nComponents()
        );
    }
    const Time& runTime = scene_.time();
    const autoPtr<dictionary> state
    (
        atomicTimeWriter::readUniform
        (
            runTime, runTime.timeName(), "coupling",
            "the coupling's restart state, the work on each solid"
        )
    );
    if (!state.valid()) return;
    const dictionary* work = state->findDict("work");
    forAll(solids, k)
    {
        if (work && work->found(solids[k]->name()))
        {
            work_[k] = work->get<scalar>(solids[k]->name());
        }
    }
}


void Foam::meshless::fsiCoupling::writeState(const word& instance) const
{
    if (work_.empty()) return;
    const List<particleBody*> solids(solidBodies());
    dictionary work;
    forAll(solids, k)
    {
        if (size_t(k) < work_.size()) work.add(solids[k]->name(), work_[k]);
    }
    dictionary state;
    state.add("work", work);
    atomicTimeWriter::writeUniform
    (
        scene_.time(), instance, "coupling", state,
        "// The work of the fluid's force on each solid since the run's"
        " start (forces.dat),\n// which a restart continues"
    );
}


Foam::label Foam::meshless::fsiCoupling::solidSteps
(
    const UList<particleBody*>& solids,
    const scalar dt,
    subStepping& counter
) const
{
    scalar dtSolid = GREAT;
    for (particleBody* b : solids)
    {
        dtSolid = min(dtSolid, b->model().solid()->stepLimit(maxCo_));
    }
    return counter(dt, dtSolid);
}


void Foam::meshless::fsiCoupling::stepSolids
(
    const UList<particleBody*>& solids,
    const scalar t,
    const scalar dt,
    const label n,
    costAccounting& costs
) const
{
    const scalar h = dt/n;
    for (particleBody* b : solids)
    {
        solidModel& s = *b->model().solid();
        costAccounting::scope timer(costs, b->modelCostPart());
        for (label j = 0; j < n; ++j)
        {
            s.step(t + j*h, h, costs);
        }
    }
}


// ************************************************************************* //
