/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "densityFilter.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include <cmath>

namespace Foam
{
namespace meshless
{
namespace effects
{
    defineTypeNameAndDebug(densityFilter, 0);
    addToRunTimeSelectionTable(effect, densityFilter, dictionary);
}
}
}


Foam::meshless::effects::densityFilter::densityFilter
(
    const word& name,
    const dictionary& dict,
    particleBody& body
)
:
    effect(name, dict, body),
    interval_(readLabelInRange(dict, "interval", 1, labelMax)),
    filtered_()
{}


void Foam::meshless::effects::densityFilter::correct
(
    const pairContext& ctx,
    const label timeIndex
) const
{
    if (timeIndex % interval_ != 0) return;

    const smoothingKernel& W = *ctx.W;
    const label dim = ctx.dim;
    const double W0 = W.W(0);
    filtered_.resize(ctx.n);

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < ctx.n; ++i)
    {
        double sumM = W0*ctx.mass[i];
        double sumV = W0*ctx.mass[i]/ctx.rho[i];
        for (size_t k = 0; k < ctx.sources.size(); ++k)
        {
            const neighbourSource& src = ctx.sources[k];
            const double* m = ctx.massSrc[k];
            for (const label* jp = src.list->begin(i); jp != src.list->end(i); ++jp)
            {
                const label j = *jp;
                double r2 = 0;
                for (label d = 0; d < dim; ++d)
                {
                    const double dx = src.x[j*dim + d] - ctx.x[i*dim + d];
                    r2 += dx*dx;
                }
                const double w = W.W(std::sqrt(r2));
                // Own particles: V = m/rho now; walls: their volume
                const double Vj = k == 0 ? m[j]/ctx.rho[j] : src.V[j];
                sumM += w*m[j];
                sumV += w*Vj;
            }
        }
        filtered_[i] = sumM/sumV;
    }
    std::copy(filtered_.begin(), filtered_.end(), ctx.rho);
}


void Foam::meshless::effects::densityFilter::describe(Ostream& os) const
{
    os  << "Shepard density filter (ULPH eq. 24) every " << interval_
        << " steps";
}
