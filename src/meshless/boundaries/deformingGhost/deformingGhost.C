/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "deformingGhost.H"

Foam::meshless::deformingGhost::deformingGhost
(
    particleBody& body,
    const word& accName,
    const word& velocityName
)
:
    ghostBoundary(body, slipType::noSlip, -GREAT, "ghost", velocityName),
    acc_
    (
        accName.empty()
      ? nullptr
      : &body.requireField(accName, "ghost particles of a coupled body")
    ),
    Mown_
    (
        body.particles().addScratchField("ghostMown", particleField::kind::tensor)
    ),
    own_(nullptr)
{}


void Foam::meshless::deformingGhost::prepare
(
    const smoothingKernel& W,
    sceneRelations& relations
)
{
    own_ = &ownRelation(relations, W, false);
    update();
}


void Foam::meshless::deformingGhost::update()
{
    if (!own_) return;
    computeOwnShapeTensors(*own_, Mown_);
}


// ************************************************************************* //
