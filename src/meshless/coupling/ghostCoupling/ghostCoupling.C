/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ghostCoupling.H"
#include "solidModel.H"
#include "particleScene.H"
#include "fluidModel.H"
#include "particleDistribution.H"

Foam::meshless::ghostCoupling::ghostCoupling
(
    const dictionary& dict,
    particleScene& scene
)
:
    fsiCoupling(dict, scene),
    fluidBody_(&fluidBody("fluid")),
    fluid_(fluidBody_->model().fluid()),
    solidBodies_(solidBodies())
{}


Foam::meshless::deformingGhost& Foam::meshless::ghostCoupling::addGhosts
(
    particleBody& sb,
    const word& accName,
    const word& velocityName
)
{
    ghosts_.emplace_back(new deformingGhost(sb, accName, velocityName));
    deformingGhost& g = *ghosts_.back();
    g.requestReaction();
    fluid_->addBoundary(g);
    boundaries_.append(&g);
    return g;
}


const double* Foam::meshless::ghostCoupling::reaction(const label k)
{
    deformingGhost& g = *ghosts_[k];
    particleDistribution::share
    (
        solidBodies_[k]->particles(), *g.reactionField()
    );
    return g.reaction();
}


void Foam::meshless::ghostCoupling::updateGhosts()
{
    forAll(solidBodies_, k)
    {
        deformingGhost& g = *ghosts_[k];
        if (g.contact()) solidBodies_[k]->model().solid()->normals();
        g.update();
    }
}


bool Foam::meshless::ghostCoupling::couples(const particleBody& b) const
{
    if (&b == fluidBody_) return true;
    for (const particleBody* s : solidBodies_)
    {
        if (&b == s) return true;
    }
    return false;
}


Foam::scalar Foam::meshless::ghostCoupling::maxDeltaT
(
    const scalar maxCo
) const
{
    maxCo_ = maxCo;
    return fluidBody_->maxDeltaT(maxCo);
}


void Foam::meshless::ghostCoupling::describeBodies(Ostream& os) const
{
    os  << "    coupling " << type() << ": fluid " << fluidBody_->name()
        << ", solids (";
    forAll(solidBodies_, k)
    {
        os  << (k ? " " : "") << solidBodies_[k]->name();
    }
    os  << ")";
}


// ************************************************************************* //
