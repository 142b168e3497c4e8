/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "energy.H"
#include "particleScene.H"
#include "bodyModel.H"
#include "gravity.H"
#include "restartManifest.H"
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
    monitor(name, dict, scene)
{
    particleScene& s = const_cast<particleScene&>(scene);
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
    return E;
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
    c.append("total");
    return wordList(c);
}


void Foam::meshless::monitors::energy::writeValues(Ostream& os)
{
    scalar total = 0;
    forAll(bodies_, k)
    {
        const particleBody& b = *bodies_[k];
        const particleSet& set = b.particles();
        scalar kinetic = 0;
        if (set.found("U"))
        {
            const particleField& U = set.field("U");
            const particleField& m = set.field("mass");
            for (label i = 0; i < set.size(); ++i)
            {
                if (b.model().isImage(i)) continue;
                scalar u2 = 0;
                for (label c = 0; c < set.dim(); ++c) u2 += sqr(U(i, c));
                kinetic += 0.5*m(i, 0)*u2;
            }
        }
        const scalar strain = b.model().strainEnergy();
        const scalar pot = potential(b) - potential0_[k];
        os << tab << kinetic << tab << strain << tab << pot;
        total += kinetic + strain + pot;
    }
    os << tab << total;
}


// ************************************************************************* //
