/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ghostBoundary.H"
#include "dispatchDim.H"
#include "correctionMatrix.H"
#include <algorithm>
#include <cmath>
#include <map>

const Foam::Enum<Foam::meshless::ghostBoundary::slipType>
Foam::meshless::ghostBoundary::slipTypeNames
({
    { slipType::noSlip, "noSlip" },
    { slipType::freeSlip, "freeSlip" },
});


namespace
{

Foam::word prefixed(const Foam::word& prefix, const Foam::word& name)
{
    if (prefix.empty()) return name;
    Foam::word n(name);
    n[0] = std::toupper(n[0]);
    return prefix + n;
}

Foam::meshless::particleField& stateField
(
    Foam::meshless::particleSet& set,
    const Foam::word& prefix,
    const Foam::word& name,
    Foam::meshless::particleField::kind k
)
{
    // A wall's state is its own and written; a solid's is scratch
    return prefix.empty()
        ? set.addField(name, k)
        : set.addScratchField(prefixed(prefix, name), k);
}

} // End anonymous namespace


Foam::meshless::ghostBoundary::ghostBoundary
(
    particleBody& body,
    const slipType slip,
    const scalar minPressure,
    const word& prefix,
    const word& velocityName
)
:
    ghostBody_(body),
    slip_(slip),
    minPressure_(minPressure),
    Uown_(body.particles().addField(velocityName, particleField::kind::vector)),
    p_(body.particles().addField("p", particleField::kind::scalar)),
    rho_(stateField(body.particles(), prefix, "rho", particleField::kind::scalar)),
    mass_(stateField(body.particles(), prefix, "mass", particleField::kind::scalar)),
    V0_(body.requireField("volume", "ghost particles")),
    Uvisc_
    (
        body.particles().addScratchField
        (
            prefixed(prefix, "Uvisc"), particleField::kind::vector
        )
    ),
    S_
    (
        body.particles().addScratchField
        (
            prefixed(prefix, "S"), particleField::kind::tensor
        )
    ),
    reaction_(nullptr),
    cell_(nullptr),
    cellOffset_(nullptr)
{}


Foam::label Foam::meshless::ghostBoundary::cells
(
    const double* X,
    const label n,
    const label dim,
    const scalar spacing,
    const scalar dx,
    double* cell
)
{
    // Cells from the lowest corner of the particles' own cells
    std::vector<double> lo(dim, GREAT);
    for (label i = 0; i < n; ++i)
    {
        for (label d = 0; d < dim; ++d)
        {
            lo[d] = std::min(lo[d], X[i*dim + d] - 0.5*spacing);
        }
    }
    // Cell numbers (a particle on a cell face goes to one side only)
    std::map<std::vector<long>, label> number;
    std::vector<long> key(dim);
    for (label i = 0; i < n; ++i)
    {
        for (label d = 0; d < dim; ++d)
        {
            key[d] = long(std::floor((X[i*dim + d] - lo[d])/dx + 1e-9));
        }
        cell[i] = number.emplace(key, label(number.size())).first->second;
    }
    return number.size();
}


void Foam::meshless::ghostBoundary::centroidOffsets
(
    const double* x,
    const double* V,
    const double* cell,
    const label n,
    const label dim,
    std::vector<double>& cellVolume,
    std::vector<double>& cellSum,
    double* offset
)
{
    std::fill(cellVolume.begin(), cellVolume.end(), 0.0);
    std::fill(cellSum.begin(), cellSum.end(), 0.0);
    for (label i = 0; i < n; ++i)
    {
        const label k = label(cell[i]);
        cellVolume[k] += V[i];
        for (label d = 0; d < dim; ++d) cellSum[k*dim + d] += V[i]*x[i*dim + d];
    }
    for (label i = 0; i < n; ++i)
    {
        const label k = label(cell[i]);
        for (label d = 0; d < dim; ++d)
        {
            offset[i*dim + d] = cellSum[k*dim + d]/cellVolume[k] - x[i*dim + d];
        }
    }
}


void Foam::meshless::ghostBoundary::coarseGrain(const scalar dx)
{
    particleSet& set = ghostBody_.particles();
    const double* X =
        set.found("X0") ? set.field("X0").data() : set.positions().data();
    cell_ = &set.addScratchField("ghostCell", particleField::kind::scalar);
    cellOffset_ =
        &set.addScratchField("ghostCellOffset", particleField::kind::vector);
    const label nCells = cells
    (
        X, set.size(), set.dim(), ghostBody_.spacing(), dx, cell_->data()
    );
    cellVolume_.assign(nCells, 0);
    cellSum_.assign(nCells*set.dim(), 0);
}


const double* Foam::meshless::ghostBoundary::summationOffsets()
{
    if (!cell_) return nullptr;
    const particleSet& set = ghostBody_.particles();
    centroidOffsets
    (
        set.positions().data(), V0_.data(), cell_->data(), set.size(),
        set.dim(), cellVolume_, cellSum_, cellOffset_->data()
    );
    return cellOffset_->data();
}


std::vector<const Foam::meshless::particleField*>
Foam::meshless::ghostBoundary::ownFields() const
{
    std::vector<const particleField*> f{&p_, &Uvisc_, &S_};
    // rho and m are the ghosts' own where scratch (a solid's), the body's
    // where written (a wall's)
    if (!rho_.written()) f.push_back(&rho_);
    if (!mass_.written()) f.push_back(&mass_);
    for (const particleField* q : {reaction_, cell_, cellOffset_})
    {
        if (q) f.push_back(q);
    }
    f.insert(f.end(), fluidFields_.begin(), fluidFields_.end());
    return f;
}


