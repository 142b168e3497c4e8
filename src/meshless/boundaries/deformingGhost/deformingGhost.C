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
    own_(nullptr),
    contactN_(nullptr),
    contactDepth_(nullptr)
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
    if (contactN_)
    {
        const particleSet& set = ghostBody().particles();
        const particleField& N = set.field("normal");
        const label n = N.size()*N.nComponents();
        const double* Nd = N.data();
        double* c = contactN_->data();
        for (label k = 0; k < n; ++k) c[k] = -Nd[k];
    }
}


void Foam::meshless::deformingGhost::enableContact()
{
    if (contactN_) return;
    particleSet& set = ghostBody().particles();
    contactN_ =
        &set.addScratchField("ghostContactNormal", particleField::kind::vector);
    contactDepth_ =
        &set.addScratchField("ghostContactDepth", particleField::kind::scalar);
    contactDepth_->fill(0.5*ghostBody().spacing());
}


// ************************************************************************* //
