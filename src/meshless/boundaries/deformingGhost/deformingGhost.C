/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "deformingGhost.H"

Foam::meshless::deformingGhost::deformingGhost
(
    particleBody& body,
    const word& accName
)
:
    ghostBoundary(body, slipType::noSlip, -GREAT, "ghost"),
    body_(body),
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
    W_(nullptr)
{}


void Foam::meshless::deformingGhost::prepare(const smoothingKernel& W)
{
    W_ = &W;
    update();
}


void Foam::meshless::deformingGhost::update()
{
    if (!W_) return;
    computeOwnShapeTensors(*W_, Mown_);
}


// ************************************************************************* //
