/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "linearSolver.H"
#include "dictionaryChecks.H"
#include "Ostream.H"
#include <algorithm>
#include <cmath>

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(linearSolver, 0);
    defineRunTimeSelectionTable(linearSolver, dictionary);
}
}


Foam::meshless::linearSolver::linearSolver(const dictionary& dict)
:
    tolerance_
    (
        dict.found("tolerance")
      ? readInOpenRange(dict, "tolerance", 0, 1)
      : 1e-8
    ),
    maxIter_
    (
        dict.found("maxIter") ? readPositiveLabel(dict, "maxIter") : 1000
    )
{}


double Foam::meshless::linearSolver::norm
(
    const double* v,
    const label n
) const
{
    return norm2(v, n);
}


double Foam::meshless::linearSolver::residualNorm
(
    const sparseMatrix& A,
    const double* b,
    const double* x
) const
{
    if (A.distributed())
    {
        FatalErrorInFunction
            << "pressureSolver " << type() << " solves a system on one"
            << " processor; a parallel run's is distributed: expected"
            << " solver BoomerAMG" << exit(FatalError);
    }
    return A.residualNorm(b, x);
}


Foam::meshless::linearSolver::performance
Foam::meshless::linearSolver::run
(
    const sparseMatrix& A,
    const double* b,
    double* x,
    const std::function<label(const label maxIter)>& iterate
) const
{
    performance p{type(), 0, 0, 0, true};

    const label n = A.n();
    const double bNorm = norm(b, n);
    if (bNorm == 0)
    {
        std::fill(x, x + n, 0.0);
        return p;
    }

    p.initialResidual = residualNorm(A, b, x)/bNorm;
    p.finalResidual = p.initialResidual;
    p.converged = p.finalResidual <= tolerance_;

    while (!p.converged && p.iterations < maxIter_)
    {
        const label done = iterate(maxIter_ - p.iterations);
        p.iterations += done;
        p.finalResidual = residualNorm(A, b, x)/bNorm;
        p.converged = p.finalResidual <= tolerance_;

        if (done <= 0 || !std::isfinite(p.finalResidual))
        {
            break;
        }
    }

    return p;
}


Foam::Ostream& Foam::meshless::operator<<
(
    Ostream& os,
    const linearSolver::performance& p
)
{
    os  << p.solver << ": initial residual " << p.initialResidual
        << ", final residual " << p.finalResidual
        << ", iterations " << p.iterations
        << (p.converged ? "" : " (not converged)");
    return os;
}
