/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ghostWall.H"
#include "particleScene.H"
#include "ulphOperators.H"
#include "addToRunTimeSelectionTable.H"
#include <algorithm>

namespace Foam
{
namespace meshless
{
namespace bodyModels
{
    defineTypeNameAndDebug(ghostWall, 0);
    addToRunTimeSelectionTable(bodyModel, ghostWall, dictionary);
}
}
}

const Foam::Enum<Foam::meshless::bodyModels::ghostWall::slipType>
Foam::meshless::bodyModels::ghostWall::slipTypeNames
({
    { slipType::noSlip, "noSlip" },
    { slipType::freeSlip, "freeSlip" },
});


Foam::meshless::bodyModels::ghostWall::ghostWall
(
    particleBody& body,
    const dictionary& dict
)
:
    bodyModel(body, dict),
    slip_(slipTypeNames.get("slip", dict)),
    minPressure_(dict.getOrDefault<scalar>("minPressure", -GREAT)),
    U_(body.particles().addField("U", particleField::kind::vector)),
    p_(body.particles().addField("p", particleField::kind::scalar)),
    rho_(body.particles().addField("rho", particleField::kind::scalar)),
    mass_(body.particles().addField("mass", particleField::kind::scalar)),
    V0_(body.requireField("volume", "model ghostWall")),
    Uvisc_(body.particles().addScratchField("Uvisc", particleField::kind::vector)),
    Ucont_(body.particles().addScratchField("Ucont", particleField::kind::vector)),
    normal_(body.requireField("normal", "model ghostWall")),
    Mwall_(body.particles().addScratchField("Mwall", particleField::kind::tensor)),
    Minv_(body.particles().addScratchField("Minv", particleField::kind::tensor)),
    S_(body.particles().addScratchField("S", particleField::kind::tensor)),
    prepared_(false),
    motionTime_(),
    motion_(),
    x0_(nullptr),
    n0_(nullptr),
    acc_(nullptr),
    R_(tensor::I),
    movedTo_(-GREAT),
    zPlane_(0)
{
    if (dict.found("effects"))
    {
        FatalIOErrorInFunction(dict)
            << "Body '" << body.name() << "' is a fixed ghost wall: its"
            << " particles never move, so effects do not apply; remove"
            << " 'effects'" << exit(FatalIOError);
    }
}


void Foam::meshless::bodyModels::ghostWall::connect(particleScene& scene)
{
    if (!dict_.found("motion")) return;

    const Time& runTime = scene.time();
    motionTime_ = Time::New(runTime.path());
    motion_ = solidBodyMotionFunction::New(dict_.subDict("motion"), *motionTime_);
    zPlane_ = scene.zPlane();

    particleSet& set = body_.particles();
    x0_ = &set.addScratchField("x0", particleField::kind::vector);
    n0_ = &set.addScratchField("n0", particleField::kind::vector);
    acc_ = &set.addScratchField("acceleration", particleField::kind::vector);

    // The cloud holds the positions at the start time (moved, on restart):
    // back to the motion's reference frame
    const septernion T = transformationAt(runTime.value());
    const label dim = set.dim();
    const particleField& x = set.positions();
    for (label i = 0; i < set.size(); ++i)
    {
        vector p(Zero), n(Zero);
        p.z() = zPlane_;
        for (label d = 0; d < dim; ++d)
        {
            p[d] = x(i, d);
            n[d] = normal_(i, d);
        }
        const vector p0 = T.invTransformPoint(p);
        const vector n0 = T.r().invTransform(n);
        for (label d = 0; d < dim; ++d)
        {
            (*x0_)(i, d) = p0[d];
            (*n0_)(i, d) = n0[d];
        }
    }
    moveTo(runTime.value());

    // Shape tensors computed before the motion was known (the fluid may
    // connect first) were taken in the start frame: back to the reference
    if (prepared_) toReferenceFrame(Mwall_, R_);
}


void Foam::meshless::bodyModels::ghostWall::toReferenceFrame
(
    particleField& M,
    const tensor& R
)
{
    const label dim = body_.dim();
    for (label i = 0; i < M.size(); ++i)
    {
        tensor Mi(Zero);
        for (label a = 0; a < dim; ++a)
            for (label b = 0; b < dim; ++b) Mi(a, b) = M(i, a*dim + b);
        const tensor Mr = R.T() & Mi & R;
        for (label a = 0; a < dim; ++a)
            for (label b = 0; b < dim; ++b) M(i, a*dim + b) = Mr(a, b);
    }
}


Foam::septernion Foam::meshless::bodyModels::ghostWall::transformationAt
(
    const scalar t
)
{
    motionTime_->setTime(t, 0);
    return motion_->transformation();
}


