/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "isph.H"
#include "particleScene.H"
#include "effect.H"
#include "viscosity.H"
#include "particleShifting.H"
#include "correctionMatrix.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include "dispatchDim.H"
#include "Pair.H"
#include "globalIndex.H"
#include "haloHook.H"
#include <algorithm>
#include <cmath>

namespace Foam
{
namespace meshless
{
namespace bodyModels
{
    defineTypeNameAndDebug(isph, 0);
    addToRunTimeSelectionTable(bodyModel, isph, dictionary);
    addModelRole(isph, fluid);
}
}
}


const Foam::Enum<Foam::meshless::bodyModels::isph::laplacianType>
Foam::meshless::bodyModels::isph::laplacianNames
({
    { laplacianType::symmetric, "symmetric" },
    { laplacianType::consistent, "consistent" },
});


const Foam::Enum<Foam::meshless::bodyModels::isph::wallPressureType>
Foam::meshless::bodyModels::isph::wallPressureNames
({
    { wallPressureType::pairwise, "pairwise" },
    { wallPressureType::implicit, "implicit" },
    { wallPressureType::solved, "solved" },
});


const Foam::Enum<Foam::meshless::bodyModels::isph::wallWettingType>
Foam::meshless::bodyModels::isph::wallWettingNames
({
    { wallWettingType::interpolated, "interpolated" },
    { wallWettingType::pair, "pair" },
    { wallWettingType::all, "all" },
});


const Foam::Enum
<
    Foam::meshless::bodyModels::isph::projectionGradientType
>
Foam::meshless::bodyModels::isph::projectionGradientNames
({
    { projectionGradientType::corrected, "corrected" },
    { projectionGradientType::surfaceUncorrected, "surfaceUncorrected" },
    { projectionGradientType::uncorrected, "uncorrected" },
    { projectionGradientType::surfaceSum, "surfaceSum" },
    { projectionGradientType::surfaceGhost, "surfaceGhost" },
});


const Foam::Enum
<
    Foam::meshless::bodyModels::isph::freeSurfacePressureType
>
Foam::meshless::bodyModels::isph::freeSurfacePressureNames
({
    { freeSurfacePressureType::dirichlet, "dirichlet" },
    { freeSurfacePressureType::ghostAir, "ghostAir" },
});


const Foam::Enum<Foam::meshless::bodyModels::isph::shiftNearWallsType>
Foam::meshless::bodyModels::isph::shiftNearWallsNames
({
    { shiftNearWallsType::normal, "normal" },
    { shiftNearWallsType::wallTangent, "wallTangent" },
    { shiftNearWallsType::none, "none" },
});


