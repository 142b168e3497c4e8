/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "fixed.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
namespace bodyModels
{
    defineTypeNameAndDebug(fixed, 0);
    addToRunTimeSelectionTable(bodyModel, fixed, dictionary);
    addModelRole(fixed, wall);
}
}
}


Foam::meshless::bodyModels::fixed::fixed
(
    particleBody& body,
    const dictionary& dict
)
:
    bodyModel(body, dict)
{
    if (dict.found("effects"))
    {
        FatalIOErrorInFunction(dict)
            << "Body '" << body.name() << "' is fixed: its particles never"
            << " move, so effects do not apply; remove 'effects'"
            << exit(FatalIOError);
    }
}
