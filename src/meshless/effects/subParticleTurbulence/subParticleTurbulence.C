/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "subParticleTurbulence.H"
#include "viscosity.H"
#include "correctionMatrix.H"
#include "dispatchDim.H"
#include "pairLoop.H"
#include "addToRunTimeSelectionTable.H"
#include <algorithm>
#include <cmath>

namespace Foam
{
namespace meshless
{
namespace effects
{
    defineTypeNameAndDebug(subParticleTurbulence, 0);
    addToRunTimeSelectionTable(effect, subParticleTurbulence, dictionary);
}
}
}


namespace
{

using Foam::label;
using Foam::meshless::pairView;
using Foam::meshless::vectorD;
using Foam::meshless::tensorD;
typedef Foam::meshless::effects::subParticleTurbulence::sourceData
    sourceData;

//- Regularisation of 1/r in the Laplacian (as the fluid's viscous term)
constexpr double epsRatio = 0.01;


//- The corrected velocity gradient and eq. 10's eddy viscosity
template<int Dim>
struct eddyViscosityTerm
{
    struct sum
    {
        tensorD<Dim> M;
        tensorD<Dim> S;
    };
    typedef const sourceData* source;

    const sourceData* src;
    const double* U;
    double CsH2;
    double* nut;

    sum start(const label) const
    {
        return {tensorD<Dim>::Zero(), tensorD<Dim>::Zero()};
    }
    source at(const Foam::meshless::pairSource&, const label k) const
    {
        return src + k;
    }
    void pair
    (
        sum& s, const source& S, const pairView& v, const label i,
        const label q
    ) const
    {
        const label j = v.j[q];
        const double c = Foam::meshless::gradientFactor(v, q)*v.V[j];
        if (c == 0) return;
        const auto x = v.x<Dim>(q);
        const vectorD<Dim> du =
            Foam::meshless::cvec<Dim>(S->U, j)
          - Foam::meshless::cvec<Dim>(U, i);
        s.M.noalias() += c*(x*x.transpose());
        s.S.noalias() += c*(du*x.transpose());
    }
    void finish(const label i, sum& s) const
    {
        tensorD<Dim> Minv;
        Foam::meshless::correctionMatrix::robustInverse<Dim>(s.M, Minv);
        const tensorD<Dim> G = s.S*Minv;
        const tensorD<Dim> eps = 0.5*(G + G.transpose());
        nut[i] = CsH2*std::sqrt(2*eps.squaredNorm());
    }
};


//- The eddy-viscous acceleration (Morris form, pair viscosity of eq. 13)
template<int Dim>
struct eddyLaplacianTerm
{
    typedef vectorD<Dim> sum;
    typedef const sourceData* source;

    const sourceData* src;
    const double* U;
    const double* rho;
    const double* nut;
    double lambda;
    double eps;
    double* a;