namespace
{
    //- The free-surface range (s0 s1) of div r: 0 < s0 < s1 <= dim
    Foam::Pair<Foam::scalar> surfaceRange
    (
        const Foam::dictionary& dict,
        const Foam::label dim
    )
    {
        using namespace Foam;
        Pair<scalar> s(0.7*dim, 0.8*dim);
        if (!dict.found("freeSurfaceRange")) return s;
        scalarList given;
        ITstream& is = dict.lookup("freeSurfaceRange");
        is >> given;
        if
        (
            given.size() != 2 || !(given[0] > 0) || !(given[1] > given[0])
         || given[1] > dim
        )
        {
            FatalIOErrorInFunction(dict)
                << "freeSurfaceRange " << given << ": expected (s0 s1) with"
                << " 0 < s0 < s1 <= " << dim << " (div r of the free surface,"
                << " e.g. (1.4 1.6) in 2D)" << exit(FatalIOError);
        }
        return Pair<scalar>(given[0], given[1]);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::bodyModels::isph::isph
(
    particleBody& body,
    const dictionary& dict
)
:
    fluidModel(body, dict),
    surface_(surfaceRange(dict, body.dim())),
    clipPressure_(dict.found("minPressure")),
    minPressure_(dict.getOrDefault<scalar>("minPressure", 0)),
    contactReach_(readNonNegativeOrDefault(dict, "wallContact", 0)),
    consistent_
    (
        readEnumOrDefault
        (
            dict, "laplacian", laplacianNames, laplacianType::symmetric
        ) == laplacianType::consistent
    ),
    wallPressure_
    (
        readEnumOrDefault
        (
            dict, "wallPressure", wallPressureNames,
            wallPressureType::pairwise
        )
    ),
    wallUnknowns_(wallPressure_ != wallPressureType::pairwise),
    wallRows_(wallPressure_ == wallPressureType::solved),
    wallGradient_(dict.getOrDefault<bool>("wallGradient", true)),
    wallWallPairs_(dict.getOrDefault<bool>("wallWallPairs", true)),
    wetting_
    (
        readEnumOrDefault
        (
            dict, "wallWetting", wallWettingNames,
            wallWettingType::interpolated
        )
    ),
    wetPerPair_(wetting_ == wallWettingType::pair),
    densityRelax_
    (
        readNonNegativeOrDefault(dict, "densityInvariantRelaxation", 0)
    ),
    densityCompressionOnly_
    (
        dict.getOrDefault<bool>("densityInvariantCompressionOnly", false)
    ),
    projectionGradient_
    (
        readEnumOrDefault
        (
            dict, "projectionGradient", projectionGradientNames,
            projectionGradientType::corrected
        )
    ),
    ghostAir_
    (
        readEnumOrDefault
        (
            dict, "freeSurfacePressure", freeSurfacePressureNames,
            freeSurfacePressureType::dirichlet
        ) == freeSurfacePressureType::ghostAir
    ),
    surfaceDefect_(dict.getOrDefault<bool>("surfaceDefectCorrection", true)),
    shiftNearWalls_
    (
        readEnumOrDefault
        (
            dict, "shiftNearWalls", shiftNearWallsNames,
            shiftNearWallsType::normal
        )
    ),
    structureLayer_
    (
        readNonNegativeOrDefault(dict, "structureShiftingLayer", 0)
    ),
    solver_
    (
        linearSolver::New
        (
            dict.found("pressureSolver")
          ? dict.subDict("pressureSolver")
          : dictionary(IStringStream("solver CG;")())
        )
    ),
    acc_(body.particles().addField("acceleration", particleField::kind::vector)),
    B_(body.particles().addScratchField("B", particleField::kind::tensor)),
    Ustar_(body.particles().addScratchField("Ustar", particleField::kind::vector)),
    Uold_(body.particles().addScratchField("Uold", particleField::kind::vector)),
    aPrior_(body.particles().addScratchField("aPrior", particleField::kind::vector)),
    gradP_(body.particles().addScratchField("gradP", particleField::kind::vector)),
    moment_(body.particles().addScratchField("laplacianMoment", particleField::kind::vector)),
    divr_(body.particles().addScratchField("divr", particleField::kind::scalar)),
    alpha_(body.particles().addScratchField("freeSurfaceWeight", particleField::kind::scalar)),
    divU_(body.particles().addScratchField("divUstar", particleField::kind::scalar)),
    rhs_(body.particles().addScratchField("poissonSource", particleField::kind::scalar)),
    shiftR_(body.particles().addScratchField("shiftR", particleField::kind::vector)),
    gradPsi_(body.particles().addScratchField("gradPsi", particleField::kind::vector)),
    gradU_(body.particles().addScratchField("gradU", particleField::kind::tensor)),
    densityRatio_(body.particles().addScratchField("densityRatio", particleField::kind::scalar)),
    pStart_(body.particles().addScratchField("pStart", particleField::kind::scalar)),
    mu_(0),
    viscosityEffect_(nullptr),
    shifting_(nullptr),
    A_(),
    last_(),
    failure_(),
    solvedOnce_(false),
    solvedOnceSaved_(false),
    pIterate_(),
    solvedSinceSave_(false),
    reSolve_(false),
    assemblyCost_(-1),
    solveCost_(-1),
    projectionCost_(-1)
{
    last_.converged = true;
    last_.iterations = 0;
    last_.initialResidual = 0;
    last_.finalResidual = 0;

    if (consistent_ && solver_->needsSymmetric())
    {
        FatalIOErrorInFunction(dict)
            << "laplacian consistent gives a non-symmetric pressure matrix,"
            << " which pressureSolver " << solver_->type() << " cannot"
            << " solve: expected solver BiCGStab or BoomerAMG (or laplacian"
            << " symmetric)" << exit(FatalIOError);
    }
    const word wallName = wallPressureNames[wallPressure_];
    if (wallUnknowns_ && solver_->needsSymmetric())
    {
        FatalIOErrorInFunction(dict)
            << "wallPressure " << wallName << " gives a non-symmetric"
            << " pressure matrix, which pressureSolver " << solver_->type()
            << " cannot solve: expected solver BiCGStab or BoomerAMG (or"
            << " wallPressure pairwise)" << exit(FatalIOError);
    }
    if (wetPerPair_ && wallPressure_ == wallPressureType::implicit)
    {
        FatalIOErrorInFunction(dict)
            << "wallWetting pair takes the pairwise or solved wall"
            << " pressure: expected wallPressure pairwise or solved"
            << exit(FatalIOError);
    }
    if (wetting_ == wallWettingType::all && !wallRows_)
    {
        FatalIOErrorInFunction(dict)
            << "wallWetting all takes the solved wall pressure: expected"
            << " wallPressure solved" << exit(FatalIOError);
    }
    if (ghostAir_ && !wallUnknowns_)
    {
        FatalIOErrorInFunction(dict)
            << "freeSurfacePressure ghostAir takes the walls as unknowns:"
            << " expected wallPressure implicit or solved" << exit(FatalIOError);
    }
    if (wallUnknowns_ && consistent_)
    {
        FatalIOErrorInFunction(dict)
            << "wallPressure " << wallName << " takes the symmetric"
            << " Laplacian (its defect correction): expected laplacian"
            << " symmetric" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::meshless::bodyModels::isph::connectModel(particleScene&)
{
    if (const auto* visc = findEffect<effects::viscosity>(body_))
    {
        mu_ = visc->mu();
        viscosityEffect_ = visc;
    }
    shifting_ = findEffect<effects::particleShifting>(body_);
    own_->cache(neighbourRelation::kernelGradient);
    if (Pstream::parRun())
    {
        if (solver_->type() != "BoomerAMG")
        {
            FatalIOErrorInFunction(dict_.subDict("pressureSolver"))
                << "Body " << body_.name() << ": pressureSolver "
                << solver_->type() << " solves on one processor; in a"
                << " parallel run the pressure system spans the processors:"
                << " expected solver BoomerAMG" << exit(FatalIOError);
        }
        // Each unknown's global row in the distributed pressure system
        body_.particles().addScratchField
        (
            "pressureRow", particleField::kind::scalar
        );
    }
    if (densityRelax_ > 0) own_->cache(neighbourRelation::kernelValue);
    for (boundary& b : boundaries_) boundaryAdded(b);
}


void Foam::meshless::bodyModels::isph::boundaryAdded(boundary& b)
{
    if (Pstream::parRun() && wallUnknowns_)
    {
        particleSet& gs = b.ghosts->ghostBody().particles();
        if (!gs.found("pressureRow"))
        {
            // The last solve's wall pressures, carried by the particles
            // (a processor's unknowns change with its halo); the fluid's,
            // not a coupled solid's state
            b.ghosts->addFluidField
            (
                gs.addScratchField("pressureRow", particleField::kind::scalar)
            );
            b.ghosts->addFluidField
            (
                gs.addScratchField("pSolved", particleField::kind::scalar)
            );
        }
    }
    b.toGhosts->cache(neighbourRelation::kernelGradient);
    if (wallUnknowns_ || b.ghosts->reaction())
    {
        b.fromGhosts->cache(neighbourRelation::kernelGradient);
    }
    if (!wallRows_) return;

    // A ghostWall's particles with themselves for the wall rows: the
    // wall's own relation (rigid: its pairs those of the start), its
    // geometry at the current positions each step (moving walls); a
    // coupled structure's surface takes rows over the fluid only
    neighbourRelation* own = nullptr;
    if (b.wall)
    {
        const particleBody& gb = b.ghosts->ghostBody();
        own = &relations_->inner
        (
            gb.name() + " (ghosts)", gb.particles().positions(),
            body_.kernel(), 0, false,
            neighbourRelation::separation | neighbourRelation::kernelGradient
        );
        relations_->update(*own);
        own->updateGeometry();
    }
    wallOwn_.push_back(own);
}


void Foam::meshless::bodyModels::isph::setSources()
{
    src_.resize(1 + boundaries_.size());
    surfaceSrc_.resize(1 + boundaries_.size());
    viscSrc_.resize(1 + boundaries_.size());
    src_[0] = isphEquations::sourceData
    {
        true, Ustar_.data(), nullptr, nullptr, nullptr, nullptr
    };
    viscSrc_[0] = riemannEquations::sourceData
    {
        true, p_.data(), B_.data(), U_.data(), nullptr, nullptr, true,
        false, nullptr, nullptr
    };
    for (size_t k = 0; k < boundaries_.size(); ++k)
    {
        const ghostBoundary& g = *boundaries_[k].ghosts;
        src_[k + 1] = isphEquations::sourceData
        {
            false, g.U(), g.accelerations(), g.p(), g.normals(), nullptr
        };
        if (wetPerPair_)
        {
            src_[k + 1].pPair = pStart_.data();
            src_[k + 1].rho = rho0_;
            for (label d = 0; d < 3; ++d) src_[k + 1].g[d] = g_[d];
        }
        if (wetting_ == wallWettingType::all) src_[k + 1].pWall = nullptr;
        viscSrc_[k + 1] = riemannEquations::sourceData
        {
            false, nullptr, nullptr, g.U(), g.accelerations(), g.normals(),
            g.slipNormals() == nullptr, false, nullptr, nullptr
        };
    }
}


template<int Dim>
void Foam::meshless::bodyModels::isph::shift
(
    const scalar dt,
    costAccounting& costs
)
{
    using namespace isphEquations;
    costAccounting::scope timer(costs, body_.costPart(*shifting_));

    const label n = U_.size();
    const scalar h = body_.kernel().h();
    vectorD<Dim> g;
    for (int d = 0; d < Dim; ++d) g[d] = g_[d];

    // At the step's end (the lists hold with the skin)
    updateGeometry();
    gather(n, ctx_.sources, correctionTerm<Dim>(src_.data(), B_.data()));
    gather
    (
        n, ctx_.sources,
        shiftTerm<Dim>
        {
            src_.data(), U_.data(), B_.data(), body_.kernel().radius(),
            std::pow(body_.spacing(), Dim), shiftR_.data(), gradPsi_.data(),
            gradU_.data()
        }
    );
    gather
    (
        n, ctx_.sources,
        pressureGradientTerm<Dim>
        {
            src_.data(), p_.data(), B_.data(), g, rho0_, gradP_.data()
        }
    );

    const scalar zeta =
        returnReduce(U_.maxMagnitude(), maxOp<scalar>())*dt;
    const scalar c = shifting_->coefficient()*zeta;
    const scalar cap = shifting_->maxShift()*h;
    const bool correctU = shifting_->correctVelocity();
    const neighbourRelation& rel = *own_;
    const label* off = rel.offsetData();
    const label* idx = rel.indexData();
    const double* r = rel.r();
    const double* alpha = alpha_.data();
    double* x = body_.particles().positions().data();
    double* U = U_.data();
    double* p = p_.data();

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        vectorD<Dim> dr = c*cvec<Dim>(shiftR_.data(), i);
        const double mag = dr.norm();
        if (mag > cap) dr *= cap/mag;

        // On or within h of the free surface: along the surface only
        bool surface = alpha[i] < 1;
        for (label q = off[i]; q < off[i + 1] && !surface; ++q)
        {
            surface = r[q] < h && alpha[idx[q]] < 1;
        }
        if (surface)
        {
            const vectorD<Dim> gp = cvec<Dim>(gradPsi_.data(), i);
            const double gm = gp.norm();
            if (gm > 0)
            {
                const vectorD<Dim> nrm = -gp/gm;
                dr -= dr.dot(nrm)*nrm;
            }
            if (shiftNearWalls_ != shiftNearWallsType::normal)
            {
                // The nearest wall particle within h (normal into it)
                double rmin = h;
                const double* nw = nullptr;
                for (const boundary& b : boundaries_)
                {
                    const neighbourRelation& tw = *b.toGhosts;
                    const label* o = tw.offsetData();
                    const label* js = tw.indexData();
                    const double* rs = tw.r();
                    const double* ns = b.ghosts->contactNormals();
                    for (label q = o[i]; q < o[i + 1]; ++q)
                    {
                        // A structure's particles off its face (no
                        // normal) are not its face
                        if (ns && cvec<Dim>(ns, js[q]).squaredNorm() == 0)
                        {
                            continue;
                        }
                        if (rs[q] < rmin)
                        {
                            rmin = rs[q];
                            nw = ns ? ns + js[q]*Dim : nullptr;
                        }
                    }
                }
                if (rmin < h)
                {
                    if (shiftNearWalls_ == shiftNearWallsType::none)
                    {
                        dr = vectorD<Dim>::Zero();
                    }
                    else if (nw)
                    {
                        const auto nn = cvec<Dim>(nw, 0);
                        const double into = dr.dot(nn);
                        if (into > 0) dr -= into*nn;
                    }
                }
            }
        }

        // The FSI layer on each coupled structure's face (eq. 27-30)
        if (structureLayer_ > 0)
        {
            const vectorD<Dim> R = cvec<Dim>(shiftR_.data(), i);
            for (const boundary& b : boundaries_)
            {
                const double* ns = b.ghosts->contactNormals();
                if (b.wall || !ns) continue;
                structureLayer<Dim>
                (
                    *b.toGhosts, i, ns, b.ghosts->contactDepth(), R, zeta,
                    structureLayer_, dr
                );
            }
        }

        if (correctU) vec<Dim>(U, i) += ctens<Dim>(gradU_.data(), i)*dr;
        p[i] += cvec<Dim>(gradP_.data(), i).dot(dr);
        vec<Dim>(x, i) += dr;
    }
}


template<int Dim>
Foam::scalar Foam::meshless::bodyModels::isph::fullLatticeD() const
{
    // D0 = 2 V^2 sum_j G(r_j) over a full lattice of the spacing
    const smoothingKernel& W = body_.kernel();
    const scalar dx = body_.spacing();
    const label K = label(std::ceil(W.radius()/dx));
    scalar sum = 0;
    for (label a = -K; a <= K; ++a)
    {
        for (label b = -K; b <= K; ++b)
        {
            for (label c = (Dim == 3 ? -K : 0); c <= (Dim == 3 ? K : 0); ++c)
            {
                const scalar r = dx*std::sqrt(scalar(a*a + b*b + c*c));
                if (r > 0 && r < W.radius())
                {
                    sum += gradientFactor(r, W.dWdr(r));
                }
            }
        }
    }
    const scalar V = std::pow(dx, Dim);
    return 2*V*V*sum;
}


template<int Dim>
void Foam::meshless::bodyModels::isph::advanceDim
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    using namespace isphEquations;

    if (assemblyCost_ < 0)
    {
        assemblyCost_ = costs.part(body_.name() + ".poissonAssembly");
        solveCost_ = costs.part(body_.name() + ".pressureSolve");
        projectionCost_ = costs.part(body_.name() + ".projection");
    }

    particleSet& set = body_.particles();
    const label n = set.size();
    const label nv = n*Dim;
    const scalar h = body_.kernel().h();
    double* x = set.positions().data();
    double* U = U_.data();
    double* Us = Ustar_.data();
    double* U0 = Uold_.data();
    double* a0 = aPrior_.data();

    vectorD<Dim> g;
    for (int d = 0; d < Dim; ++d) g[d] = g_[d];

    // 0. The pressure gradient at x^n for the Laplacian's defect
    //    correction (isphEquations.H)
    if (!consistent_)
    {
        costAccounting::scope timer(costs, assemblyCost_);
        gather(n, ctx_.sources, correctionTerm<Dim>(src_.data(), B_.data()));
        gather
        (
            n, ctx_.sources,
            pressureGradientTerm<Dim>
            {
                src_.data(), p_.data(), B_.data(), g, rho0_, gradP_.data()
            }
        );
    }

    // 1. Prediction at x^n: effects (gravity, ...) and viscosity
    aPrior_.fill(0);
    body_.addEffectAccelerations(t, aPrior_, costs);
    body_.addPairEffectAccelerations(ctx_, aPrior_, costs);
    if (viscosityEffect_)
    {
        costAccounting::scope timer(costs, body_.costPart(*viscosityEffect_));
        gather
        (
            n, ctx_.sources,
            riemannEquations::viscousTerm<Dim>
            {
                viscSrc_.data(), U, rho_.data(), mu_, 0.01*h, true, a0
            }
        );
    }
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nv; ++k)
    {
        U0[k] = U[k];
        Us[k] = U[k] + dt*a0[k];
        x[k] += dt*U[k];
    }
    moveBoundaries(t + dt);
    updateGeometry();

    // 2. At x*: correction, free surface, divergence, Poisson equation
    {
        costAccounting::scope timer(costs, assemblyCost_);
        gather(n, ctx_.sources, correctionTerm<Dim>(src_.data(), B_.data()));
        gather
        (
            n, ctx_.sources,
            freeSurfaceTerm<Dim>
            {
                surfaceSrc_.data(), V_.data(), surface_.first(),
                surface_.second(), divr_.data(), alpha_.data(),
                moment_.data(), wallRows_
            }
        );
        gather
        (
            n, ctx_.sources,
            divergenceTerm<Dim>{src_.data(), Us, B_.data(), dt*g, divU_.data()}
        );
        if (densityRelax_ > 0)
        {
            // The stabilised source of Asai et al. (2012): div u*_i +
            // relax (1 - rho*_i/rho0)/dt, rho* the kernel sum at x*
            const smoothingKernel& W = body_.kernel();
            const scalar dx = body_.spacing();
            const label K = label(std::ceil(W.radius()/dx));
            scalar sigma0 = 0;
            for (label a = -K; a <= K; ++a)
            {
                for (label b = -K; b <= K; ++b)
                {
                    for (label c = (Dim == 3 ? -K : 0); c <= (Dim == 3 ? K : 0); ++c)
                    {
                        sigma0 += W.W(dx*std::sqrt(scalar(a*a + b*b + c*c)));
                    }
                }
            }
            sigma0 *= std::pow(dx, Dim);
            gather
            (
                n, ctx_.sources,
                kernelSumTerm{V_.data(), W.W(0), sigma0, densityRatio_.data()}
            );
            const double* ratio = densityRatio_.data();
            double* div = divU_.data();
            const double c = densityRelax_/dt;
            const bool compressionOnly = densityCompressionOnly_;
            #pragma omp parallel for schedule(static)
            for (label i = 0; i < n; ++i)
            {
                const double e = 1 - ratio[i];
                div[i] += c*(compressionOnly ? std::min(0.0, e) : e);
            }
        }
        rhs_.fill(0);
        const double* Bc = consistent_ ? B_.data() : nullptr;
        const double* mc = consistent_ ? moment_.data() : nullptr;
        if (!wallUnknowns_)
        {
            gather
            (
                n, ctx_.sources,
                wallHeadTerm<Dim>
                {
                    src_.data(), V_.data(), g, rho0_, rhs_.data(), Bc, mc
                }
            );
        }
        // On or within h of the free surface at x*
        {
            refreshHalos();
            nearSurface_.assign(n, 0);
            const neighbourRelation& rel = *own_;
            const label* off = rel.offsetData();
            const label* idx = rel.indexData();
            const double* r = rel.r();
            const double* alpha = alpha_.data();
            char* ns = nearSurface_.data();
            #pragma omp parallel for schedule(static)
            for (label i = 0; i < n; ++i)
            {
                bool s = alpha[i] < 1;
                for (label q = off[i]; q < off[i + 1] && !s; ++q)
                {
                    s = r[q] < h && alpha[idx[q]] < 1;
                }
                ns[i] = s;
            }
        }
        if (!consistent_)
        {
            const double* m = moment_.data();
            const double* gp = gradP_.data();
            double* R = rhs_.data();
            const char* ns = surfaceDefect_ ? nullptr : nearSurface_.data();
            #pragma omp parallel for schedule(static)
            for (label i = 0; i < n; ++i)
            {
                if (ns && ns[i]) continue;
                double c = 0;
                for (int d = 0; d < Dim; ++d) c += m[i*Dim + d]*gp[i*Dim + d];
                R[i] -= c;
            }
        }
        if (wallUnknowns_)
        {
            std::vector<wallBlock> blocks;
            for (size_t k = 0; k < boundaries_.size(); ++k)
            {
                const boundary& b = boundaries_[k];
                blocks.push_back
                (
                    wallBlock
                    {
                        b.toGhosts, b.fromGhosts, b.ghosts->V(),
                        b.ghosts->accelerations(), wallOffset_[k]
                    }
                );
                if (wallRows_)
                {
                    // The wall rows' source: div u* at the wall particles
                    std::vector<double>& dw = wallDiv_[k];
                    dw.resize(b.fromGhosts->size());
                    wallDivergence<Dim>
                    (
                        *b.fromGhosts, Us, V_.data(), b.ghosts->U(),
                        b.ghosts->normals(), dt*g, dw.data()
                    );
                    if (wallOwn_[k] && b.ghosts->moving())
                    {
                        wallOwn_[k]->updateGeometry();
                    }
                    blocks.back().div = dw.data();
                    if (wallWallPairs_) blocks.back().own = wallOwn_[k];
                }
            }
            std::copy(rhs_.data(), rhs_.data() + n, bAll_.begin());
            isphEquations::assemblePoissonWalls<Dim>
            (
                *own_, blocks, V_.data(), alpha_.data(), divr_.data(),
                divU_.data(), rho0_, dt, g, bAll_.data(), A_, wallGradient_,
                ghostAir_ ? fullLatticeD<Dim>() : 0
            );
            std::copy(bAll_.begin(), bAll_.begin() + n, rhs_.data());
        }
        else
        {
            isphEquations::assemblePoisson<Dim>
            (
                *own_, V_.data(), alpha_.data(), divr_.data(), divU_.data(),
                rho0_, dt, rhs_.data(), A_, nullptr, Bc, mc
            );
        }
    }
    {
        costAccounting::scope timer(costs, solveCost_);
        // The initial guess: the pressure of the step's start, or of the
        // last solve when re-solving the step
        const bool guess = reSolve_;
        if (wallUnknowns_)
        {
            std::copy(p_.data(), p_.data() + n, pAll_.begin());
            if (guess && pIterate_.size() == pAll_.size())
            {
                std::copy(pIterate_.begin(), pIterate_.end(), pAll_.begin());
            }
            if (Pstream::parRun())
            {
                solveDistributed(bAll_.data(), pAll_.data(), pAll_.size());
            }
            else
            {
                last_ = solver_->solve(A_, bAll_.data(), pAll_.data());
            }
            std::copy(pAll_.begin(), pAll_.begin() + n, p_.data());
            if (last_.converged) pIterate_.assign(pAll_.begin(), pAll_.end());
        }
        else
        {
            if (guess && label(pIterate_.size()) == n)
            {
                std::copy(pIterate_.begin(), pIterate_.end(), p_.data());
            }
            if (Pstream::parRun())
            {
                solveDistributed(rhs_.data(), p_.data(), n);
            }
            else
            {
                last_ = solver_->solve(A_, rhs_.data(), p_.data());
            }
            if (last_.converged) pIterate_.assign(p_.data(), p_.data() + n);
        }
        // A solve that did not converge is no guess: the re-solves start
        // from the step's start pressure again
        solvedSinceSave_ = last_.converged;
    }

    if (clipPressure_)
    {
        double* pp = p_.data();
        const double floor = minPressure_;
        #pragma omp parallel for schedule(static)
        for (label i = 0; i < n; ++i) pp[i] = std::max(pp[i], floor);
        const label N = pAll_.size();
        if (wallUnknowns_)
        {
            for (label i = n; i < N; ++i)
            {
                pAll_[i] = std::max(pAll_[i], floor);
            }
        }
    }
    if (wallUnknowns_)
    {
        // The walls' own pressures to their bodies (written, probes)
        for (size_t k = 0; k < boundaries_.size(); ++k)
        {
            particleField& pw =
                boundaries_[k].ghosts->ghostBody().particles().field("p");
            std::copy
            (
                pAll_.begin() + wallOffset_[k],
                pAll_.begin() + wallOffset_[k] + pw.size(),
                pw.data()
            );
        }
    }
    if (Pstream::parRun()) refreshUnknowns();
    Info<< "    " << body_.name() << ": pressure " << last_.solver << ", "
        << last_.iterations << " iterations, residual "
        << last_.initialResidual << " -> " << last_.finalResidual << endl;
    if (!last_.converged)
    {
        OStringStream os;
        os  << "the pressure Poisson equation did not converge: "
            << last_.solver << " stopped after " << last_.iterations
            << " iterations at residual " << last_.finalResidual
            << " (relative), tolerance not reached (pressureSolver)";
        failure_ = os.str();
    }

    // 3. Projection and positions
    {
        costAccounting::scope timer(costs, projectionCost_);
        std::vector<char> everywhere;
        const char* plain = nullptr;
        if (projectionGradient_ == projectionGradientType::uncorrected)
        {
            everywhere.assign(n, 1);
            plain = everywhere.data();
        }
        else if (projectionGradient_ != projectionGradientType::corrected)
        {
            plain = nearSurface_.data();
        }
        gather
        (
            n, ctx_.sources,
            pressureGradientTerm<Dim>
            {
                src_.data(), p_.data(), B_.data(), g, rho0_, gradP_.data(),
                plain,
                projectionGradient_ == projectionGradientType::surfaceSum
              ? 2.0
              : projectionGradient_ == projectionGradientType::surfaceGhost
              ? 1.0
              : 0.0
            }
        );
        interfaceForces<Dim>();
        const double* gp = gradP_.data();
        double* acc = acc_.data();
        const double c = dt/rho0_;
        #pragma omp parallel for schedule(static)
        for (label k = 0; k < nv; ++k)
        {
            U[k] = Us[k] - c*gp[k];
        }
        if (contactReach_ > 0)
        {
            const scalar reach = contactReach_*body_.spacing();
            for (const boundary& b : boundaries_)
            {
                const ghostBoundary& g = *b.ghosts;
                if (!g.contactNormals() || !g.contactDepth()) continue;
                // A coupled structure (it takes the fluid's reaction)
                isphEquations::wallContact<Dim>
                (
                    *b.toGhosts, g.contactNormals(), g.contactDepth(),
                    g.U(), reach,
                    alpha_.data(), U,
                    g.takesReaction()
                );
            }
        }
        #pragma omp parallel for schedule(static)
        for (label k = 0; k < nv; ++k)
        {
            x[k] += 0.5*dt*(U[k] - U0[k]);
            acc[k] = (U[k] - U0[k])/dt;
        }
    }
    if (shifting_) shift<Dim>(dt, costs);
    releaseSplash();
}


void Foam::meshless::bodyModels::isph::solveDistributed
(
    const double* b,
    double* p,
    const label N
)
{
    const label n = p_.size();

    // This processor's unknowns: its own fluid particles, then each
    // boundary's own particles
    ownRow_.assign(N, -1);
    label M = 0;
    const label nF = body_.particles().nOwned();
    for (label i = 0; i < nF; ++i) ownRow_[i] = M++;
    const bool walls = N > n;
    if (walls)
    {
        for (size_t k = 0; k < boundaries_.size(); ++k)
        {
            // (a replicated body's, a solid's: those this processor owns)
            const particleSet& gs =
                boundaries_[k].ghosts->ghostBody().particles();
            for (label j = 0; j < gs.size(); ++j)
            {
                if (gs.owns(j)) ownRow_[wallOffset_[k] + j] = M++;
            }
        }
    }
    const globalIndex rows(M);
    const label offset = rows.offset(Pstream::myProcNo());

    // Each unknown's global row, the halo's as its owner numbered it
    particleField& rowF = body_.particles().field("pressureRow");
    for (label i = 0; i < nF; ++i) rowF(i, 0) = offset + ownRow_[i];
    if (walls)
    {
        for (size_t k = 0; k < boundaries_.size(); ++k)
        {
            particleSet& gs = boundaries_[k].ghosts->ghostBody().particles();
            particleField& rowW = gs.field("pressureRow");
            for (label j = 0; j < gs.size(); ++j)
            {
                if (gs.owns(j))
                {
                    rowW(j, 0) = offset + ownRow_[wallOffset_[k] + j];
                }
            }
        }
    }
    refreshHalos();
    auto globalRow = [&](const label c) -> label
    {
        if (c < n) return label(rowF(c, 0));
        size_t k = boundaries_.size() - 1;
        while (wallOffset_[k] > c) --k;
        const particleField& rowW =
            boundaries_[k].ghosts->ghostBody().particles().field
            (
                "pressureRow"
            );
        return label(rowW(c - wallOffset_[k], 0));
    };

    // The own rows, columns own (compact) or another processor's
    const label* rs = A_.rowStart();
    const label* cols = A_.columns();
    const double* vals = A_.values();
    label nnz = 0;
    for (label r = 0; r < N; ++r)
    {
        if (ownRow_[r] >= 0) nnz += rs[r + 1] - rs[r];
    }
    Adist_.resize(M, nnz);
    bDist_.resize(M);
    xDist_.resize(M);
    haloColumn_.assign(N, -1);
    haloRows_.clear();
    label* rsD = Adist_.rowStart();
    label* colsD = Adist_.columns();
    double* valsD = Adist_.values();
    label q = 0;
    rsD[0] = 0;
    for (label r = 0; r < N; ++r)
    {
        const label u = ownRow_[r];
        if (u < 0) continue;
        for (label e = rs[r]; e < rs[r + 1]; ++e)
        {
            const label c = cols[e];
            label cD = ownRow_[c];
            if (cD < 0)
            {
                if (haloColumn_[c] < 0)
                {
                    haloColumn_[c] = label(haloRows_.size());
                    haloRows_.push_back(globalRow(c));
                }
                cD = M + haloColumn_[c];
            }
            colsD[q] = cD;
            valsD[q] = vals[e];
            ++q;
        }
        rsD[u + 1] = q;
        bDist_[u] = b[r];
        xDist_[u] = p[r];
    }
    Adist_.setSymmetric(A_.symmetric());
    Adist_.setDistribution(offset, rows.size(), haloRows_);

    last_ = solver_->solve(Adist_, bDist_.data(), xDist_.data());
    for (label r = 0; r < N; ++r)
    {
        if (ownRow_[r] >= 0) p[r] = xDist_[ownRow_[r]];
    }
}


void Foam::meshless::bodyModels::isph::stateSaved()
{
    pAllSaved_ = pAll_;
    solvedOnceSaved_ = solvedOnce_;
    solvedSinceSave_ = false;
    reSolve_ = false;
    pSolvedSaved_.resize(boundaries_.size());
    for (size_t k = 0; k < boundaries_.size(); ++k)
    {
        const particleSet& gs = boundaries_[k].ghosts->ghostBody().particles();
        if (!gs.found("pSolved")) continue;
        const particleField& ps = gs.field("pSolved");
        pSolvedSaved_[k].assign(ps.data(), ps.data() + ps.size());
    }
}


void Foam::meshless::bodyModels::isph::restored()
{
    fluidModel::restored();
    pAll_ = pAllSaved_;
    solvedOnce_ = solvedOnceSaved_;
    reSolve_ = solvedSinceSave_;
    for (size_t k = 0; k < boundaries_.size(); ++k)
    {
        particleSet& gs = boundaries_[k].ghosts->ghostBody().particles();
        if (!gs.found("pSolved")) continue;
        particleField& ps = gs.field("pSolved");
        const std::vector<double>& saved = pSolvedSaved_[k];
        if (label(saved.size()) != ps.size())
        {
            FatalErrorInFunction
                << "Boundary " << gs.name() << " changed since the state was"
                << " saved" << abort(FatalError);
        }
        std::copy(saved.begin(), saved.end(), ps.data());
    }
}


void Foam::meshless::bodyModels::isph::refreshUnknowns()
{
    refreshHalos();
    if (!wallUnknowns_) return;
    const label n = p_.size();
    std::copy(p_.data(), p_.data() + n, pAll_.begin());
    for (size_t k = 0; k < boundaries_.size(); ++k)
    {
        particleSet& gs = boundaries_[k].ghosts->ghostBody().particles();
        const particleField& pw = gs.field("p");
        particleField& ps = gs.field("pSolved");
        std::copy(pw.data(), pw.data() + pw.size(), ps.data());
        std::copy
        (
            pw.data(), pw.data() + pw.size(), pAll_.begin() + wallOffset_[k]
        );
    }
    solvedOnce_ = true;
}


template<int Dim>
void Foam::meshless::bodyModels::isph::interfaceForces()
{
    const label n = p_.size();
    vectorD<Dim> g;
    for (int d = 0; d < Dim; ++d) g[d] = g_[d];
    for (size_t k = 0; k < boundaries_.size(); ++k)
    {
        boundary& b = boundaries_[k];
        double* R = b.ghosts->reaction();
        if (!R) continue;
        const isphEquations::sourceData& S = src_[k + 1];
        const label nR = b.ghosts->ghostBody().particles().size()*Dim;
        std::fill(R, R + nR, 0.0);
        isphEquations::interfaceReaction<Dim>
        (
            *b.fromGhosts, S, b.ghosts->V(), p_.data(), V_.data(), g, rho0_,
            R
        );
        interfaceForce_.resize(size_t(n)*Dim);
        gather
        (
            *b.toGhosts, b.ghosts->V(),
            isphEquations::interfaceForceTerm<Dim>
            {
                &S, p_.data(), V_.data(), g, rho0_, interfaceForce_.data()
            }
        );
        const vectorD<Dim> F = sumInOrder<Dim>
        (
            interfaceForce_.data(), body_.particles().nOwned()
        );
        b.forceOnFluid = Zero;
        for (label d = 0; d < Dim; ++d) b.forceOnFluid[d] = F[d];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::meshless::bodyModels::isph::maxDeltaT
(
    const scalar maxCo
) const
{
    const scalar h = body_.kernel().h();
    const label n = U_.size();
    const label dim = body_.dim();
    const double* U = U_.data();
    const double* a = acc_.data();
    double u2 = 0, a2 = magSqr(g_);
    for (label i = 0; i < n; ++i)
    {
        double ui = 0, ai = 0;
        for (label d = 0; d < dim; ++d)
        {
            ui += U[i*dim + d]*U[i*dim + d];
            ai += a[i*dim + d]*a[i*dim + d];
        }
        u2 = std::max(u2, ui);
        a2 = std::max(a2, ai);
    }
    const scalar umax = std::sqrt(u2);
    scalar dt = GREAT;
    if (umax > 0)
    {
        dt = std::min(maxCo*h/umax, 0.5*skin_*body_.kernel().radius()/umax);
    }
    if (a2 > 0) dt = std::min(dt, 0.25*std::sqrt(h/std::sqrt(a2)));
    if (mu_ > 0) dt = std::min(dt, 0.125*rho0_*h*h/mu_);
    return dt;
}


void Foam::meshless::bodyModels::isph::advance
(
    const scalar t,
    const scalar dt,
    costAccounting& costs
)
{
    emptied_ = -1;
    failure_.clear();

    // Incompressible: rho = rho0, V = m/rho0 throughout
    {
        const label n = rho_.size();
        const double* m = mass_.data();
        double* rho = rho_.data();
        double* V = V_.data();
        for (label i = 0; i < n; ++i)
        {
            rho[i] = rho0_;
            V[i] = m[i]/rho0_;
        }
    }
    moveBoundaries(t);
    setSources();

    // The walls' pressure from the water at the step's start: which wall
    // particles it covers (isphEquations::dry); water without pressure (a
    // start from rest) covers them all for this step
    interpolateBoundaries();
    // (over every processor: one may hold only surface water)
    if (returnReduce(p_.maxMagnitude(), maxOp<scalar>()) == 0)
    {
        for (size_t k = 1; k < src_.size(); ++k)
        {
            src_[k].pWall = nullptr;
            src_[k].pPair = nullptr;
        }
    }
    if (wetPerPair_)
    {
        std::copy(p_.data(), p_.data() + p_.size(), pStart_.data());
    }

    // With the walls as unknowns every wall particle takes part, with the
    // pressure of the last solve (the interpolated one before the first)
    if (wallUnknowns_)
    {
        const label n = p_.size();
        label N = n;
        wallOffset_.resize(boundaries_.size());
        for (size_t k = 0; k < boundaries_.size(); ++k)
        {
            wallOffset_[k] = N;
            N += boundaries_[k].fromGhosts->size();
        }
        if (Pstream::parRun() && solvedOnce_)
        {
            // The last solve's, as the particles of this step's halo carry
            // them (the walls' p is the interpolated one now)
            pAll_.assign(N, 0);
            for (size_t k = 0; k < boundaries_.size(); ++k)
            {
                const particleField& ps =
                    boundaries_[k].ghosts->ghostBody().particles().field
                    (
                        "pSolved"
                    );
                std::copy
                (
                    ps.data(), ps.data() + ps.size(),
                    pAll_.begin() + wallOffset_[k]
                );
            }
        }
        else if (label(pAll_.size()) != N)
        {
            pAll_.assign(N, 0);
            for (size_t k = 0; k < boundaries_.size(); ++k)
            {
                const label nw = boundaries_[k].fromGhosts->size();
                const double* pw = boundaries_[k].ghosts->p();
                std::copy(pw, pw + nw, pAll_.begin() + wallOffset_[k]);
            }
        }
        bAll_.resize(N);
        wallDiv_.resize(boundaries_.size());
        for (size_t k = 0; k < boundaries_.size(); ++k)
        {
            src_[k + 1].pSolved = pAll_.data() + wallOffset_[k];
        }
        // Solved: the wetting rule for the free surface's div r only,
        // every wall particle in every other term
        if (wallRows_) surfaceSrc_ = src_;
        for (size_t k = 0; k < boundaries_.size(); ++k)
        {
            src_[k + 1].pWall = nullptr;
            src_[k + 1].pPair = nullptr;
        }
    }
    if (!wallRows_) surfaceSrc_ = src_;
    dispatchDim(body_.dim(), [&](auto d) { advanceDim<d>(t, dt, costs); });
}


Foam::string Foam::meshless::bodyModels::isph::blowUp() const
{
    if (!failure_.empty()) return failure_;
    return fluidModel::blowUp();
}


// ************************************************************************* //
