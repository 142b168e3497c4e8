/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "probes.H"
#include "particleDistribution.H"
#include "particleScene.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace monitors
{
    defineTypeNameAndDebug(probes, 0);
    addToRunTimeSelectionTable(monitor, probes, dictionary);
}
}
}


Foam::meshless::monitors::probes::probes
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
    ),
    field_(dict.getOrDefault<word>("field", "p")),
    points_(dict.get<List<point>>("points"))
{
    const particleSet& set = body_.particles();
    if (!set.found(field_) || set.field(field_).nComponents() != 1)
    {
        FatalIOErrorInFunction(dict)
            << "field " << field_ << ": body " << body_.name() << " has no"
            << " such scalar field; expected one of its scalar fields, e.g."
            << " p or rho of a fluid" << exit(FatalIOError);
    }
    if (!body_.hasKernel())
    {
        FatalIOErrorInFunction(dict)
            << "body " << body_.name() << " has no kernel to average with;"
            << " expected a body with a 'kernel'" << exit(FatalIOError);
    }
    if (points_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "points: expected at least one point" << exit(FatalIOError);
    }
}


Foam::wordList Foam::meshless::monitors::probes::columns() const
{
    wordList names(points_.size());
    forAll(points_, k) names[k] = field_ + Foam::name(k);
    return names;
}


Foam::scalar Foam::meshless::monitors::probes::value(const label k) const
{
    const particleSet& set = body_.particles();
    const particleField& x = set.positions();
    const particleField& f = set.field(field_);
    // Current volumes m/rho of a fluid (from the state, so that a restart
    // samples what the uninterrupted run samples), else seeded volumes
    const bool current = set.found("mass") && set.found("rho");
    const particleField& V = set.field(current ? "mass" : "volume");
    const particleField* rho = current ? &set.field("rho") : nullptr;
    const smoothingKernel& W = body_.kernel();
    const scalar R2 = sqr(W.radius());
    const label dim = set.dim();
    const point& p = points_[k];

    scalar sumWf = 0, sumW = 0;
    for (label i = 0; i < set.size(); ++i)
    {
        scalar r2 = 0;
        for (label d = 0; d < dim; ++d) r2 += sqr(x(i, d) - p[d]);
        if (r2 >= R2) continue;
        const scalar w = W.W(std::sqrt(r2))*V(i, 0)/(rho ? (*rho)(i, 0) : 1);
        sumWf += w*f(i, 0);
        sumW += w;
    }
    // Over every processor's particles
    sumWf = particleDistribution::globalSum(set, sumWf);
    sumW = particleDistribution::globalSum(set, sumW);
    return sumW > 0 ? sumWf/sumW : 0;
}


void Foam::meshless::monitors::probes::writeValues(Ostream& os)
{
    forAll(points_, k) os << tab << value(k);
}


// ************************************************************************* //
