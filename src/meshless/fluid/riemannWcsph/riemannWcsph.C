/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "riemannWcsph.H"
#include "particleScene.H"
#include "effect.H"
#include "viscosity.H"
#include "transportVelocity.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include "dispatchDim.H"
#include <algorithm>
#include <cmath>

namespace Foam
{
namespace meshless
{
namespace bodyModels
{
    defineTypeNameAndDebug(riemannWcsph, 0);
    addToRunTimeSelectionTable(bodyModel, riemannWcsph, dictionary);
    addModelRole(riemannWcsph, fluid);
}
}
}


const Foam::Enum<Foam::meshless::bodyModels::riemannWcsph::correctionType>
Foam::meshless::bodyModels::riemannWcsph::correctionTypeNames
({
    { correctionType::none, "none" },
    { correctionType::KGC, "KGC" },
    { correctionType::RKGC, "RKGC" },
    { correctionType::WKGC, "WKGC" },
});


const Foam::Enum<Foam::meshless::riemannEquations::limiterType>
Foam::meshless::bodyModels::riemannWcsph::limiterTypeNames
({
    { riemannEquations::limiterType::compression, "compression" },
    { riemannEquations::limiterType::expansion, "expansion" },
    { riemannEquations::limiterType::full, "full" },
    { riemannEquations::limiterType::none, "none" },
});


const Foam::Enum<bool>
Foam::meshless::bodyModels::riemannWcsph::laplacianNames
({
    { true, "normalised" },
    { false, "morris" },
});


const Foam::Enum<bool>
Foam::meshless::bodyModels::riemannWcsph::wallPressureNames
({
    { true, "clipped" },
    { false, "linear" },
});


namespace
{
    Foam::word densityReinitialisationWord(const Foam::dictionary& dict)
    {
        const Foam::word w =
            dict.getOrDefault<Foam::word>
            (
                "densityReinitialisation",
                "freeSurface"
            );
        if (w != "freeSurface" && w != "internal")
        {
            FatalIOErrorInFunction(dict)
                << "densityReinitialisation " << w << ": expected freeSurface"
                << " (summation, at least rho0) or internal (summation)"
                << Foam::exit(Foam::FatalIOError);
        }
        return w;
    }
}


Foam::meshless::bodyModels::riemannWcsph::riemannWcsph
(
    particleBody& body,
    const dictionary& dict
)
:
    fluidModel(body, dict),
    c0_(readPositive(dict, "soundSpeed")),
    acousticCourant_(readPositiveOrDefault(dict, "acousticCourant", 0.6)),
    referenceSpeed_(readPositiveOrDefault(dict, "referenceSpeed", 0.1*c0_)),
    correction_(correctionTypeNames.get("kernelCorrection", dict)),
    wkgcAlpha_(0),
    limiter_
    (
        limiterTypeNames.getOrDefault
        (
            "dissipationLimiter", dict, riemannEquations::limiterType::compression
        )
    ),
    freeSurface_(densityReinitialisationWord(dict) == "freeSurface"),
    clipWallPressure_
    (
        wallPressureNames.getOrDefault("wallPressure", dict, false)
    ),
    normaliseLaplacian_
    (
        laplacianNames.getOrDefault("viscousLaplacian", dict, false)
    ),
    summationNorm_(0),
    drho_(body.particles().addField("densityRate", particleField::kind::scalar)),
    aDiss_
    (
        body.particles().addField
        (
            "dissipativeAcceleration", particleField::kind::vector
        )
    ),
    acc_(body.particles().addField("acceleration", particleField::kind::vector)),
    B_(body.particles().addScratchField("B", particleField::kind::tensor)),
    aP_(body.particles().addScratchField("aPressure", particleField::kind::vector)),
    aPrior_(body.particles().addScratchField("aPrior", particleField::kind::vector)),
    dx_(body.particles().addScratchField("dxTransport", particleField::kind::vector)),
    mu_(0),
    viscosityEffect_(nullptr),
    transport_(nullptr),
    acoustic_(body.name(), 1, "acoustic steps per advection step"),
    summationCost_(-1),
    correctionCost_(-1),
    acousticCost_(-1)
{
    if (correction_ == correctionType::WKGC)
    {
        wkgcAlpha_ = readPositive(dict, "wkgcAlpha");
    }
    else if (dict.found("wkgcAlpha"))
    {
        FatalIOErrorInFunction(dict)
            << "wkgcAlpha is the weight of kernelCorrection WKGC, but"
            << " kernelCorrection is " << correctionTypeNames[correction_]
            << ": expected no wkgcAlpha, or kernelCorrection WKGC"
            << exit(FatalIOError);
    }

    // The geometry is that of the advection step's start: no skin
    if (!dict.found("neighbourSkin")) skin_ = 0;

    // Without a correction B = I throughout (the transport velocity's
    // weights B_i + B_j)
    if (correction_ == correctionType::none)
    {
        const label dim = body.dim();
        for (label i = 0; i < B_.size(); ++i)
        {
            for (label d = 0; d < dim; ++d) B_(i, d*dim + d) = 1;
        }
    }
}


