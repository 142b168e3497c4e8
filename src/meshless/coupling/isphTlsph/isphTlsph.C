/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "isphTlsph.H"
#include "fluidModel.H"
#include "particleBody.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace couplings
{
    defineTypeNameAndDebug(isphTlsph, 0);
    addToRunTimeSelectionTable(fsiCoupling, isphTlsph, dictionary);
}
}
}


Foam::meshless::couplings::isphTlsph::isphTlsph
(
    const dictionary& dict,
    particleScene& scene
)
:
    ulphPd(dict, scene)
{
    if (fluid_->hasInnerSteps() || fluid_->soundSpeed() < GREAT)
    {
        FatalIOErrorInFunction(dict)
            << "coupling isphTlsph: fluid " << fluidBody_->name()
            << " has model " << fluidBody_->dict().get<word>("model")
            << ", a weakly compressible fluid: expected a projection fluid"
            << " (isph), or coupling riemannTlsph (riemannWcsph) or ulphPd"
            << exit(FatalIOError);
    }
}


void Foam::meshless::couplings::isphTlsph::describe(Ostream& os) const
{
    describeBodies(os);
    os  << ", solid particles in the fluid's Poisson equation and"
        << " projection, the pressure's exchange pair by pair, minSubSteps "
        << subSteps_.minSubSteps() << nl;
}


// ************************************************************************* //
