/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Application
    ulphPdFoam

Group
    grpLagrangianSolvers

Description
    Updated Lagrangian particle hydrodynamics (ULPH) weakly compressible
    fluid with fixed ghost walls, after Wang, Xiong, Li, Lai, Liu and Liu,
    "An updated Lagrangian particle hydrodynamics (ULPH)-NOSBPD coupling
    approach for modeling fluid-structure interaction problem", CMES 2024,
    doi:10.32604/cmes.2024.052923. The fluid model
    (ulph), the walls (ghostWall) and the effects are selected in
    constant/particleProperties. The peridynamic solid and its coupling
    arrive with the solid model.

Usage
    \b ulphPdFoam [-case dir]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "particleScene.H"
#include "particleTimeLoop.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "ULPH fluid (and, to come, NOSB peridynamic solid) particle solver"
    );
    #include "setRootCase.H"
    #include "runScene.H"

    return 0;
}
