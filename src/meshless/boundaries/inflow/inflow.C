/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "inflow.H"
#include "particleScene.H"
#include "fluidModel.H"
#include "particleExpression.H"
#include "ListListOps.H"
#include <algorithm>
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
    // (OpenFOAM's expressions reduce over the processors: every processor
    // evaluates, with no point if need be)
    if (!nb && !Pstream::parRun()) return;

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
    particleSet& set = body_.particles();
    crossed_.clear();
    for (const label i : buffer_)
    {
        // (a parallel run's halo, selected with the step's particles, is
        // gone: its own processor emits it)
        if (i < set.size() && distance(i) >= 0) crossed_.push_back(i);
    }
    buffer_.clear();
    const label nc = crossed_.size();

    // The copies' ids: from the largest next id of any processor, in the
    // order of their sources' ids over every processor's (unique, and the
    // same for any decomposition)
    labelList sources(nc);
    forAll(sources, k) sources[k] = set.ids()[crossed_[k]];
    label base = set.nextId();
    labelList every(sources);
    if (Pstream::parRun())
    {
        base = returnReduce(base, maxOp<label>());
        List<labelList> all(Pstream::nProcs());
        all[Pstream::myProcNo()] = sources;
        Pstream::gatherList(all);
        Pstream::scatterList(all);
        every = ListListOps::combine<labelList>(all, accessOp<labelList>());
    }
    Foam::sort(every);
    const label next = base + every.size();
    if (!nc)
    {
        if (next != set.nextId()) set.setNextId(next);
        return 0;
    }

    // The crossed particles go on as fluid, their copies (buffer
    // particles) a buffer length upstream
    const label first = set.appendCopies(crossed_);
    forAll(sources, k)
    {
        const label rank = label
        (
            std::lower_bound(every.begin(), every.end(), sources[k])
          - every.begin()
        );
        set.ids()[first + k] = base + rank;
    }
    if (next != set.nextId()) set.setNextId(next);
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
