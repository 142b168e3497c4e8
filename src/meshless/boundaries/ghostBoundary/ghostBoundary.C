/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ghostBoundary.H"
#include "ulphOperators.H"
#include "cellLinkedList.H"
#include <algorithm>

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
    const word& prefix
)
:
    ghostBody_(body),
    slip_(slip),
    minPressure_(minPressure),
    Uown_(body.particles().addField("U", particleField::kind::vector)),
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
    Minv_
    (
        body.particles().addScratchField
        (
            prefixed(prefix, "Minv"), particleField::kind::tensor
        )
    ),
    S_
    (
        body.particles().addScratchField
        (
            prefixed(prefix, "S"), particleField::kind::tensor
        )
    ),
    reaction_(nullptr)
{}


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


template<int Dim>
void Foam::meshless::ghostBoundary::ownShapeTensorsImpl
(
    const smoothingKernel& W,
    particleField& Mown
) const
{
    using namespace ulphOperators;
    const particleSet& set = ghostBody_.particles();
    const double* x = set.positions().data();
    const double* V0 = V0_.data();
    cellLinkedList cells(Dim, W.radius());
    cells.build(x, set.size());
    neighbourList own;
    own.build(cells, x, set.size(), true);
    double* Mo = Mown.data();

    #pragma omp parallel for schedule(static)
    for (label s = 0; s < set.size(); ++s)
    {
        const Eigen::Map<const vectorD<Dim>> xs(x + size_t(s)*Dim);
        tensorD<Dim> M = tensorD<Dim>::Zero();
        for (const label* jp = own.begin(s); jp != own.end(s); ++jp)
        {
            const vectorD<Dim> xsj =
                Eigen::Map<const vectorD<Dim>>(x + size_t(*jp)*Dim) - xs;
            M.noalias() += (W.W(xsj.norm())*V0[*jp])*(xsj*xsj.transpose());
        }
        Eigen::Map<tensorD<Dim>>(Mo + size_t(s)*Dim*Dim) = M;
    }
}


void Foam::meshless::ghostBoundary::computeOwnShapeTensors
(
    const smoothingKernel& W,
    particleField& M
) const
{
    if (ghostBody_.dim() == 2) ownShapeTensorsImpl<2>(W, M);
    else ownShapeTensorsImpl<3>(W, M);
}


template<int Dim>
void Foam::meshless::ghostBoundary::interpolateImpl
(
    const neighbourList& ghostToFluid,
    const double* xF,
    const double* pF,
    const double* rhoF,
    const double* UF,
    const double* VF,
    const smoothingKernel& W,
    const vector& g,
    const scalar c0,
    const scalar rho0
)
{
    using namespace ulphOperators;
    const particleSet& set = ghostBody_.particles();
    const double* xS = set.positions().data();
    const label n = set.size();
    vectorD<Dim> gD;
    for (int d = 0; d < Dim; ++d) gD(d) = g[d];
    const bool noSlip = slip_ == slipType::noSlip;

    double* p = p_.data();
    double* rho = rho_.data();
    double* m = mass_.data();
    const double* V0 = V0_.data();
    const double* Uw = Uown_.data();
    double* Uv = Uvisc_.data();
    const double* nrm = normals();
    double* S = S_.data();
    double* Minv = Minv_.data();
    const double* Mown = ownShapeTensors();
    const double* acc = accelerations();

    #pragma omp parallel for schedule(static)
    for (label s = 0; s < n; ++s)
    {
        const Eigen::Map<const vectorD<Dim>> xs(xS + size_t(s)*Dim);
        double sumW = 0, sumWp = 0;
        vectorD<Dim> sumWrhoX = vectorD<Dim>::Zero();
        vectorD<Dim> sumWU = vectorD<Dim>::Zero();
        tensorD<Dim> M =
            Eigen::Map<const tensorD<Dim>>(Mown + size_t(s)*Dim*Dim);
        for
        (
            const label* fp = ghostToFluid.begin(s);
            fp != ghostToFluid.end(s);
            ++fp
        )
        {
            const label f = *fp;
            const vectorD<Dim> xsf =
                Eigen::Map<const vectorD<Dim>>(xF + size_t(f)*Dim) - xs;
            const double w = W.W(xsf.norm());
            sumW += w;
            sumWp += w*pF[f];
            sumWrhoX += (w*rhoF[f])*xsf;
            sumWU += w*Eigen::Map<const vectorD<Dim>>(UF + size_t(f)*Dim);
            M.noalias() += (w*VF[f])*(xsf*xsf.transpose());
        }
        tensorD<Dim> inv;
        invertShapeTensor<Dim>(M, inv);
        Eigen::Map<tensorD<Dim>>(Minv + size_t(s)*Dim*Dim) = inv;

        // Eq. 52: gravity less the boundary's own acceleration
        vectorD<Dim> gEff = gD;
        if (acc)
        {
            gEff -= Eigen::Map<const vectorD<Dim>>(acc + size_t(s)*Dim);
        }
        const double ps = sumW > 0
            ? std::max((sumWp - gEff.dot(sumWrhoX))/sumW, minPressure_)
            : 0;
        const vectorD<Dim> uTilde =
            sumW > 0 ? vectorD<Dim>(sumWU/sumW) : vectorD<Dim>::Zero();

        p[s] = ps;
        rho[s] = ps/(c0*c0) + rho0;
        m[s] = rho[s]*V0[s];

        const Eigen::Map<const vectorD<Dim>> uw(Uw + size_t(s)*Dim);
        if (noSlip)
        {
            Eigen::Map<vectorD<Dim>>(Uv + size_t(s)*Dim) = 2*uw - uTilde;
        }
        else
        {
            // Free slip mirrors only the normal velocity: the fluid slides
            // along the wall without shear but cannot approach it unopposed
            const Eigen::Map<const vectorD<Dim>> nv(nrm + size_t(s)*Dim);
            Eigen::Map<vectorD<Dim>>(Uv + size_t(s)*Dim) =
                uTilde - 2*uTilde.dot(nv)*nv + 2*uw.dot(nv)*nv;
        }

        Eigen::Map<tensorD<Dim>>(S + size_t(s)*Dim*Dim) = -ps*inv;
    }
}


void Foam::meshless::ghostBoundary::interpolate
(
    const neighbourList& ghostToFluid,
    const double* xF,
    const double* pF,
    const double* rhoF,
    const double* UF,
    const double* VF,
    const smoothingKernel& W,
    const vector& g,
    const scalar c0,
    const scalar rho0
)
{
    if (ghostBody_.dim() == 2)
    {
        interpolateImpl<2>(ghostToFluid, xF, pF, rhoF, UF, VF, W, g, c0, rho0);
    }
    else
    {
        interpolateImpl<3>(ghostToFluid, xF, pF, rhoF, UF, VF, W, g, c0, rho0);
    }
}


// ************************************************************************* //
