/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "artificialViscosity.H"
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
    defineTypeNameAndDebug(artificialViscosity, 0);
    addToRunTimeSelectionTable(effect, artificialViscosity, dictionary);
}
}
}


Foam::meshless::effects::artificialViscosity::artificialViscosity
(
    const word& name,
    const dictionary& dict,
    particleBody& body
)
:
    effect(name, dict, body),
    alpha_(readPositive(dict, "alpha"))
{
    if (alpha_ > 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'alpha' is " << alpha_
            << ": expected a value in (0, 1] (the paper uses 0 to 0.5)"
            << exit(FatalIOError);
    }
}


namespace
{

//- Eq. 26 summed over a particle's neighbours: sum_J w pi_IJ x_IJ V_J for
//  approaching pairs, pi = v_IJ.x_IJ/(|x_IJ|^2 + 0.01 h^2); times
//  coeff/rho_I M_I^-1 into the acceleration
template<int Dim>
struct viscousTerm
{
    typedef Foam::meshless::vectorD<Dim> sum;
    typedef const double* source;
    const Foam::meshless::pairContext* ctx;
    double eps2;
    double coeff;
    double* a;

    sum start(const Foam::label) const { return sum::Zero(); }
    source at(const Foam::meshless::pairSource&, const Foam::label k) const
    {
        return ctx->Usrc[k];
    }
    void pair
    (
        sum& s, const source& U, const Foam::meshless::pairView& v,
        const Foam::label i, const Foam::label q
    ) const
    {
        using namespace Foam::meshless;
        const Foam::label j = v.j[q];
        const auto xij = v.x<Dim>(q);
        const vectorD<Dim> uij = cvec<Dim>(U, j) - cvec<Dim>(ctx->U, i);
        const double vx = uij.dot(xij);
        if (vx < 0)
        {
            const double pi = vx/(xij.squaredNorm() + eps2);
            s += (v.w[q]*pi*v.V[j])*xij;
        }
    }
    void finish(const Foam::label i, sum& s) const
    {
        using namespace Foam::meshless;
        vec<Dim>(a, i) += (coeff/ctx->rho[i])*(ctens<Dim>(ctx->Minv, i)*s);
    }
};

} // End anonymous namespace


template<int Dim>
void Foam::meshless::effects::artificialViscosity::add
(
    const pairContext& ctx,
    particleField& acc
) const
{
    const double h = ctx.W->h();
    gather
    (
        ctx.n, ctx.sources,
        viscousTerm<Dim>{&ctx, 0.01*h*h, alpha_*h*ctx.c0*ctx.rho0, acc.data()}
    );
}


void Foam::meshless::effects::artificialViscosity::addPairAcceleration
(
    const pairContext& ctx,
    particleField& acc
) const
{
    dispatchDim(ctx.dim, [&](auto d) { add<d>(ctx, acc); });
}


void Foam::meshless::effects::artificialViscosity::describe(Ostream& os) const
{
    os  << "artificial viscosity (ULPH eq. 26), alpha " << alpha_;
}
