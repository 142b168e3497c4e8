/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "artificialViscosity.H"
#include "ulphOperators.H"
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


template<int Dim>
void Foam::meshless::effects::artificialViscosity::add
(
    const pairContext& ctx,
    particleField& acc
) const
{
    using namespace ulphOperators;
    const smoothingKernel& W = *ctx.W;
    const double h = W.h();
    const double eps2 = 0.01*h*h;
    const double coeff = alpha_*h*ctx.c0*ctx.rho0;
    double* a = acc.data();

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < ctx.n; ++i)
    {
        const Eigen::Map<const vectorD<Dim>> xi(ctx.x + size_t(i)*Dim);
        const Eigen::Map<const vectorD<Dim>> ui(ctx.U + size_t(i)*Dim);
        vectorD<Dim> s = vectorD<Dim>::Zero();
        for (size_t k = 0; k < ctx.sources.size(); ++k)
        {
            const neighbourSource& src = ctx.sources[k];
            for (const label* jp = src.list->begin(i); jp != src.list->end(i); ++jp)
            {
                const label j = *jp;
                const vectorD<Dim> xij =
                    Eigen::Map<const vectorD<Dim>>(src.x + size_t(j)*Dim) - xi;
                const vectorD<Dim> uij =
                    Eigen::Map<const vectorD<Dim>>(ctx.Usrc[k] + size_t(j)*Dim)
                  - ui;
                const double vx = uij.dot(xij);
                if (vx < 0)
                {
                    const double pi = vx/(xij.squaredNorm() + eps2);
                    const double w = src.pairW(jp, xij.norm(), W);
                    s += (w*pi*src.V[j])*xij;
                }
            }
        }
        const Eigen::Map<const tensorD<Dim>> Mi(ctx.Minv + size_t(i)*Dim*Dim);
        Eigen::Map<vectorD<Dim>>(a + size_t(i)*Dim) +=
            (coeff/ctx.rho[i])*(Mi*s);
    }
}


void Foam::meshless::effects::artificialViscosity::addPairAcceleration
(
    const pairContext& ctx,
    particleField& acc
) const
{
    if (ctx.dim == 2) add<2>(ctx, acc);
    else add<3>(ctx, acc);
}


void Foam::meshless::effects::artificialViscosity::describe(Ostream& os) const
{
    os  << "artificial viscosity (ULPH eq. 26), alpha " << alpha_;
}
