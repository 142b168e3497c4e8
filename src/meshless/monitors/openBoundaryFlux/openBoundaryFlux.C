/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "openBoundaryFlux.H"
#include "particleScene.H"

namespace Foam
{
namespace meshless
{
namespace monitors
{
    defineTypeNameAndDebug(openBoundaryFlux, 0);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::meshless::monitors::openBoundaryFlux::openBoundaryFlux
(
    const word& name,
    const dictionary& dict,
    const particleScene& scene,
    PtrList<openBoundary>& boundaries
)
:
    monitor(name, dict, scene),
    boundaries_(boundaries)
{
    forAll(boundaries_, k)
    {
        bool first = true;
        for (label j = 0; j < k; ++j)
        {
            if (&boundaries_[j].body() == &boundaries_[k].body())
            {
                first = false;
            }
        }
        if (first) bodyOf_.append(k);
    }

    const dictionary* state = restartState();
    if (!state) return;
    // The counts written are every processor's together (the same in a
    // serial case, its decomposed copies and a reconstructed one): the
    // master continues them
    const bool master = Pstream::master();
    for (openBoundary& ob : boundaries_)
    {
        const dictionary& d = state->subDict(ob.name());
        ob.setCounters
        (
            master ? d.get<label>("particles") : 0,
            master ? d.get<scalar>("mass") : 0
        );
    }
    for (const label k : bodyOf_)
    {
        particleSet& set = boundaries_[k].body().particles();
        set.setNextId
        (
            state->get<label>(word(boundaries_[k].body().name() + ".nextId"))
        );
    }
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::wordList Foam::meshless::monitors::openBoundaryFlux::columns() const
{
    wordList c;
    for (const label k : bodyOf_)
    {
        c.append(boundaries_[k].body().name() + ".particles");
    }
    for (const openBoundary& ob : boundaries_)
    {
        c.append(ob.name() + ".particles");
        c.append(ob.name() + ".mass");
    }
    return c;
}


void Foam::meshless::monitors::openBoundaryFlux::writeValues(Ostream& os)
{
    // Over every processor's particles and counts (each counts its own)
    for (const label k : bodyOf_)
    {
        os  << tab
            << returnReduce
               (
                   boundaries_[k].body().particles().size(), sumOp<label>()
               );
    }
    for (const openBoundary& ob : boundaries_)
    {
        os  << tab << returnReduce(ob.particles(), sumOp<label>())
            << tab << returnReduce(ob.mass(), sumOp<scalar>());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::monitors::openBoundaryFlux::writeState
(
    dictionary& dict
) const
{
    for (const openBoundary& ob : boundaries_)
    {
        dictionary d;
        d.add("particles", returnReduce(ob.particles(), sumOp<label>()));
        d.add("mass", returnReduce(ob.mass(), sumOp<scalar>()));
        dict.add(ob.name(), d);
    }
    for (const label k : bodyOf_)
    {
        const particleBody& b = boundaries_[k].body();
        dict.add(word(b.name() + ".nextId"), b.particles().nextId());
    }
}


// ************************************************************************* //
