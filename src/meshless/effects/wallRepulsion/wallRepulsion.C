/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "wallRepulsion.H"
#include "ulphOperators.H"
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

template<int Dim>
Foam::label addImpl
(
    const Foam::meshless::pairContext& ctx,
    const double D,
    const double r0,
    const double p1,
    const double p2,
    double* a
)
{
    using namespace Foam::meshless::ulphOperators;
    using Foam::meshless::effects::wallRepulsion;
    const double r02 = r0*r0;
    Foam::label nPairs = 0;

    #pragma omp parallel for schedule(static) reduction(+:nPairs)
    for (Foam::label i = 0; i < ctx.n; ++i)
    {
        const Eigen::Map<const vectorD<Dim>> xi(ctx.x + size_t(i)*Dim);
        vectorD<Dim> s = vectorD<Dim>::Zero();
        for (size_t k = 1; k < ctx.sources.size(); ++k)
        {
            if (!ctx.wallSource[k]) continue;
            const auto& src = ctx.sources[k];
            for (const Foam::label* jp = src.list->begin(i); jp != src.list->end(i); ++jp)
            {
                const vectorD<Dim> xji =
                    xi - Eigen::Map<const vectorD<Dim>>(src.x + size_t(*jp)*Dim);
                const double r2 = xji.squaredNorm();
                if (r2 < r02 && r2 > 0)
                {
                    const double r = std::sqrt(r2);
                    s += (wallRepulsion::magnitude(r, D, r0, p1, p2)/r)*xji;
                    ++nPairs;
                }
            }
        }
        Eigen::Map<vectorD<Dim>>(a + size_t(i)*Dim) += s;
    }
    return nPairs;
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
    return ctx.dim == 2
        ? addImpl<2>(ctx, D, r0, p1, p2, acc)
        : addImpl<3>(ctx, D, r0, p1, p2, acc);
}


void Foam::meshless::effects::wallRepulsion::addPairAcceleration
(
    const pairContext& ctx,
    particleField& acc
) const
{
    add(ctx, D_, r0_, p1_, p2_, acc.data());
}


void Foam::meshless::effects::wallRepulsion::describe(Ostream& os) const
{
    os  << "wall repulsion (Monaghan 1994 Lennard-Jones), D " << D_
        << " m^2/s^2, range " << r0_ << " m, exponents (" << p1_ << ' '
        << p2_ << ')';
}
