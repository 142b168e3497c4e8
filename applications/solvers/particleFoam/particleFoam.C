/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Application
    particleFoam

Group
    grpLagrangianSolvers

Description
    Advances the scene of constant/particleProperties when its bodies move
    on their own (no coupling between them): e.g. kinematic bodies under
    their effects beside fixed walls. The reference application of the
    shared machinery (scene, effects, time loop, output, restart) that the
    FSI solvers build on.

Usage
    \b particleFoam [-case dir]

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
        "Advance uncoupled particle bodies (constant/particleProperties)"
    );
    #include "setRootCase.H"
    #include "runScene.H"

    return 0;
}
