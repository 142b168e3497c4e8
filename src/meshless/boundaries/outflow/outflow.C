/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "outflow.H"
#include "particleScene.H"
#include "fluidModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace openBoundaries
{
    defineTypeNameAndDebug(outflow, 0);
    addToRunTimeSelectionTable(openBoundary, outflow, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::meshless::openBoundaries::outflow::outflow
(
    const word& name,
    const dictionary& dict,
    particleScene& scene
)
:
    openBoundary(name, dict, scene),
    setPressure_(dict.found("pressure")),
    pressure_(dict.getOrDefault<scalar>("pressure", 0))
{
    if (setPressure_ && bufferLength_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "Outflow " << name << ": 'pressure' needs a 'bufferLength'"
            << " > 0 (the layer where it is set)" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::openBoundaries::outflow::select(const scalar)
{
    if (setPressure_) selectBetween(-bufferLength_, 0);
}


void Foam::meshless::openBoundaries::outflow::constrain
(
    const scalar,
    double*,
    double* rho
)
{
    if (!setPressure_) return;
    const scalar rhoB = fluid_.density(pressure_);
    for (const label i : buffer_) rho[i] = rhoB;
}


Foam::label Foam::meshless::openBoundaries::outflow::remove(const scalar)
{
    buffer_.clear();
    return removeWhere([&](const label i) { return distance(i) >= 0; });
}


// ************************************************************************* //
