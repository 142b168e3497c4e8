/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Application
    isphTlsphFoam

Group
    grpLagrangianSolvers

Description
    Total Lagrangian SPH (TLSPH) solid, after Salehizadeh and Shafiei, "A
    coupled ISPH-TLSPH method for simulating fluid-elastic structure
    interaction problems", J. Marine Sci. Appl. (2022). The solid model
    (tlsph), its constitutive law, constraints, initial velocity and
    effects are selected in constant/particleProperties; monitors write
    point displacements and energies to postProcessing/. The projection
    ISPH fluid and its coupling arrive with the fluid model.

Usage
    \b isphTlsphFoam [-case dir]

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
        "Total Lagrangian SPH solid (and, to come, ISPH fluid) particle solver"
    );
    #include "setRootCase.H"
    #include "runScene.H"

    return 0;
}


// ************************************************************************* //
