/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "constitutiveLaw.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(constitutiveLaw, 0);
    defineRunTimeSelectionTable(constitutiveLaw, dictionary);
}
}

const Foam::Enum<Foam::meshless::constitutiveLaw::planeModel>
Foam::meshless::constitutiveLaw::planeModelNames
({
    { planeModel::none, "none" },
    { planeModel::strain, "strain" },
    { planeModel::stress, "stress" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::constitutiveLaw::constitutiveLaw
(
    const dictionary& dict,
    const label dim
)
:
    dict_(dict),
    dim_(dim),
    plane_(planeModel::none),
    elastic_(dict)
{
    if (dim == 2)
    {
        if (!dict.found("plane"))
        {
            FatalIOErrorInFunction(dict)
                << "A 2D solid needs 'plane strain;' or 'plane stress;'"
                << exit(FatalIOError);
        }
        plane_ = planeModelNames.get("plane", dict);
        if (plane_ == planeModel::none)
        {
            FatalIOErrorInFunction(dict)
                << "plane: expected strain or stress for a 2D solid, not none"
                << exit(FatalIOError);
        }
    }
    else if (dict.found("plane"))
    {
        FatalIOErrorInFunction(dict)
            << "'plane' is for 2D solids only; this body is 3D"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::meshless::constitutiveLaw::planeLambda() const
{
    const scalar lambda = elastic_.lambda();
    const scalar G = elastic_.G();
    return plane_ == planeModel::stress ? 2*lambda*G/(lambda + 2*G) : lambda;
}


Foam::scalar Foam::meshless::constitutiveLaw::waveModulus() const
{
    return planeLambda() + 2*elastic_.G();
}


// ************************************************************************* //