Foam::scalar Foam::meshless::bodyModels::riemannWcsph::pressureOf
(
    const scalar rho
) const
{
    return c0_*c0_*(rho - rho0_);
}


Foam::scalar Foam::meshless::bodyModels::riemannWcsph::densityOf
(
    const scalar p
) const
{
    return rho0_ + p/(c0_*c0_);
}


void Foam::meshless::bodyModels::riemannWcsph::connectModel(particleScene&)
{
    if (const auto* visc = findEffect<effects::viscosity>(body_))
    {
        mu_ = visc->mu();
        viscosityEffect_ = visc;
    }
    transport_ = findEffect<effects::transportVelocity>(body_);

    // Pair geometry: x_ij, r, W (summation) and dW/dr (everything else)
    own_->cache(neighbourRelation::kernelGradient);
    for (boundary& b : boundaries_) boundaryAdded(b);

    // Kernel sum of a full lattice at the body's spacing, self included
    const smoothingKernel& W = body_.kernel();
    const scalar dx = body_.spacing();
    const scalar sigma0 = dispatchDim(body_.dim(), [&](auto d)
    {
        return correctionMatrix::latticeSum<d>
        (
            W, dx, [&](const double r2) { return W.W(std::sqrt(r2)); }
        );
    });
    summationNorm_ = 1/(sigma0*std::pow(dx, body_.dim()));
}


void Foam::meshless::bodyModels::riemannWcsph::boundaryAdded(boundary& b)
{
    b.toGhosts->cache(neighbourRelation::kernelGradient);
    if (b.ghosts->reaction())
    {
        b.fromGhosts->cache(neighbourRelation::kernelGradient);

        // The reaction of the dissipation of the last acoustic step, which
        // the next one applies, as the fluid its own (written: restart)
        b.ghosts->ghostBody().particles().addField
        (
            "fluidDissipativeForce", particleField::kind::vector
        );
    }
}


bool Foam::meshless::bodyModels::riemannWcsph::anyReaction() const
{
    for (const boundary& b : boundaries_)
    {
        if (b.ghosts->reaction()) return true;
    }
    return false;
}


template<int Dim>
void Foam::meshless::bodyModels::riemannWcsph::pressureReactions
(
    const double* rho,
    const double* aPrior,
    const double rho0c0,
    const bool last
)
{
    using riemannEquations::pressureReaction;
    const double* B = correction_ == correctionType::none ? nullptr : B_.data();
    for (size_t k = 0; k < boundaries_.size(); ++k)
    {
        boundary& b = boundaries_[k];
        double* R = b.ghosts->reaction();
        if (!R) continue;
        const std::vector<double>& Rv = viscousReaction_[k];
        const particleField& Rd =
            b.ghosts->ghostBody().particles().field("fluidDissipativeForce");
        const label nR = Rv.size();
        for (label c = 0; c < nR; ++c) R[c] = Rv[c] + Rd.data()[c];
        pressureReaction<Dim>
        (
            *b.fromGhosts, src_[k + 1], b.ghosts->V(), p_.data(), rho, B,
            aPrior, V_.data(), R
        );
        if (!last) continue;

        // The boundary's force on the fluid from the fluid's own terms:
        // the momentum equation's sums over this boundary alone
        pressure<Dim>(rho, aPrior, rho0c0, k);
        b.forceOnFluid =
            boundaryForce<Dim>() + viscousOnFluid_[k] + dissipativeOnFluid_[k];
    }
}