void Foam::meshless::ghostBoundary::requestReaction()
{
    if (!reaction_)
    {
        reaction_ = &ghostBody_.particles().addScratchField
        (
            "fluidForce",
            particleField::kind::vector
        );
    }
}


Foam::meshless::neighbourRelation& Foam::meshless::ghostBoundary::ownRelation
(
    sceneRelations& relations,
    const smoothingKernel& W,
    const bool rigid
)
{
    const particleField& x = ghostBody_.particles().positions();
    neighbourRelation& own = relations.inner
    (
        ghostBody_.name() + " (ghosts)", x, W, 0, !rigid,
        neighbourRelation::separation | neighbourRelation::kernelValue
    );
    relations.update(own);
    return own;
}


void Foam::meshless::ghostBoundary::computeOwnShapeTensors
(
    const neighbourRelation& own,
    particleField& M
) const
{
    dispatchDim(ghostBody_.dim(), [&](auto d)
    {
        correctionMatrix::moments<d>
        (
            own, V0_.data(), correctionMatrix::kernelWeight(), M.data()
        );
    });
}


namespace
{

//- Eq. 50-54 at a ghost particle s from its fluid neighbours f, and the
//  fluid's part of its shape tensor
template<int Dim>
struct interpolationTerm
{
    struct sum
    {
        double sumW, sumWp;
        Foam::meshless::vectorD<Dim> sumWrhoX, sumWU;
        Foam::meshless::tensorD<Dim> M;
    };

    const double* pF;
    const double* rhoF;
    const double* UF;
    const double* Mown;
    Foam::meshless::vectorD<Dim> g;
    double c0, rho0, minPressure;
    bool noSlip;
    const double* acc;
    const double* Uw;
    const double* nrm;
    const double* V0;
    double* p;
    double* rho;
    double* m;
    double* Uv;
    double* S;

    sum start(const Foam::label s) const
    {
        using namespace Foam::meshless;
        return
        {
            0, 0, vectorD<Dim>::Zero(), vectorD<Dim>::Zero(),
            ctens<Dim>(Mown, s)
        };
    }
    void pair
    (
        sum& a, const Foam::meshless::pairView& v,
        const Foam::label, const Foam::label q
    ) const
    {
        using namespace Foam::meshless;
        const Foam::label f = v.j[q];
        const auto xsf = v.x<Dim>(q);
        const double w = v.w[q];
        a.sumW += w;
        a.sumWp += w*pF[f];
        a.sumWrhoX += (w*rhoF[f])*xsf;
        a.sumWU += w*cvec<Dim>(UF, f);
        a.M.noalias() += (w*v.V[f])*(xsf*xsf.transpose());
    }
    void finish(const Foam::label s, sum& a) const
    {
        using namespace Foam::meshless;
        tensorD<Dim> inv;
        correctionMatrix::robustInverse<Dim>(a.M, inv);

        // Eq. 52: gravity less the boundary's own acceleration
        vectorD<Dim> gEff = g;
        if (acc) gEff -= cvec<Dim>(acc, s);
        const double ps = a.sumW > 0
            ? std::max((a.sumWp - gEff.dot(a.sumWrhoX))/a.sumW, minPressure)
            : 0;
        const vectorD<Dim> uTilde =
            a.sumW > 0 ? vectorD<Dim>(a.sumWU/a.sumW) : vectorD<Dim>::Zero();

        p[s] = ps;
        rho[s] = ps/(c0*c0) + rho0;
        m[s] = rho[s]*V0[s];

        const auto uw = cvec<Dim>(Uw, s);
        if (noSlip)
        {
            vec<Dim>(Uv, s) = 2*uw - uTilde;
        }
        else
        {
            // Free slip mirrors only the normal velocity: the fluid slides
            // along the wall without shear but cannot approach it unopposed
            const auto nv = cvec<Dim>(nrm, s);
            vec<Dim>(Uv, s) = uTilde - 2*uTilde.dot(nv)*nv + 2*uw.dot(nv)*nv;
        }
        tens<Dim>(S, s) = -ps*inv;
    }
};

} // End anonymous namespace


template<int Dim>
void Foam::meshless::ghostBoundary::interpolateImpl
(
    const neighbourRelation& ghostToFluid,
    const double* pF,
    const double* rhoF,
    const double* UF,
    const double* VF,
    const vector& g,
    const scalar c0,
    const scalar rho0
)
{
    vectorD<Dim> gD;
    for (int d = 0; d < Dim; ++d) gD(d) = g[d];
    gather
    (
        ghostToFluid, VF,
        interpolationTerm<Dim>
        {
            pF, rhoF, UF, ownShapeTensors(), gD, c0, rho0, minPressure_,
            slip_ == slipType::noSlip, accelerations(), Uown_.data(),
            normals(), V0_.data(), p_.data(), rho_.data(), mass_.data(),
            Uvisc_.data(), S_.data()
        }
    );
}


void Foam::meshless::ghostBoundary::interpolate
(
    const neighbourRelation& ghostToFluid,
    const double* pF,
    const double* rhoF,
    const double* UF,
    const double* VF,
    const vector& g,
    const scalar c0,
    const scalar rho0
)
{
    dispatchDim(ghostBody_.dim(), [&](auto d)
    {
        interpolateImpl<d>(ghostToFluid, pF, rhoF, UF, VF, g, c0, rho0);
    });
}


const double* Foam::meshless::ghostBoundary::contactDepth() const
{
    const particleSet& set = ghostBody_.particles();
    return set.found("wallDistance") ? set.field("wallDistance").data() : nullptr;
}


// ************************************************************************* //
