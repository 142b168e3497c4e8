/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "seedRegion.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(seedRegion, 0);
    defineRunTimeSelectionTable(seedRegion, dictionary);
}
}

// ************************************************************************* //
