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
        dict.getOrDefault<scalar>("minPressure", -GREAT),
        word::null
    ),
    U_(body.particles().addField("U", particleField::kind::vector)),
    normal_(body.requireField("normal", "model ghostWall")),
    Mwall_(body.particles().addScratchField("Mwall", particleField::kind::tensor)),
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
    Mcurrent_ = &set.addScratchField("Mcurrent", particleField::kind::tensor);

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
    if (prepared_)
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
    if (prepared_) rotateShapeTensors();
}


void Foam::meshless::bodyModels::ghostWall::prepare(const smoothingKernel& W)
{
    if (prepared_) return;
    computeOwnShapeTensors(W, Mwall_);

    // Kept in the motion's reference frame (R_ is the identity until the
    // motion is set up, see connect)
    toReferenceFrame(Mwall_, R_);
    prepared_ = true;
    rotateShapeTensors();
}


// ************************************************************************* //