template<int Dim>
void Foam::meshless::bodyModels::riemannWcsph::dissipationReactions
(
    const double* U,
    const double* rho,
    const double rho0c0
)
{
    for (size_t k = 0; k < boundaries_.size(); ++k)
    {
        if (!boundaries_[k].ghosts->reaction()) continue;
        dissipation<Dim>(U, rho, rho0c0, k);
        dissipativeOnFluid_[k] = boundaryForce<Dim>();
    }
}


template<int Dim>
Foam::vector Foam::meshless::bodyModels::riemannWcsph::boundaryForce() const
{
    // Over the own particles (a parallel run's halo is another's)
    const label n = body_.particles().nOwned();
    const double* m = mass_.data();
    vectorD<Dim> f = vectorD<Dim>::Zero();
    for (label i = 0; i < n; ++i) f += m[i]*cvec<Dim>(aBoundary_.data(), i);
    vector F(Zero);
    for (int d = 0; d < Dim; ++d) F[d] = f(d);
    return F;
}


template<int Dim>
void Foam::meshless::bodyModels::riemannWcsph::viscousReactions()
{
    using namespace riemannEquations;
    viscousReaction_.resize(boundaries_.size());
    viscousOnFluid_.assign(boundaries_.size(), Zero);
    if (dissipativeOnFluid_.size() != boundaries_.size())
    {
        // A start or a restart: the carried reaction read (or zero), and
        // its fluid's side, equal and opposite
        dissipativeOnFluid_.assign(boundaries_.size(), Zero);
        for (size_t k = 0; k < boundaries_.size(); ++k)
        {
            if (!boundaries_[k].ghosts->reaction()) continue;
            const particleSet& ws =
                boundaries_[k].ghosts->ghostBody().particles();
            const particleField& Rd = ws.field("fluidDissipativeForce");
            for (label i = 0; i < Rd.size(); ++i)
            {
                if (!ws.owns(i)) continue;
                for (label d = 0; d < Rd.nComponents(); ++d)
                {
                    dissipativeOnFluid_[k][d] -= Rd(i, d);
                }
            }
        }
    }
    const double eps = 0.01*body_.kernel().h();
    for (size_t k = 0; k < boundaries_.size(); ++k)
    {
        boundary& b = boundaries_[k];
        if (!b.ghosts->reaction()) continue;
        const label nw = b.fromGhosts->size();
        std::vector<double>& R = viscousReaction_[k];
        R.assign(size_t(nw)*Dim, 0);
        const sourceData& S = src_[k + 1];
        if (!viscosityEffect_ || !S.noSlip) continue;
        const double* Vw = b.ghosts->V();
        viscousReaction<Dim>
        (
            *b.fromGhosts, S, Vw, U_.data(), mass_.data(),
            viscousFactor_.data(), eps, R.data()
        );

        // The same pairs from the fluid's side
        const double* f = viscousFactor_.data();
        const double* U = U_.data();
        const double* m = mass_.data();
        const label* off = b.toGhosts->offsetData();
        const label* idx = b.toGhosts->indexData();
        const double* r = b.toGhosts->r();
        const double* dw = b.toGhosts->dw();
        vectorD<Dim> F = vectorD<Dim>::Zero();
        for (label i = 0; i < body_.particles().nOwned(); ++i)
        {
            for (label q = off[i]; q < off[i + 1]; ++q)
            {
                const label w = idx[q];
                const double c = dw[q]*Vw[w]/(r[q] + eps);
                F += (m[i]*f[i]*2*c)*(cvec<Dim>(U, i) - cvec<Dim>(S.U, w));
            }
        }
        for (int d = 0; d < Dim; ++d) viscousOnFluid_[k][d] = F(d);
    }
}


void Foam::meshless::bodyModels::riemannWcsph::resizedModel()
{
    setSources();
}


