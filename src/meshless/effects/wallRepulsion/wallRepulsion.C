/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "wallRepulsion.H"
#include "dispatchDim.H"
#include "pairLoop.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace effects
{
    defineTypeNameAndDebug(wallRepulsion, 0);
    addToRunTimeSelectionTable(effect, wallRepulsion, dictionary);
}
}
}


namespace
{

//- Monaghan's repulsion of a fluid particle by the particles of its walls
//  closer than r0
template<int Dim>
struct repulsionTerm
{
    struct sum { Foam::meshless::vectorD<Dim> s; Foam::label n; };
    double D, r0, r02, p1, p2;
    double* a;
    Foam::label* count;

    sum start(const Foam::label) const
    {
        return {Foam::meshless::vectorD<Dim>::Zero(), 0};
    }
    void pair
    (
        sum& acc, const Foam::meshless::pairView& v,
        const Foam::label, const Foam::label q
    ) const
    {
        const Foam::meshless::vectorD<Dim> xji = -v.x<Dim>(q);
        const double r2 = xji.squaredNorm();
        if (r2 < r02 && r2 > 0)
        {
            const double r = std::sqrt(r2);
            acc.s += (Foam::meshless::effects::wallRepulsion::magnitude
                  (r, D, r0, p1, p2)/r)*xji;
            ++acc.n;
        }
    }
    void finish(const Foam::label i, sum& acc) const
    {
        Foam::meshless::vec<Dim>(a, i) += acc.s;
        if (count) count[i] = acc.n;
    }
};

//- The repulsion of ctx's wall sources (collected into walls)
void addImpl
(
    const Foam::meshless::pairContext& ctx,
    const double D,
    const double r0,
    const double p1,
    const double p2,
    double* a,
    Foam::label* count,
    std::vector<Foam::meshless::pairSource>& walls
)
{
    walls.clear();
    for (size_t k = 1; k < ctx.sources.size(); ++k)
    {
        if (ctx.wallSource[k]) walls.push_back(ctx.sources[k]);
    }
    Foam::meshless::dispatchDim(ctx.dim, [&](auto d)
    {
        Foam::meshless::gather
        (
            ctx.n, walls, repulsionTerm<d>{D, r0, r0*r0, p1, p2, a, count}
        );
    });
}

} // End anonymous namespace


Foam::meshless::effects::wallRepulsion::wallRepulsion
(
    const word& name,
    const dictionary& dict,
    particleBody& body
)
:
    effect(name, dict, body),
    D_(readPositive(dict, "strength")),
    r0_(readPositiveOrDefault(dict, "range", 0.9*body.spacing())),
    p1_(12),
    p2_(4)
{
    const Pair<scalar> p =
        dict.getOrDefault<Pair<scalar>>("exponents", Pair<scalar>(12, 4));
    if (!(p.first() > p.second() && p.second() > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'exponents' is " << p
            << ": expected (p1 p2) with p1 > p2 > 0 (Monaghan: (12 4))"
            << exit(FatalIOError);
    }
    p1_ = p.first();
    p2_ = p.second();
}


Foam::scalar Foam::meshless::effects::wallRepulsion::magnitude
(
    const scalar r,
    const scalar D,
    const scalar r0,
    const scalar p1,
    const scalar p2
)
{
    if (r >= r0) return 0;
    const scalar q = r0/r;
    return D*(std::pow(q, p1) - std::pow(q, p2))/r;
}


Foam::label Foam::meshless::effects::wallRepulsion::add
(
    const pairContext& ctx,
    const scalar D,
    const scalar r0,
    const scalar p1,
    const scalar p2,
    double* acc
)
{
    std::vector<label> count(ctx.n, 0);
    std::vector<pairSource> walls;
    addImpl(ctx, D, r0, p1, p2, acc, count.data(), walls);
    label nPairs = 0;
    for (const label c : count) nPairs += c;
    return nPairs;
}


void Foam::meshless::effects::wallRepulsion::addPairAcceleration
(
    const pairContext& ctx,
    particleField& acc
) const
{
    addImpl(ctx, D_, r0_, p1_, p2_, acc.data(), nullptr, walls_);
}


void Foam::meshless::effects::wallRepulsion::describe(Ostream& os) const
{
    os  << "wall repulsion (Monaghan 1994 Lennard-Jones), D " << D_
        << " m^2/s^2, range " << r0_ << " m, exponents (" << p1_ << ' '
        << p2_ << ')';
}