void Foam::meshless::bodyModels::ghostWall::moveTo(const scalar t)
{
    if (!motion_.valid() || t == movedTo_) return;

    // Central differences of the rigid transformation
    const scalar d = 1e-4;
    const septernion Tm = transformationAt(t - d);
    const septernion T0 = transformationAt(t);
    const septernion Tp = transformationAt(t + d);

    particleSet& set = body_.particles();
    const label dim = set.dim();
    particleField& x = set.positions();
    particleField& n = normal_;

    for (label i = 0; i < set.size(); ++i)
    {
        vector p0(Zero), n0(Zero);
        p0.z() = zPlane_;
        for (label c = 0; c < dim; ++c)
        {
            p0[c] = (*x0_)(i, c);
            n0[c] = (*n0_)(i, c);
        }
        const vector xm = Tm.transformPoint(p0);
        const vector xc = T0.transformPoint(p0);
        const vector xp = Tp.transformPoint(p0);
        const vector nc = T0.r().transform(n0);
        for (label c = 0; c < dim; ++c)
        {
            x(i, c) = xc[c];
            n(i, c) = nc[c];
            U_(i, c) = (xp[c] - xm[c])/(2*d);
            (*acc_)(i, c) = (xp[c] - 2*xc[c] + xm[c])/(d*d);
        }
    }
    R_ = T0.r().R();
    movedTo_ = t;
}


template<int Dim>
void Foam::meshless::bodyModels::ghostWall::prepareImpl
(
    const smoothingKernel& W
)
{
    using namespace ulphOperators;
    const particleSet& set = body_.particles();
    const double* x = set.positions().data();
    const double* V0 = V0_.data();
    cellLinkedList cells(Dim, W.radius());
    cells.build(x, set.size());
    neighbourList own;
    own.build(cells, x, set.size(), true);
    double* Mw = Mwall_.data();

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
        Eigen::Map<tensorD<Dim>>(Mw + size_t(s)*Dim*Dim) = M;
    }
}


void Foam::meshless::bodyModels::ghostWall::prepare(const smoothingKernel& W)
{
    if (prepared_) return;
    if (body_.dim() == 2) prepareImpl<2>(W);
    else prepareImpl<3>(W);

    // Kept in the motion's reference frame (R_ is the identity until the
    // motion is set up, see connect)
    toReferenceFrame(Mwall_, R_);
    prepared_ = true;
}


template<int Dim>
void Foam::meshless::bodyModels::ghostWall::interpolateImpl
(
    const neighbourList& wallToFluid,
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
    const particleSet& set = body_.particles();
    const double* xS = set.positions().data();
    const label n = set.size();
    vectorD<Dim> gD;
    for (int d = 0; d < Dim; ++d) gD(d) = g[d];
    const bool noSlip = slip_ == slipType::noSlip;

    double* p = p_.data();
    double* rho = rho_.data();
    double* m = mass_.data();
    const double* V0 = V0_.data();
    const double* Uw = U_.data();
    double* Uv = Uvisc_.data();
    double* Uc = Ucont_.data();
    const double* nrm = normal_.data();
    double* S = S_.data();
    double* Minv = Minv_.data();
    const double* Mw = Mwall_.data();
    const double* acc = acc_ ? acc_->data() : nullptr;
    tensorD<Dim> Rd;
    for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) Rd(a, b) = R_(a, b);

    #pragma omp parallel for schedule(static)
    for (label s = 0; s < n; ++s)
    {
        const Eigen::Map<const vectorD<Dim>> xs(xS + size_t(s)*Dim);
        double sumW = 0, sumWp = 0;
        vectorD<Dim> sumWrhoX = vectorD<Dim>::Zero();
        vectorD<Dim> sumWU = vectorD<Dim>::Zero();
        tensorD<Dim> M = Eigen::Map<const tensorD<Dim>>(Mw + size_t(s)*Dim*Dim);
        if (acc)
        {
            M = Rd*M*Rd.transpose();
        }
        for
        (
            const label* fp = wallToFluid.begin(s);
            fp != wallToFluid.end(s);
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

        // Eq. 52: gravity less the wall's acceleration
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
        // Free slip mirrors only the normal velocity: the fluid slides
        // along the wall without shear but cannot approach it unopposed
        const Eigen::Map<const vectorD<Dim>> n(nrm + size_t(s)*Dim);
        Eigen::Map<vectorD<Dim>>(Uv + size_t(s)*Dim) =
            noSlip
          ? vectorD<Dim>(2*uw - uTilde)
          : vectorD<Dim>(uTilde - 2*uTilde.dot(n)*n + 2*uw.dot(n)*n);

        Eigen::Map<vectorD<Dim>>(Uc + size_t(s)*Dim) =
            noSlip
          ? vectorD<Dim>(uw)
          : vectorD<Dim>(uTilde - uTilde.dot(n)*n + uw.dot(n)*n);

        Eigen::Map<tensorD<Dim>>(S + size_t(s)*Dim*Dim) = -ps*inv;
    }
}


void Foam::meshless::bodyModels::ghostWall::interpolate
(
    const neighbourList& wallToFluid,
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
    if (body_.dim() == 2)
    {
        interpolateImpl<2>(wallToFluid, xF, pF, rhoF, UF, VF, W, g, c0, rho0);
    }
    else
    {
        interpolateImpl<3>(wallToFluid, xF, pF, rhoF, UF, VF, W, g, c0, rho0);
    }
}
