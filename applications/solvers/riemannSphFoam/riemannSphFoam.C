/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Application
    riemannSphFoam

Group
    grpLagrangianSolvers

Description
    Riemann weakly compressible SPH fluid with reverse kernel gradient
    correction (RKGC) and dual-criteria time stepping, after Zhang, Yu,
    Hu et al., "A reverse kernel gradient corrected Riemann SPH method for
    multi-resolution fluid-structure interaction" (RKGC paper). The fluid
    model (riemannWcsph), its kernel correction, the walls (ghostWall) and
    the effects are selected in constant/particleProperties; monitors
    write probes and energies to postProcessing/. The multi-resolution
    coupling with the TLSPH solid arrives with its coupling.

Usage
    \b riemannSphFoam [-case dir]

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
        "Riemann weakly compressible SPH fluid with kernel gradient corrections"
    );
    #include "setRootCase.H"
    #include "runScene.H"

    return 0;
}


// ************************************************************************* //
