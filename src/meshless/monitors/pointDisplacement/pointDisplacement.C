/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "pointDisplacement.H"
#include "particleScene.H"
#include "addToRunTimeSelectionTable.H"
#include "movingLeastSquares.H"

namespace Foam
{
namespace meshless
{
namespace monitors
{
    defineTypeNameAndDebug(pointDisplacement, 0);
    addToRunTimeSelectionTable(monitor, pointDisplacement, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::monitors::pointDisplacement::pointDisplacement
(
    const word& name,
    const dictionary& dict,
    const particleScene& scene
)
:
    monitor(name, dict, scene),
    body_
    (
        const_cast<particleScene&>(scene).body(dict.get<word>("body"), dict)
    )
{
    const particleSet& set = body_.particles();
    if (!set.found("X0"))
    {
        FatalIOErrorInFunction(dict)
            << "body " << body_.name() << " has no reference positions X0"
            << " (a solid model's field): a point displacement needs them;"
            << " expected a body of a solid model (nosbPd, tlsph)"
            << exit(FatalIOError);
    }
    const particleField& X0 = set.field("X0");
    const label dim = set.dim();

    if (dict.found("id"))
    {
        const label id = dict.get<label>("id");
        if (set.findId(id) < 0)
        {
            label maxId = -1;
            for (const label i : set.ids()) maxId = max(maxId, i);
            FatalIOErrorInFunction(dict)
                << "id " << id << ": body " << body_.name()
                << " has no particle with that id; expected the id of one"
                << " of its " << set.size() << " particles (ids up to "
                << maxId << ")" << exit(FatalIOError);
        }
        ids_ = labelList(1, id);
        weights_ = scalarList(1, 1.0);
        index_ = labelList(1, -1);
        return;
    }

    const point p = dict.get<point>("point");
    if (!body_.hasKernel())
    {
        FatalIOErrorInFunction(dict)
            << "point: body " << body_.name() << " has no kernel to"
            << " interpolate with; give the particle's id instead"
            << exit(FatalIOError);
    }
    const smoothingKernel& W = body_.kernel();
    const particleField& V = set.field("volume");

    // Moving least squares with a linear basis (movingLeastSquares.H)
    DynamicList<label> index;
    DynamicList<scalar> w;
    const label found =
        movingLeastSquaresWeights(p, X0, V, W, dim, index, w);
    if (found == 0)
    {
        FatalIOErrorInFunction(dict)
            << "point " << p << ": no particle of body " << body_.name()
            << " within the kernel radius " << W.radius()
            << " (reference configuration): expected a point inside or"
            << " next to the body, or a particle id" << exit(FatalIOError);
    }
    if (found < 0)
    {
        FatalIOErrorInFunction(dict)
            << "point " << p << ": the " << index.size() << " particles of body "
            << body_.name() << " around it do not span " << dim
            << " dimensions; give a point inside the body or a particle id"
            << exit(FatalIOError);
    }
    DynamicList<label> ids(index.size());
    for (const label i : index) ids.append(set.ids()[i]);
    ids_.transfer(ids);
    weights_.transfer(w);
    index_ = labelList(ids_.size(), -1);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::meshless::monitors::pointDisplacement::columns() const
{
    if (body_.dim() == 2) return wordList({"dx", "dy", "x", "y"});
    return wordList({"dx", "dy", "dz", "x", "y", "z"});
}


void Foam::meshless::monitors::pointDisplacement::value
(
    vector& d,
    point& x
) const
{
    const particleSet& set = body_.particles();
    const particleField& X0 = set.field("X0");
    const particleField& pos = set.positions();
    d = Zero;
    x = Zero;
    forAll(ids_, k)
    {
        label& i = index_[k];
        if (i < 0 || i >= set.size() || set.ids()[i] != ids_[k])
        {
            i = set.findId(ids_[k]);
        }
        for (label c = 0; c < set.dim(); ++c)
        {
            d[c] += weights_[k]*(pos(i, c) - X0(i, c));
            x[c] += weights_[k]*pos(i, c);
        }
    }
}


void Foam::meshless::monitors::pointDisplacement::writeValues(Ostream& os)
{
    vector d;
    point x;
    value(d, x);
    const label dim = body_.dim();
    for (label c = 0; c < dim; ++c) os << tab << d[c];
    for (label c = 0; c < dim; ++c) os << tab << x[c];
}


// ************************************************************************* //
