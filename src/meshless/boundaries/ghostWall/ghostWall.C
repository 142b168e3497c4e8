/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ghostWall.H"
#include "dispatchDim.H"
#include "dictionaryChecks.H"
#include "particleScene.H"
#include "smallTensor.H"
#include "addToRunTimeSelectionTable.H"
#include <algorithm>
#include <cstdint>
#include <unordered_set>

namespace Foam
{
namespace meshless
{
namespace bodyModels
{
    defineTypeNameAndDebug(ghostWall, 0);
    addToRunTimeSelectionTable(bodyModel, ghostWall, dictionary);
    addModelRole(ghostWall, wall);
}
}
}

Foam::meshless::bodyModels::ghostWall::ghostWall
(
    particleBody& body,
    const dictionary& dict
)
:
    bodyModel(body, dict),
    ghostBoundary
    (
        body,
        slipTypeNames.get("slip", dict),
        (
            checkRenamed(dict, {{"minPressure", "minWallPressure"}}),
            dict.getOrDefault<scalar>("minWallPressure", -GREAT)
        ),
        word::null
    ),
    referenceRead_
    (
        dict.found("motion") && body.particles().found("x0")
     && body.particles().found("n0") && body.particles().found("Mwall")
    ),
    U_(body.particles().addField("U", particleField::kind::vector)),
    normal_(body.requireField("normal", "model ghostWall")),
    // A moving wall writes its reference frame (restart state)
    Mwall_
    (
        dict.found("motion")
      ? body.particles().addField("Mwall", particleField::kind::tensor)
      : body.particles().addScratchField("Mwall", particleField::kind::tensor)
    ),
    Mcurrent_(nullptr),
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
            << " particles never move, so effects do not apply: expected"
            << " no 'effects' entry" << exit(FatalIOError);
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
    x0_ = &set.addField("x0", particleField::kind::vector);
    n0_ = &set.addField("n0", particleField::kind::vector);
    acc_ = &set.addScratchField("acceleration", particleField::kind::vector);
    Mcurrent_ = &set.addScratchField("Mcurrent", particleField::kind::tensor);

    // The cloud holds the positions at the start time: back to the
    // motion's reference frame, unless a restart read that frame
    const septernion T = transformationAt(runTime.value());
    const label dim = set.dim();
    const particleField& x = set.positions();
    for (label i = 0; i < (referenceRead_ ? 0 : set.size()); ++i)
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
    // (read in it on a restart)
    if (prepared_ && !referenceRead_)
    {
        toReferenceFrame(Mwall_, R_);
        rotateShapeTensors();
    }
}


void Foam::meshless::bodyModels::ghostWall::rotateShapeTensors()
{
    if (!Mcurrent_) return;
    const label dim = body_.dim();
    for (label i = 0; i < Mwall_.size(); ++i)
    {
        tensor Mi(Zero);
        for (label a = 0; a < dim; ++a)
            for (label b = 0; b < dim; ++b) Mi(a, b) = Mwall_(i, a*dim + b);
        const tensor Mr = R_ & Mi & R_.T();
        for (label a = 0; a < dim; ++a)
            for (label b = 0; b < dim; ++b) (*Mcurrent_)(i, a*dim + b) = Mr(a, b);
    }
}


const double*
Foam::meshless::bodyModels::ghostWall::ownShapeTensors() const
{
    return Mcurrent_ ? Mcurrent_->data() : Mwall_.data();
}