void Foam::meshless::bodyModels::riemannWcsph::setSources()
{
    using riemannEquations::sourceData;
    src_.resize(1 + boundaries_.size());
    invR_.resize(1 + boundaries_.size());
    src_[0] = sourceData
    {
        true, p_.data(), B_.data(), U_.data(), nullptr, nullptr, true,
        clipWallPressure_, nullptr, nullptr
    };
    for (size_t k = 0; k < boundaries_.size(); ++k)
    {
        const ghostBoundary& g = *boundaries_[k].ghosts;
        src_[k + 1] = sourceData
        {
            false, nullptr, nullptr, g.U(), g.accelerations(), g.normals(),
            g.slipNormals() == nullptr, clipWallPressure_, nullptr, nullptr
        };
    }
}


void Foam::meshless::bodyModels::riemannWcsph::updatePressure()
{
    const label n = rho_.size();
    const double* rho = rho_.data();
    const double* m = mass_.data();
    double* p = p_.data();
    double* V = V_.data();
    const double c2 = c0_*c0_;
    const double rho0 = rho0_;
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        V[i] = m[i]/rho[i];
        p[i] = c2*(rho[i] - rho0);
    }
}


template<int Dim>
void Foam::meshless::bodyModels::riemannWcsph::reinitialiseDensity()
{
    using namespace riemannEquations;
    const label n = rho_.size();
    for (size_t k = 0; k < boundaries_.size(); ++k)
    {
        src_[k + 1].offset = boundaries_[k].ghosts->summationOffsets();
    }
    gather
    (
        n, ctx_.sources,
        summationTerm<Dim>
        {
            src_.data(), mass_.data(), V0_.data(), aPrior_.data(),
            &body_.kernel(), body_.kernel().W(0), summationNorm_, rho0_,
            c0_*c0_,
            freeSurface_, rho_.data()
        }
    );
    updatePressure();
}


template<int Dim, Foam::meshless::riemannEquations::pairing P>
void Foam::meshless::bodyModels::riemannWcsph::pressure
(
    const double* rho,
    const double* aPrior,
    const double rho0c0,
    const label k
)
{
    typedef riemannEquations::pressureTerm<Dim, P> term;
    const label n = U_.size();
    if (k < 0)
    {
        gather
        (
            n, ctx_.sources,
            term
            {
                src_.data(), p_.data(), rho, B_.data(), aPrior, rho0c0,
                aP_.data(), drho_.data()
            }
        );
        return;
    }
    aBoundary_.resize(size_t(n)*Dim);
    drhoBoundary_.resize(n);
    gather
    (
        n, &ctx_.sources[k + 1], 1,
        term
        {
            src_.data() + k + 1, p_.data(), rho, B_.data(), aPrior, rho0c0,
            aBoundary_.data(), drhoBoundary_.data()
        }
    );
}


template<int Dim>
void Foam::meshless::bodyModels::riemannWcsph::pressure
(
    const double* rho,
    const double* aPrior,
    const double rho0c0,
    const label k
)
{
    using riemannEquations::pairing;
    switch (correction_)
    {
        case correctionType::none:
            pressure<Dim, pairing::none>(rho, aPrior, rho0c0, k);
            break;
        case correctionType::KGC:
            pressure<Dim, pairing::kgc>(rho, aPrior, rho0c0, k);
            break;
        default:
            pressure<Dim, pairing::rkgc>(rho, aPrior, rho0c0, k);
            break;
    }
}


template<int Dim, Foam::meshless::riemannEquations::limiterType L>
void Foam::meshless::bodyModels::riemannWcsph::dissipation
(
    const double* U,
    const double* rho,
    const double rho0c0,
    const label k
)
{
    typedef riemannEquations::dissipationTerm<Dim, L> term;
    const label n = U_.size();
    if (k < 0)
    {
        gather
        (
            n, ctx_.sources,
            term
            {
                src_.data(), U, rho, rho0c0, 3/c0_, aDiss_.data(),
                drho_.data()
            }
        );
        return;
    }

    // Boundary k both ways: its reaction into fluidDissipativeForce, the
    // fluid's sum over it alone into aBoundary_
    boundary& b = boundaries_[k];
    particleField& Rd =
        b.ghosts->ghostBody().particles().field("fluidDissipativeForce");
    Rd.fill(0);
    riemannEquations::dissipationReaction<Dim, L>
    (
        *b.fromGhosts, src_[k + 1], b.ghosts->V(), U, rho0c0, 3/c0_,
        V_.data(), Rd.data()
    );
    aBoundary_.assign(size_t(n)*Dim, 0);
    drhoBoundary_.assign(n, 0);
    gather
    (
        n, &ctx_.sources[k + 1], 1,
        term
        {
            src_.data() + k + 1, U, rho, rho0c0, 3/c0_, aBoundary_.data(),
            drhoBoundary_.data()
        }
    );
}


