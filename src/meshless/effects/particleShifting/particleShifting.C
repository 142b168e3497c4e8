/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "particleShifting.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace effects
{
    defineTypeNameAndDebug(particleShifting, 0);
    addToRunTimeSelectionTable(effect, particleShifting, dictionary);
}
}
}


Foam::meshless::effects::particleShifting::particleShifting
(
    const word& name,
    const dictionary& dict,
    particleBody& body
)
:
    effect(name, dict, body),
    coefficient_(readPositiveOrDefault(dict, "coefficient", 0.05)),
    maxShift_(readPositiveOrDefault(dict, "maxShift", 0.2)),
    correctVelocity_(dict.getOrDefault<bool>("correctVelocity", false))
{
    if (coefficient_ > 1)
    {
        FatalIOErrorInFunction(dict)
            << "coefficient " << coefficient_ << ": expected C of"
            << " dr = C |u|max dt R at most 1 (the paper: 0.01-0.1)"
            << exit(FatalIOError);
    }
    if (maxShift_ > 0.5)
    {
        FatalIOErrorInFunction(dict)
            << "maxShift " << maxShift_ << ": expected at most 0.5 (the"
            << " largest shift per step in smoothing lengths; the paper:"
            << " 0.2)" << exit(FatalIOError);
    }
}


void Foam::meshless::effects::particleShifting::describe(Ostream& os) const
{
    os  << "particle shifting, dr = " << coefficient_ << " |u|max dt R,"
        << " at most " << maxShift_ << " h per step"
        << (correctVelocity_ ? ", velocity corrected" : "");
}

// ************************************************************************* //
