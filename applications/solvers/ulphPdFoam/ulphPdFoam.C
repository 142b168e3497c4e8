/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Application
    ulphPdFoam

Group
    grpLagrangianSolvers

Description
    Updated Lagrangian particle hydrodynamics (ULPH) weakly compressible
    fluid with ghost walls, non-ordinary state-based peridynamic (NOSB-PD)
    solids, and their coupling, after Wang, Xiong, Li, Lai, Liu and Liu,
    "An updated Lagrangian particle hydrodynamics (ULPH)-NOSBPD coupling
    approach for modeling fluid-structure interaction problem", CMES 2024,
    doi:10.32604/cmes.2024.052923. The fluid model
    (ulph), the walls (ghostWall), the solids (nosbPd), the effects and the
    fluid-structure coupling (coupling { type ulphPd; ... }) are selected in
    constant/particleProperties; a scene without a coupling advances each
    body on its own.

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
        "ULPH fluid, NOSB peridynamic solid and their coupling"
    );
    #include "setRootCase.H"
    #include "runScene.H"

    return 0;
}
