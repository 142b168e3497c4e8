/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "bodyModel.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(bodyModel, 0);
    defineRunTimeSelectionTable(bodyModel, dictionary);
}
}


Foam::meshless::bodyModel::bodyModel
(
    particleBody& body,
    const dictionary& dict
)
:
    body_(body),
    dict_(dict)
{}