template<int Dim>
void Foam::meshless::bodyModels::riemannWcsph::dissipation
(
    const double* U,
    const double* rho,
    const double rho0c0,
    const label k
)
{
    using riemannEquations::limiterType;
    switch (limiter_)
    {
        case limiterType::compression:
            dissipation<Dim, limiterType::compression>(U, rho, rho0c0, k);
            break;
        case limiterType::expansion:
            dissipation<Dim, limiterType::expansion>(U, rho, rho0c0, k);
            break;
        case limiterType::full:
            dissipation<Dim, limiterType::full>(U, rho, rho0c0, k);
            break;
        case limiterType::none:
            dissipation<Dim, limiterType::none>(U, rho, rho0c0, k);
            break;
    }
}


Foam::scalar Foam::meshless::bodyModels::riemannWcsph::maxDeltaT
(
    const scalar maxCo
) const
{
    const scalar h = body_.kernel().h();
    const label n = U_.size();
    const label dim = body_.dim();
    const double* U = U_.data();
    const double* a = acc_.data();
    double s2 = 0;
    for (label i = 0; i < n; ++i)
    {
        double u2 = 0, a2 = 0;
        for (label d = 0; d < dim; ++d)
        {
            u2 += U[i*dim + d]*U[i*dim + d];
            a2 += a[i*dim + d]*a[i*dim + d];
        }
        s2 = std::max(s2, std::max(u2, 4*h*std::sqrt(a2)));
    }
    return maxCo*h/std::max(std::sqrt(s2), referenceSpeed_);
}


Foam::scalar Foam::meshless::bodyModels::riemannWcsph::strainEnergy() const
{
    const label n = rho_.size();
    const double* rho = rho_.data();
    const double* m = mass_.data();
    double e = 0;
    for (label i = 0; i < n; ++i)
    {
        const double r = rho[i]/rho0_;
        e += m[i]*(std::log(r) + 1/r - 1);
    }
    return c0_*c0_*e;
}


Foam::scalar Foam::meshless::bodyModels::riemannWcsph::acousticDeltaT() const
{
    // The same number of acoustic steps on every processor
    const scalar Umax = returnReduce(U_.maxMagnitude(), maxOp<scalar>());
    return acousticCourant_*body_.kernel().h()/(c0_ + Umax);
}


