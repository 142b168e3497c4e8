/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "openBoundary.H"
#include "particleScene.H"
#include "fluidModel.H"
#include "dictionaryChecks.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(openBoundary, 0);
    defineRunTimeSelectionTable(openBoundary, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::meshless::openBoundary::openBoundary
(
    const word& name,
    const dictionary& dict,
    particleScene& scene
)
:
    name_(name),
    dict_(dict),
    body_(scene.body(dict.get<word>("body"), dict)),
    fluid_
    (
        [&]() -> fluidModel&
        {
            fluidModel* f = body_.model().fluid();
            if (!f)
            {
                FatalIOErrorInFunction(dict)
                    << "Open boundary " << name << ": body " << body_.name()
                    << " is not a fluid: expected a fluid body"
                    << exit(FatalIOError);
            }
            return *f;
        }()
    ),
    dim_(scene.dim()),
    point_(dict.get<vector>("point")),
    normal_(dict.get<vector>("normal")),
    bufferLength_(readNonNegativeOrDefault(dict, "bufferLength", 0)),
    particles_(0),
    mass_(0)
{
    if (dim_ == 2) normal_.z() = 0;
    if (mag(normal_) < SMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Open boundary " << name << ": 'normal' " << normal_
            << " is zero (or along z in 2D): expected the plane's normal"
            << exit(FatalIOError);
    }
    normal_ /= mag(normal_);
    fluid_.addOpenBoundary(*this);
}


Foam::autoPtr<Foam::meshless::openBoundary> Foam::meshless::openBoundary::New
(
    const word& name,
    const dictionary& dict,
    particleScene& scene
)
{
    const word boundaryType(dict.get<word>("type"));
    return selectConstructor
    (
        dict, "openBoundary", boundaryType, *dictionaryConstructorTablePtr_
    )(name, dict, scene);
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::scalar Foam::meshless::openBoundary::distance(const label i) const
{
    const double* x = body_.particles().positions().data() + size_t(i)*dim_;
    scalar s = 0;
    for (label d = 0; d < dim_; ++d) s += (x[d] - point_[d])*normal_[d];
    return s;
}


void Foam::meshless::openBoundary::selectBetween
(
    const scalar lo,
    const scalar hi
)
{
    buffer_.clear();
    const label n = body_.particles().size();
    for (label i = 0; i < n; ++i)
    {
        const scalar s = distance(i);
        if (s >= lo && s < hi) buffer_.push_back(i);
    }
}


Foam::label Foam::meshless::openBoundary::removeWhere
(
    const std::function<bool(label)>& leaves
)
{
    particleSet& set = body_.particles();
    const label n = set.size();
    marks_.assign(n, 0);
    const particleField& m = set.field("mass");
    label nr = 0;
    for (label i = 0; i < n; ++i)
    {
        if (leaves(i))
        {
            marks_[i] = 1;
            mass_ -= m(i, 0);
            ++nr;
        }
    }
    if (!nr) return 0;
    set.removeMarked(marks_);
    particles_ -= nr;
    return nr;
}


// ************************************************************************* //