const double*
Foam::meshless::bodyModels::ghostWall::accelerations() const
{
    return acc_ ? acc_->data() : nullptr;
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


namespace
{
    //- The step of the motion's central differences [s]
    const Foam::scalar motionStep = 1e-4;
}


void Foam::meshless::bodyModels::ghostWall::transformationsAround
(
    const scalar t,
    septernion& Tm,
    septernion& T0,
    septernion& Tp
)
{
    Tm = transformationAt(t - motionStep);
    T0 = transformationAt(t);
    Tp = transformationAt(t + motionStep);
}


void Foam::meshless::bodyModels::ghostWall::pointRates
(
    const septernion& Tm,
    const septernion& Tp,
    const vector& X,
    const vector& xc,
    vector& v,
    vector& a
)
{
    const scalar d = motionStep;
    const vector xm = Tm.transformPoint(X);
    const vector xp = Tp.transformPoint(X);
    v = (xp - xm)/(2*d);
    a = (xp - 2*xc + xm)/(d*d);
}


void Foam::meshless::bodyModels::ghostWall::moveTo(const scalar t)
{
    if (!motion_.valid() || t == movedTo_) return;

    // Central differences of the rigid transformation
    septernion Tm, T0, Tp;
    transformationsAround(t, Tm, T0, Tp);

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
        const vector xc = T0.transformPoint(p0);
        const vector nc = T0.r().transform(n0);
        vector v, a;
        pointRates(Tm, Tp, p0, xc, v, a);
        for (label c = 0; c < dim; ++c)
        {
            x(i, c) = xc[c];
            n(i, c) = nc[c];
            U_(i, c) = v[c];
            (*acc_)(i, c) = a[c];
        }
    }
    R_ = T0.r().R();
    movedTo_ = t;
    if (prepared_) rotateShapeTensors();
}


void Foam::meshless::bodyModels::ghostWall::frameKinematics
(
    const scalar t,
    const label n,
    const label dim,
    const double* x,
    double* v,
    double* a
)
{
    std::fill(v, v + n*dim, 0.0);
    std::fill(a, a + n*dim, 0.0);
    if (!motion_.valid()) return;

    // The same central differences as moveTo's
    septernion Tm, T0, Tp;
    transformationsAround(t, Tm, T0, Tp);
    for (label i = 0; i < n; ++i)
    {
        vector p(Zero);
        p.z() = zPlane_;
        for (label c = 0; c < dim; ++c) p[c] = x[i*dim + c];
        vector vi, ai;
        pointRates(Tm, Tp, T0.invTransformPoint(p), p, vi, ai);
        for (label c = 0; c < dim; ++c)
        {
            v[i*dim + c] = vi[c];
            a[i*dim + c] = ai[c];
        }
    }
}


