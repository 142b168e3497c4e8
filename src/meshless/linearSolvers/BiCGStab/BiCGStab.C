/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "BiCGStab.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(BiCGStab, 0);
    addToRunTimeSelectionTable(linearSolver, BiCGStab, dictionary);
}
}
