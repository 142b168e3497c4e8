/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "inflow.H"
#include "particleScene.H"
#include "fluidModel.H"
#include "particleExpression.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace openBoundaries
{
    defineTypeNameAndDebug(inflow, 0);
    addToRunTimeSelectionTable(openBoundary, inflow, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::meshless::openBoundaries::inflow::inflow
(
    const word& name,
    const dictionary& dict,
    particleScene& scene
)
:
    openBoundary(name, dict, scene),
    velocityDict_(dict_.subDict("velocity")),
    inBuffer_
    (
        [&]() -> particleField&
        {
            particleSet& set = body_.particles();
            const word field(name + "Buffer");
            const bool fresh = !set.found(field);
            particleField& f =
                set.addField(field, particleField::kind::scalar);
            // A fresh start: the buffer is what lies in its layer
            if (fresh)
            {
                for (label i = 0; i < set.size(); ++i)
                {
                    const scalar s = distance(i);
                    f(i, 0) = s >= -bufferLength_ && s < 0 ? 1 : 0;
                }
            }
            return f;
        }()
    )
{
    if (bufferLength_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "Inflow " << name << ": 'bufferLength' " << bufferLength_
            << ": expected a buffer length > 0 (a kernel support or more)"
            << exit(FatalIOError);
    }
    if (dict_.found("ramp"))
    {
        ramp_ = Function1<scalar>::New("ramp", dict_);
    }

    // Check the expression once (a vector per point)
    vectorField X(1, point_);
    const scalar t0 = scene.time().value();
    particleExpression::evaluate(velocityDict_, X, &t0);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::meshless::openBoundaries::inflow::ramp
(
    const scalar t
) const
{
    return ramp_.valid() ? ramp_->value(t) : 1;
}


void Foam::meshless::openBoundaries::inflow::select(const scalar t)
{
    buffer_.clear();
    const label n = body_.particles().size();
    for (label i = 0; i < n; ++i)
    {
        if (inBuffer_(i, 0) > 0.5) buffer_.push_back(i);
    }
    const label nb = buffer_.size();
    target_.resize(nb);
    if (!nb) return;

    const particleField& x = body_.particles().positions();
    X_.resize(nb);
    for (label k = 0; k < nb; ++k)
    {
        X_[k] = Zero;
        for (label d = 0; d < dim_; ++d) X_[k][d] = x(buffer_[k], d);
    }
    const tmp<vectorField> tU =
        particleExpression::evaluate(velocityDict_, X_, &t);
    for (label k = 0; k < nb; ++k) target_[k] = tU()[k];
}


void Foam::meshless::openBoundaries::inflow::constrain
(
    const scalar t,
    double* U,
    double*
)
{
    const scalar f = ramp(t);
    const label nb = buffer_.size();
    for (label k = 0; k < nb; ++k)
    {
        double* u = U + size_t(buffer_[k])*dim_;
        for (label d = 0; d < dim_; ++d) u[d] = f*target_[k][d];
    }
}


Foam::label Foam::meshless::openBoundaries::inflow::emit(const scalar)
{
    crossed_.clear();
    for (const label i : buffer_)
    {
        if (distance(i) >= 0) crossed_.push_back(i);
    }
    buffer_.clear();
    const label nc = crossed_.size();
    if (!nc) return 0;

    // The crossed particles go on as fluid, their copies (buffer
    // particles) a buffer length upstream
    particleSet& set = body_.particles();
    const label first = set.appendCopies(crossed_);
    for (const label i : crossed_) inBuffer_(i, 0) = 0;
    particleField& x = set.positions();
    const particleField& m = set.field("mass");
    for (label k = 0; k < nc; ++k)
    {
        for (label d = 0; d < dim_; ++d)
        {
            x(first + k, d) -= bufferLength_*normal_[d];
        }
        mass_ += m(first + k, 0);
    }
    particles_ += nc;
    return nc;
}


Foam::label Foam::meshless::openBoundaries::inflow::remove(const scalar)
{
    // Fluid particles back upstream of the plane leave through the inlet
    return removeWhere
    (
        [&](const label i) { return inBuffer_(i, 0) < 0.5 && distance(i) < 0; }
    );
}


// ************************************************************************* //