template<int Dim>
Foam::label Foam::meshless::bodyModels::ghostWall::completeFarSide
(
    const smoothingKernel& W,
    const neighbourRelation& own
)
{
    const particleSet& set = body_.particles();
    if (!set.found("wallDistance")) return 0;

    const particleField& dist = set.field("wallDistance");
    const label n = set.size();
    const double dx = body_.spacing();
    const double R = W.radius();
    const double* x = set.positions().data();
    const double* nrm = normal_.data();
    const double* V0 = V();

    // Lattice index of every particle (relative to the first), packed in
    // 21 bits per direction; a wall off its seeding lattice (a restart of
    // a rotated wall) is not completed. The tolerance allows for positions
    // written with few digits
    const int64_t off = int64_t(1) << 20;
    auto key = [off](const int64_t i, const int64_t j, const int64_t k)
    {
        return ((i + off) << 42) | ((j + off) << 21) | (k + off);
    };
    std::vector<int64_t> index(size_t(n)*3, 0);
    std::unordered_set<int64_t> taken;
    taken.reserve(2*n);
    double dmax = 0;
    bool offLattice = false;
    for (label s = 0; s < n && !offLattice; ++s)
    {
        for (int d = 0; d < Dim; ++d)
        {
            const double r = (x[s*Dim + d] - x[d])/dx;
            if (std::abs(r - std::round(r)) > 1e-3 || std::abs(r) >= off)
            {
                offLattice = true;
                break;
            }
            index[3*s + d] = std::llround(r);
        }
        taken.insert(key(index[3*s], index[3*s + 1], index[3*s + 2]));
        dmax = std::max(dmax, double(dist(s, 0)));
    }
    // In a parallel run over the whole wall: a processor's part may lack
    // the deepest particles (a corner's)
    if (Pstream::parRun())
    {
        reduce(offLattice, orOp<bool>());
        reduce(dmax, maxOp<double>());
    }
    if (offLattice) return -1;

    const label* rowStart = own.offsetData();
    const label* idx = own.indexData();
    const double tol = 1e-6*dx;
    double* Mw = Mwall_.data();

    // The lattice offsets inside the support, with their kernel weights:
    // the same for every particle (plain arrays: no Eigen alignment in a
    // std::vector)
    struct offset { int64_t i[3]; double delta[3]; double w; };
    std::vector<offset> offsets;
    const int m = int(std::ceil(R/dx));
    const int kMax = Dim == 3 ? m : 0;
    for (int a = -m; a <= m; ++a)
    {
        for (int b = -m; b <= m; ++b)
        {
            for (int c = -kMax; c <= kMax; ++c)
            {
                offset o{{a, b, c}, {a*dx, b*dx, c*dx}, 0};
                const double r =
                    Eigen::Map<const vectorD<Dim>>(o.delta).norm();
                o.w = r > 0 ? W.W(r) : 0;
                if (o.w > 0) offsets.push_back(o);
            }
        }
    }

    // Counted over the particles this processor owns
    const label nOwned = set.nOwned();
    label nCompleted = 0;
    #pragma omp parallel for schedule(static) reduction(+:nCompleted)
    for (label s = 0; s < n; ++s)
    {
        const Eigen::Map<const vectorD<Dim>> ns(nrm + size_t(s)*Dim);

        // Only where the support meets the deepest layer of the same wall:
        // a wall cut by the layer count, not a thin wall with fluid behind
        bool reachesBack = false;
        for (label q = rowStart[s]; q < rowStart[s + 1]; ++q)
        {
            const label j = idx[q];
            const Eigen::Map<const vectorD<Dim>> nj(nrm + size_t(j)*Dim);
            if (dist(j, 0) >= dmax - 0.5*dx - tol && nj.dot(ns) > 0.5)
            {
                reachesBack = true;
                break;
            }
        }
        if (!reachesBack) continue;

        // Depth of a lattice point: along the normal from the particle's
        // nearest wall point, where the particle's own depth is dist(s)
        const int64_t* is = &index[3*s];
        tensorD<Dim> M = tensorD<Dim>::Zero();
        for (const offset& o : offsets)
        {
            const Eigen::Map<const vectorD<Dim>> delta(o.delta);
            if
            (
                dist(s, 0) + delta.dot(ns) > dmax + tol
             && !taken.count
                (
                    key(is[0] + o.i[0], is[1] + o.i[1], is[2] + o.i[2])
                )
            )
            {
                M.noalias() += (o.w*V0[s])*(delta*delta.transpose());
            }
        }
        if (M.squaredNorm() > 0)
        {
            Eigen::Map<tensorD<Dim>>(Mw + size_t(s)*Dim*Dim) += M;
            if (s < nOwned) ++nCompleted;
        }
    }
    return nCompleted;
}


void Foam::meshless::bodyModels::ghostWall::prepare
(
    const smoothingKernel& W,
    sceneRelations& relations
)
{
    if (prepared_) return;

    // The wall moves rigidly: its own pairs are those of the start
    const neighbourRelation& own = ownRelation(relations, W, true);
    if (referenceRead_)
    {
        prepared_ = true;
        rotateShapeTensors();
        return;
    }
    computeOwnShapeTensors(own, Mwall_);
    label nCompleted = dispatchDim
    (
        body_.dim(), [&](auto d) { return completeFarSide<d>(W, own); }
    );
    if (Pstream::parRun() && nCompleted >= 0)
    {
        reduce(nCompleted, sumOp<label>());
    }
    if (nCompleted > 0)
    {
        Info<< "    ghostWall " << body_.name() << ": shape tensors"
            << " completed behind the seeded layers for " << nCompleted
            << " particles (their supports reach past the deepest one)"
            << endl;
    }
    else if (nCompleted < 0)
    {
        Info<< "    ghostWall " << body_.name() << ": particles off one"
            << " lattice (a rotated wall), shape tensors taken over the"
            << " seeded layers only" << endl;
    }

    // Kept in the motion's reference frame (R_ is the identity until the
    // motion is set up, see connect)
    toReferenceFrame(Mwall_, R_);
    prepared_ = true;
    rotateShapeTensors();
}


// ************************************************************************* //
