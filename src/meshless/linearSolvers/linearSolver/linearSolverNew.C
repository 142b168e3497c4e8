/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "linearSolver.H"
#include "dictionaryChecks.H"

Foam::autoPtr<Foam::meshless::linearSolver>
Foam::meshless::linearSolver::New(const dictionary& dict)
{
    const word solverType(dict.get<word>("solver"));
    return selectConstructor
    (
        dict, "solver", solverType, *dictionaryConstructorTablePtr_
    )(dict);
}
