/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "densityFilter.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include <Eigen/Dense>
#include <algorithm>
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


const Foam::Enum<Foam::meshless::effects::densityFilter::methodType>
Foam::meshless::effects::densityFilter::methodTypeNames
({
    { methodType::Shepard, "Shepard" },
    { methodType::MLS, "MLS" },
});


Foam::meshless::effects::densityFilter::densityFilter
(
    const word& name,
    const dictionary& dict,
    particleBody& body
)
:
    effect(name, dict, body),
    interval_(readLabelInRange(dict, "interval", 1, labelMax)),
    method_
    (
        methodTypeNames.getOrDefault("method", dict, methodType::Shepard)
    ),
    filtered_()
{}


template<int Dim, bool Fit>
void Foam::meshless::effects::densityFilter::filterPass
(
    const pairContext& ctx,
    double* out
)
{
    typedef Eigen::Matrix<double, Dim + 1, Dim + 1> matrix;
    typedef Eigen::Matrix<double, Dim + 1, 1> vector;

    const smoothingKernel& W = *ctx.W;
    const double W0 = W.W(0);
    // Offsets in units of h keep A's blocks of one order of magnitude
    const double invH = 1.0/W.h();

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < ctx.n; ++i)
    {
        const double Vi = ctx.mass[i]/ctx.rho[i];
        // Shepard's sums (eq. 24), and the fit's moments when fitting
        double sumM = W0*ctx.mass[i];
        double sumV = W0*Vi;
        matrix A = matrix::Zero();
        vector b = vector::Zero();
        double rhoMin = ctx.rho[i], rhoMax = ctx.rho[i];
        if (Fit)
        {
            A(0, 0) = W0*Vi;
            b(0) = W0*ctx.mass[i];
        }
        for (size_t k = 0; k < ctx.sources.size(); ++k)
        {
            const neighbourSource& src = ctx.sources[k];
            const double* m = ctx.massSrc[k];
            for (const label* jp = src.list->begin(i); jp != src.list->end(i); ++jp)
            {
                const label j = *jp;
                vector p;
                p(0) = 1;
                double r2 = 0;
                for (label d = 0; d < Dim; ++d)
                {
                    const double dx = src.x[j*Dim + d] - ctx.x[i*Dim + d];
                    p(d + 1) = dx*invH;
                    r2 += dx*dx;
                }
                const double w = W.W(std::sqrt(r2));
                // Own particles: V = m/rho now; walls: their volume
                const double Vj = k == 0 ? m[j]/ctx.rho[j] : src.V[j];
                sumM += w*m[j];
                sumV += w*Vj;
                if (Fit)
                {
                    A.noalias() += (w*Vj)*p*p.transpose();
                    b.noalias() += (w*m[j])*p;
                    const double rhoj = m[j]/Vj;
                    rhoMin = std::min(rhoMin, rhoj);
                    rhoMax = std::max(rhoMax, rhoj);
                }
            }
        }

        double rho = sumM/sumV;
        if (Fit)
        {
            Eigen::SelfAdjointEigenSolver<matrix> eig
            (
                A, Eigen::EigenvaluesOnly
            );
            const vector lambda = eig.eigenvalues();
            if (lambda(0) > 1e-3*lambda(Dim))
            {
                // Within the densities it fits: a fit that extrapolates
                // (a thin jet) must not invent a density
                const double fit = A.ldlt().solve(b)(0);
                if (std::isfinite(fit))
                {
                    rho = std::min(std::max(fit, rhoMin), rhoMax);
                }
            }
        }
        out[i] = rho;
    }
}


void Foam::meshless::effects::densityFilter::filter
(
    const pairContext& ctx,
    const methodType method,
    double* out
)
{
    const bool fit = method == methodType::MLS;
    if (ctx.dim == 2)
    {
        fit ? filterPass<2, true>(ctx, out) : filterPass<2, false>(ctx, out);
    }
    else
    {
        fit ? filterPass<3, true>(ctx, out) : filterPass<3, false>(ctx, out);
    }
}


void Foam::meshless::effects::densityFilter::correct
(
    const pairContext& ctx,
    const label timeIndex
) const
{
    if (timeIndex % interval_ != 0) return;

    // A Jacobi update: every particle filtered from the old densities
    filtered_.resize(ctx.n);
    filter(ctx, method_, filtered_.data());
    std::copy(filtered_.begin(), filtered_.end(), ctx.rho);
}


void Foam::meshless::effects::densityFilter::describe(Ostream& os) const
{
    os  << (method_ == methodType::MLS
            ? "MLS density filter (linear fit)"
            : "Shepard density filter (ULPH eq. 24)")
        << " every " << interval_ << " steps";
}
