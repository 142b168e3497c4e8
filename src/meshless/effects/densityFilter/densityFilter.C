/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "densityFilter.H"
#include "dispatchDim.H"
#include "pairLoop.H"
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


namespace
{

//- Shepard's sums (eq. 24) of a particle, and with Fit the moments of the
//  MLS fit (Shepard's value its fallback)
template<int Dim, bool Fit>
struct filterTerm
{
    typedef Eigen::Matrix<double, Dim + 1, Dim + 1> matrix;
    typedef Eigen::Matrix<double, Dim + 1, 1> vector;
    struct sum
    {
        double sumM, sumV, rhoMin, rhoMax;
        matrix A;
        vector b;
    };
    struct source { const double* m; bool own; };

    const Foam::meshless::pairContext* ctx;
    double W0;
    double invH;
    double* out;

    sum start(const Foam::label i) const
    {
        const double Vi = ctx->mass[i]/ctx->rho[i];
        sum s{W0*ctx->mass[i], W0*Vi, ctx->rho[i], ctx->rho[i], {}, {}};
        if (Fit)
        {
            s.A = matrix::Zero();
            s.b = vector::Zero();
            s.A(0, 0) = W0*Vi;
            s.b(0) = W0*ctx->mass[i];
        }
        return s;
    }
    source at(const Foam::meshless::pairSource&, const Foam::label k) const
    {
        return {ctx->massSrc[k], k == 0};
    }
    void pair
    (
        sum& s, const source& src, const Foam::meshless::pairView& v,
        const Foam::label, const Foam::label q
    ) const
    {
        const Foam::label j = v.j[q];
        const double w = v.w[q];
        // Own particles: V = m/rho now; walls: their volume
        const double Vj = src.own ? src.m[j]/ctx->rho[j] : v.V[j];
        s.sumM += w*src.m[j];
        s.sumV += w*Vj;
        if (Fit)
        {
            vector p;
            p(0) = 1;
            for (Foam::label d = 0; d < Dim; ++d)
            {
                p(d + 1) = v.xij[size_t(q)*Dim + d]*invH;
            }
            s.A.noalias() += (w*Vj)*p*p.transpose();
            s.b.noalias() += (w*src.m[j])*p;
            const double rhoj = src.m[j]/Vj;
            s.rhoMin = std::min(s.rhoMin, rhoj);
            s.rhoMax = std::max(s.rhoMax, rhoj);
        }
    }
    void finish(const Foam::label i, sum& s) const
    {
        double rho = s.sumM/s.sumV;
        if (Fit)
        {
            Eigen::SelfAdjointEigenSolver<matrix> eig
            (
                s.A, Eigen::EigenvaluesOnly
            );
            const vector lambda = eig.eigenvalues();
            if (lambda(0) > 1e-3*lambda(Dim))
            {
                // Within the densities it fits: a fit that extrapolates
                // (a thin jet) must not invent a density
                const double fit = s.A.ldlt().solve(s.b)(0);
                if (std::isfinite(fit))
                {
                    rho = std::min(std::max(fit, s.rhoMin), s.rhoMax);
                }
            }
        }
        out[i] = rho;
    }
};

} // End anonymous namespace


template<int Dim, bool Fit>
void Foam::meshless::effects::densityFilter::filterPass
(
    const pairContext& ctx,
    double* out
)
{
    const smoothingKernel& W = *ctx.W;
    // Offsets in units of h keep A's blocks of one order of magnitude
    gather
    (
        ctx.n, ctx.sources,
        filterTerm<Dim, Fit>{&ctx, W.W(0), 1.0/W.h(), out}
    );
}


void Foam::meshless::effects::densityFilter::filter
(
    const pairContext& ctx,
    const methodType method,
    double* out
)
{
    const bool fit = method == methodType::MLS;
    dispatchDim(ctx.dim, [&](auto d)
    {
        fit ? filterPass<d, true>(ctx, out) : filterPass<d, false>(ctx, out);
    });
}


void Foam::meshless::effects::densityFilter::correct
(
    const pairContext& ctx,
    const label timeIndex
) const
{
    if (!correctsAt(timeIndex)) return;

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