    sum start(const label) const { return sum::Zero(); }
    source at(const Foam::meshless::pairSource&, const label k) const
    {
        return src + k;
    }
    void pair
    (
        sum& s, const source& S, const pairView& v, const label i,
        const label q
    ) const
    {
        if (!S->fluid && !S->noSlip) return;
        const label j = v.j[q];
        const double F = v.dw[q]/(v.r[q] + eps);
        if (F == 0) return;
        const vectorD<Dim> du =
            Foam::meshless::cvec<Dim>(U, i)
          - Foam::meshless::cvec<Dim>(S->U, j);
        if (S->fluid)
        {
            s.noalias() +=
                (v.V[j]*(rho[i]*nut[i] + rho[j]*nut[j])*F)*du;
        }
        else
        {
            // The boundary's particle with the fluid particle's nu^t, the
            // mirrored no-slip velocity difference 2 (u_i - v_s)
            s.noalias() += (4*v.V[j]*rho[i]*nut[i]*F)*du;
        }
    }
    void finish(const label i, sum& s) const
    {
        Foam::meshless::vec<Dim>(a, i) += (lambda/rho[i])*s;
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::effects::subParticleTurbulence::subParticleTurbulence
(
    const word& name,
    const dictionary& dict,
    particleBody& body
)
:
    effect(name, dict, body),
    Cs_(readCs(dict)),
    nut_
    (
        body.particles().addScratchField
        (
            "eddyViscosity", particleField::kind::scalar
        )
    ),
    lambda_
    (
        // Without a kernel the model check rejects the body (isph has one)
        body.hasKernel()
      ? normalisation(body.kernel(), body.dim(), body.spacing())
      : 0
    ),
    nutMax_(0),
    src_()
{}


// * * * * * * * * * * * * * * * Static Functions * * * * * * * * * * * * * //

Foam::scalar Foam::meshless::effects::subParticleTurbulence::readCs
(
    const dictionary& dict
)
{
    if (!dict.found("Cs")) return 0.1;
    const ITstream& is = dict.lookup("Cs");
    if (is.size() != 1 || !is[0].isNumber() || !(is[0].number() > 0))
    {
        OStringStream given;
        forAll(is, k) given << (k ? " " : "") << is[k];
        FatalIOErrorInFunction(dict)
            << "Entry 'Cs' is '" << given.str().c_str() << "'"
            << ": expected a number > 0 (the Smagorinsky constant of the"
            << " sub-particle-scale eddy viscosity, e.g. Cs 0.1)"
            << exit(FatalIOError);
    }
    return is[0].number();
}


Foam::scalar Foam::meshless::effects::subParticleTurbulence::normalisation
(
    const smoothingKernel& W,
    const label dim,
    const scalar dx
)
{
    const double eps = epsRatio*W.h();
    return dispatchDim(dim, [&](auto d)
    {
        constexpr int Dim = decltype(d)::value;
        const double V = std::pow(dx, Dim);
        const double s = correctionMatrix::latticeSum<Dim>
        (
            W, dx, [&](const double r2)
            {
                const double r = std::sqrt(r2);
                return W.dWdr(r)*r2*V/(r + eps);
            }
        );
        return s < 0 ? -Dim/s : 0.0;
    });
}


void Foam::meshless::effects::subParticleTurbulence::sources
(
    const pairContext& ctx,
    std::vector<sourceData>& src
)
{
    const size_t nSrc = ctx.sources.size();
    src.resize(nSrc);
    for (size_t k = 0; k < nSrc; ++k)
    {
        const double* U =
            k == 0 ? ctx.U
          : (k < ctx.Uown.size() && ctx.Uown[k]) ? ctx.Uown[k]
          : ctx.Usrc[k];
        src[k] = sourceData
        {
            U, k == 0, k == 0 || k >= ctx.noSlip.size() || ctx.noSlip[k]
        };
    }
}


Foam::scalar Foam::meshless::effects::subParticleTurbulence::eddyViscosity
(
    const pairContext& ctx,
    const sourceData* src,
    const scalar Cs,
    double* nut
)
{
    const double CsH = Cs*ctx.W->h();
    dispatchDim(ctx.dim, [&](auto d)
    {
        gather
        (
            ctx.n, ctx.sources,
            eddyViscosityTerm<d>{src, ctx.U, CsH*CsH, nut}
        );
    });
    double nutMax = 0;
    for (label i = 0; i < ctx.n; ++i) nutMax = std::max(nutMax, nut[i]);
    return nutMax;
}


void Foam::meshless::effects::subParticleTurbulence::addAcceleration
(
    const pairContext& ctx,
    const sourceData* src,
    const double* nut,
    const scalar lambda,
    double* acc
)
{
    const double eps = epsRatio*ctx.W->h();
    dispatchDim(ctx.dim, [&](auto d)
    {
        gather
        (
            ctx.n, ctx.sources,
            eddyLaplacianTerm<d>
            {
                src, ctx.U, ctx.rho, nut, lambda, eps, acc
            }
        );
    });
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::effects::subParticleTurbulence::addPairAcceleration
(
    const pairContext& ctx,
    particleField& acc
) const
{
    sources(ctx, src_);
    nutMax_ = eddyViscosity(ctx, src_.data(), Cs_, nut_.data());
    addAcceleration(ctx, src_.data(), nut_.data(), lambda_, acc.data());
}


Foam::scalar Foam::meshless::effects::subParticleTurbulence::maxDeltaT() const
{
    const viscosity* visc = findEffect<viscosity>(body_);
    const scalar nu = visc ? visc->mu()/body_.density() : 0;
    if (!(nu + nutMax_ > 0) || !body_.hasKernel()) return GREAT;
    const scalar h = body_.kernel().h();
    return 0.125*h*h/(nu + nutMax_);
}


void Foam::meshless::effects::subParticleTurbulence::describe
(
    Ostream& os
) const
{
    os  << "sub-particle-scale turbulence (Smagorinsky eddy viscosity,"
        << " Gotoh et al. 2000), Cs " << Cs_ << ", Delta = h";
}


// ************************************************************************* //