template<int Dim>
void Foam::meshless::bodyModels::riemannWcsph::advanceDim
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    using namespace riemannEquations;

    if (summationCost_ < 0)
    {
        summationCost_ = costs.part(body_.name() + ".densitySummation");
        correctionCost_ = costs.part(body_.name() + ".kernelCorrection");
        acousticCost_ = costs.part(body_.name() + ".acousticSteps");
    }

    particleSet& set = body_.particles();
    const label n = set.size();
    const label nv = n*Dim;
    const scalar h = body_.kernel().h();
    const double rho0c0 = rho0_*c0_;

    // Advection step: the scene built the relations at t. The prior
    // accelerations of the effects first: the walls' density in the
    // summation takes them
    aPrior_.fill(0);
    body_.addEffectAccelerations(t, aPrior_, costs);
    {
        costAccounting::scope timer(costs, summationCost_);
        reinitialiseDensity<Dim>();
    }
    if (!openBoundaries_.empty())
    {
        selectOpenBoundaries(t);
        constrainOpenBoundaries(t);
        updatePressure();
    }
    if (correction_ != correctionType::none)
    {
        costAccounting::scope timer(costs, correctionCost_);
        gather
        (
            n, ctx_.sources,
            correctionMatrix::weightedInverseTerm
            <
                Dim, correctionMatrix::gradientWeight
            >{correctionMatrix::gradientWeight(), wkgcAlpha_, B_.data()}
        );
    }

    const bool react = anyReaction();
    if (viscosityEffect_)
    {
        costAccounting::scope timer(costs, body_.costPart(*viscosityEffect_));
        viscousTerm<Dim> term
        {
            src_.data(), U_.data(), rho_.data(), mu_, 0.01*h,
            normaliseLaplacian_, aPrior_.data()
        };
        if (react)
        {
            viscousFactor_.resize(n);
            term.factor = viscousFactor_.data();
        }
        gather(n, ctx_.sources, term);
    }
    if (react) viscousReactions<Dim>();

    double* x = set.positions().data();
    if (transport_)
    {
        costAccounting::scope timer(costs, body_.costPart(*transport_));
        gather
        (
            n, ctx_.sources,
            transportTerm<Dim>
            {
                src_.data(), B_.data(), transport_->coefficient()*h*h,
                dx_.data()
            }
        );
        const double* dx = dx_.data();
        #pragma omp parallel for schedule(static)
        for (label k = 0; k < nv; ++k) x[k] += dx[k];
    }

    // 1/r of every pair for the acoustic steps (their geometry is that of
    // the advection step's start)
    for (size_t k = 0; k < src_.size(); ++k)
    {
        const neighbourRelation& rel = *ctx_.sources[k].rel;
        const label nq = rel.nPairs();
        std::vector<double>& ir = invR_[k];
        if (label(ir.size()) < nq) ir.resize(nq);
        const double* r = rel.r();
        double* irp = ir.data();
        #pragma omp parallel for schedule(static)
        for (label q = 0; q < nq; ++q) irp[q] = r[q] > 0 ? 1/r[q] : 0;
        src_[k].invR = irp;
    }

    // Acoustic steps
    const label nAc = acoustic_(dt, acousticDeltaT());
    const scalar dts = dt/nAc;
    Info<< "    " << body_.name() << ": " << nAc << " acoustic steps of "
        << dts << " s" << endl;

    costAccounting::scope timer(costs, acousticCost_);
    double* U = U_.data();
    double* rho = rho_.data();
    double* drho = drho_.data();
    const double* aP = aP_.data();
    const double* aDc = aDiss_.data();
    const double* a0 = aPrior_.data();

    for (label s = 0; s < nAc; ++s)
    {
        const scalar ts = t + s*dts;
        moveBoundaries(ts + 0.5*dts);

        // First half: density and position to the half step, pressure
        updateDensity(rho, drho, 0.5*dts, rho);
        updatePressure();
        #pragma omp parallel for schedule(static)
        for (label k = 0; k < nv; ++k) x[k] += 0.5*dts*U[k];

        pressure<Dim>(rho, a0, rho0c0);
        if (react) pressureReactions<Dim>(rho, a0, rho0c0, s == nAc - 1);
        #pragma omp parallel for schedule(static)
        for (label k = 0; k < nv; ++k) U[k] += dts*(aP[k] + aDc[k] + a0[k]);
        constrainOpenBoundaries(ts + dts);

        // A coupling's solids over the same acoustic step, with the
        // reaction of the forces that moved the fluid (the dissipation's
        // of the last step, as the fluid's own), so that the second half
        // sees their velocity over this step
        if (innerStep_) innerStep_(ts, dts);

        // Second half: position to the full step, continuity, dissipation
        #pragma omp parallel for schedule(static)
        for (label k = 0; k < nv; ++k) x[k] += 0.5*dts*U[k];
        dissipation<Dim>(U, rho, rho0c0);
        if (react) dissipationReactions<Dim>(U, rho, rho0c0);
        updateDensity(rho, drho, 0.5*dts, rho);
        constrainOpenBoundaries(ts + dts);
    }

    // The accelerations the next advection step is taken from
    double* acc = acc_.data();
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k) acc[k] = a0[k] + aDc[k];

    updatePressure();
    releaseSplash();
    moveBoundaries(t + dt);
}


void Foam::meshless::bodyModels::riemannWcsph::advance
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    emptied_ = -1;
    moveBoundaries(t);
    setSources();
    dispatchDim(body_.dim(), [&](auto d) { advanceDim<d>(t, dt, costs); });
}


// ************************************************************************* //
