/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Application
    parallelLinearSolve

Description
    Test of the distributed linear solve (tests/cases/parallelRuns.py runs
    it): the 5-point Laplacian of an N x N grid with Dirichlet boundaries
    (symmetric), and the same with a first-order convection term
    (non-symmetric), their rows split in contiguous blocks over the
    processors of a parallel run (each processor its own rows, the columns
    of the others' rows given by their global index, as
    sparseMatrix::setDistribution says), solved by BoomerAMG (PCG, GMRES)
    from zero for b = A x* of a smooth x*. Checks, printed as PASS/FAIL
    lines (exit code 1 on a failure):
    - the solve converges to the tolerance (1e-10);
    - x is x* to 1e-6 relative (the matrices' condition, about N^2, times
      the tolerance);
    - the final residual the solver reports is the whole system's: equal,
      to 1e-12 of ||b||, to ||b - A x|| computed by the master from every
      processor's x.
    Serially (no -parallel) the same systems on one processor.

Usage
    parallelLinearSolve [-n N]
    mpirun -np 2 parallelLinearSolve -parallel [-n N]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "linearSolver.H"
#include "scalarList.H"
#include <cmath>

using namespace Foam;
using namespace Foam::meshless;

namespace
{

label failures = 0;

void check(const std::string& what, const bool ok)
{
    Info<< (ok ? "[  PASS  ] " : "[  FAIL  ] ") << what.c_str() << endl;
    if (!ok) ++failures;
}


//- The exact solution at global row g of an N x N grid
double exact(const label g, const label N)
{
    const label i = g % N;
    const label j = g / N;
    const double h = 1.0/(N + 1);
    return std::sin(M_PI*(i + 1)*h)*std::sin(2*M_PI*(j + 1)*h)
         + 0.1*(i + 1)*h;
}


//- The entries of global row g: (column, value), diagonal first
std::vector<std::pair<label, double>> row
(
    const label g,
    const label N,
    const double convection
)
{
    const label i = g % N;
    const label j = g / N;
    std::vector<std::pair<label, double>> r{{g, 4.0}};
    if (i > 0) r.push_back({g - 1, -1.0 - convection});
    if (i < N - 1) r.push_back({g + 1, -1.0 + convection});
    if (j > 0) r.push_back({g - N, -1.0});
    if (j < N - 1) r.push_back({g + N, -1.0});
    return r;
}


void solveOne(const label N, const double convection)
{
    const word kind(convection == 0 ? "symmetric" : "non-symmetric");
    const label nGlobal = N*N;
    const label P = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    const label lo = nGlobal*me/P;
    const label hi = nGlobal*(me + 1)/P;
    const label n = hi - lo;

    // This processor's rows, other processors' columns numbered after n
    sparseMatrix A;
    label nnz = 0;
    for (label g = lo; g < hi; ++g) nnz += label(row(g, N, convection).size());
    A.resize(n, nnz);
    std::vector<label> haloRows;
    std::vector<double> b(n, 0.0), x(n, 0.0);
    label k = 0;
    A.rowStart()[0] = 0;
    for (label g = lo; g < hi; ++g)
    {
        for (const auto& e : row(g, N, convection))
        {
            label c = e.first - lo;
            if (e.first < lo || e.first >= hi)
            {
                c = n + label(haloRows.size());
                haloRows.push_back(e.first);
            }
            A.columns()[k] = c;
            A.values()[k] = e.second;
            b[g - lo] += e.second*exact(e.first, N);
            ++k;
        }
        A.rowStart()[g - lo + 1] = k;
    }
    A.setSymmetric(convection == 0);
    if (Pstream::parRun()) A.setDistribution(lo, nGlobal, haloRows);
    check(kind + ": the block is well formed", A.checkDiagonalFirst());

    dictionary d;
    d.add("solver", word("BoomerAMG"));
    d.add("tolerance", 1e-10);
    d.add("maxIter", 500);
    autoPtr<linearSolver> solver(linearSolver::New(d));
    const linearSolver::performance p = solver->solve(A, b.data(), x.data());
    Info<< "    " << kind << ", " << P << " processor(s), " << nGlobal
        << " rows: " << p << endl;
    check(kind + ": converged", p.converged);

    double err = 0, ref = 0;
    for (label i = 0; i < n; ++i)
    {
        err += sqr(x[i] - exact(lo + i, N));
        ref += sqr(exact(lo + i, N));
    }
    reduce(err, sumOp<double>());
    reduce(ref, sumOp<double>());
    const double relErr = std::sqrt(err/ref);
    Info<< "    relative error " << relErr << endl;
    check(kind + ": x is the exact solution to 1e-6", relErr < 1e-6);

    // The master's residual of every processor's x
    List<scalarList> xs(P);
    xs[me] = scalarList(n);
    for (label i = 0; i < n; ++i) xs[me][i] = x[i];
    Pstream::gatherList(xs);
    if (Pstream::master())
    {
        scalarList all(nGlobal);
        label g = 0;
        for (const scalarList& part : xs)
        {
            for (const scalar v : part) all[g++] = v;
        }
        double rr = 0, bb = 0;
        for (label r = 0; r < nGlobal; ++r)
        {
            double ax = 0, br = 0;
            for (const auto& e : row(r, N, convection))
            {
                ax += e.second*all[e.first];
                br += e.second*exact(e.first, N);
            }
            rr += sqr(br - ax);
            bb += sqr(br);
        }
        const double truth = std::sqrt(rr/bb);
        Info<< "    residual reported " << p.finalResidual << ", of every"
            << " processor's x " << truth << endl;
        check
        (
            kind + ": the reported residual is the whole system's",
            std::abs(truth - p.finalResidual) < 1e-12
        );
    }
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::noBanner();
    argList::noCheckProcessorDirectories();
    argList::addOption("n", "N", "grid side (default 60)");
    argList args(argc, argv);

    const label N = args.getOrDefault<label>("n", 60);
    solveOne(N, 0);
    solveOne(N, 0.4);

    reduce(failures, maxOp<label>());
    Info<< "parallelLinearSolve: " << (failures ? "FAILED" : "passed")
        << endl;
    return failures ? 1 : 0;
}


// ************************************************************************* //
